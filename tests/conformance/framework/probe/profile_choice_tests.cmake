# How a run's profile is chosen on drivers voxref has no named profile for
# (conformance/framework/probe/profile_choice.h, docs/profiles.md): the probe picks a known profile,
# or builds one from what it measured; a driver file pins a probed profile; every verdict is
# exact against it.

# A subset of all three systems: combination, texture and hard sparse-grid cases, decoders of
# every kind and a composite, isosurface frames and a hard case.
set(zink_subset "sparsegrid.combination.rgba8.l5.xray,sparsegrid.combination.rgba32f.l3.mip,sparsegrid.texture.r8.exact.linear.repeat,sparsegrid.texture.r32f.exact.linear.clamp_to_edge,sparsegrid.hard.level12.rgba8,timevarying.decode.paper_rgba8.orbit,timevarying.decode.texel_centre.voxel_centres,timevarying.decode.texel_fetch.block_faces,timevarying.composite.paper_rgba8.blobs,iso.frames.blobs_not_a_cube,iso.hard.single_voxel")

# Zink on lavapipe through EGL (Debian's mesa-vulkan-drivers, cmake/setup-debian.sh): GL_RENDERER
# names no profile, so auto runs the probe, which finds llvmpipe's model in every probe frame; every
# case is then judged exactly against it.
set(zink_env "MESA_LOADER_DRIVER_OVERRIDE=zink|LIBGL_ALWAYS_SOFTWARE=1|EGL_PLATFORM=surfaceless")
voxref_expect(conform.zink.subset
  COMMAND "${voxref_bin}|conform|--driver|egl|--filter|${zink_subset}|--out|${test_out}/conform-zink" EXIT 0
  ENVIRONMENT "${zink_env}"
  OUTPUT "on zink .*profile: auto: GL_RENDERER 'zink [^']*' names no profile; the probe chose llvmpipe: all [0-9]+ probe frames bit-identical to its emulation.*summary: [0-9]+ pass 0 warn 0 fail 0 skip"
  CHECK "$<TARGET_FILE:check_results>|${test_out}/conform-zink/results.json|--profile|llvmpipe|--require-exact-pass|--require-no-fail|--min-cases|11|--expect-oracle|iso.frames.blobs_not_a_cube:sample_counters=pass"
  LABELS "conformance;zink" TIMEOUT 900)

# llvmpipe with its CPU capabilities below SSSE3: the 8-bit lerps floor (lp_build_lerp without
# pmulhrsw), which no named profile models. The probe determines every property and the profile
# built from them reproduces every probe frame; auto judges against it, exactly.
set(sse3_filter "sparsegrid.texture.r8.*,sparsegrid.texture.rgba8.*,sparsegrid.combination.rgba8.l5.xray,sparsegrid.hard.level12.rgba8,timevarying.decode.paper_rgba8.voxel_centres,timevarying.composite.paper_rgba8.blobs,iso.hard.single_voxel")
voxref_expect(probe.sse3.driver_file COMMAND "${voxref_bin}|probe|--out|${test_out}/sse3-driver.json" EXIT 1
  ENVIRONMENT "GALLIUM_OVERRIDE_CPU_CAPS=sse3"
  OUTPUT "sampling.unorm8.lerp_rounding +floor.*no known profile matches.*probed profile: built from the 11 properties; its emulation reproduces all [0-9]+ probe frames.*wrote .*sse3-driver.json"
  SETS sse3_driver_file LABELS "cli;probe")
voxref_expect(conform.sse3.probed_by_auto
  COMMAND "${voxref_bin}|conform|--filter|${sse3_filter}|--out|${test_out}/conform-sse3" EXIT 0
  ENVIRONMENT "GALLIUM_OVERRIDE_CPU_CAPS=sse3"
  OUTPUT "profile probed \\(probed\\).*no known profile reproduces the probe .*judged against a profile built from the 11 probed properties, whose emulation reproduces all [0-9]+ probe frames.* 0 fail"
  CHECK "$<TARGET_FILE:check_results>|${test_out}/conform-sse3/results.json|--profile|probed|--require-exact-pass|--require-no-fail|--min-cases|20"
  LABELS "conformance;probe" TIMEOUT 900)
voxref_expect(conform.sse3.driver_file
  COMMAND "${voxref_bin}|conform|--profile|${test_out}/sse3-driver.json|--filter|sparsegrid.texture.r8.*|--out|${test_out}/conform-sse3-file" EXIT 0
  ENVIRONMENT "GALLIUM_OVERRIDE_CPU_CAPS=sse3"
  OUTPUT "the probed profile of .*sse3-driver.json; the probe confirms it.* 0 fail"
  CHECK "$<TARGET_FILE:check_results>|${test_out}/conform-sse3-file/results.json|--profile|probed|--require-exact-pass|--require-no-fail"
  NEEDS sse3_driver_file LABELS "conformance;probe")
# The pin holds: on llvmpipe with SSSE3 the 8-bit lerps round, and the run refuses, naming the property.
voxref_expect(conform.driver_file.moved_property
  COMMAND "${voxref_bin}|conform|--profile|${test_out}/sse3-driver.json|--filter|sparsegrid.texture.r8.*|--out|${test_out}/conform-moved" EXIT 2
  OUTPUT "the driver no longer probes as .*sse3-driver.json: sampling.unorm8.lerp_rounding: probed floor, now nearest"
  NEEDS sse3_driver_file LABELS "cli;probe")
voxref_expect(conform.driver_file.not_a_driver_file
  COMMAND "${voxref_bin}|conform|--profile|${CMAKE_CURRENT_SOURCE_DIR}/../fixtures/iso/manifest.json|--filter|sparsegrid.hard.level1|--out|${test_out}/conform-notfile" EXIT 2
  OUTPUT "--profile .*manifest.json: not a driver file of `voxref probe --out` \\(no properties\\)" LABELS "cli;probe")

# softpipe held against the profile the probe alone builds (its calibrated profile set aside): the
# probe does not measure the texture tile cache's aliasing, which changes 213 samples of the r16
# case (none of the r8 case), so that case says the probed model does not hold here, counted apart.
voxref_expect(conform.softpipe.probed_profile
  COMMAND "${voxref_bin}|conform|--driver|softpipe|--profile|probed|--filter|sparsegrid.texture.r16.exact.linear.clamp_to_edge,sparsegrid.texture.r8.exact.linear.clamp_to_edge|--out|${test_out}/conform-softpipe-probed"
  EXIT 1
  OUTPUT "fail  sparsegrid.texture.r16.exact.linear.clamp_to_edge: the probed model does not hold here: exact: [0-9]+ of [0-9]+ samples differ.*summary: 1 pass 0 warn 1 fail.*1 exact failure\\(s\\) against the probed profile: the probed model does not hold here"
  LABELS "conformance;probe")
