# Faults (issue 8): a full disk while writing a report, a fixture or a stream, a GL library that
# cannot be loaded, a GL context that cannot be created. Each must end in a clear error, a non-zero
# exit, and leave what was already there intact (check_fault.cmake). A full disk is simulated with
# a file-size limit (`ulimit -f`, SIGXFSZ ignored): every write past 512 bytes fails with EFBIG,
# which voxref meets exactly where a full disk's ENOSPC would meet it. Included from
# tests/CMakeLists.txt (voxref_expect, test_out, voxref_bin).
set(fault_dir "${test_out}/faults")
add_test(NAME fault.clean COMMAND ${CMAKE_COMMAND} -E rm -rf "${fault_dir}")
add_test(NAME fault.mkdir COMMAND ${CMAKE_COMMAND} -E make_directory "${fault_dir}/stream" "${fault_dir}/leb")
set_tests_properties(fault.clean PROPERTIES FIXTURES_SETUP fault_clean LABELS "fault;sanitize")
set_tests_properties(fault.mkdir PROPERTIES FIXTURES_SETUP fault_mkdir FIXTURES_REQUIRED fault_clean LABELS "fault;sanitize")

# The outputs the faults must not touch, made by successful runs first.
voxref_expect(fault.setup.report
  COMMAND "${voxref_bin}|conform|--filter|sparsegrid.hard.level1|--all-images|--out|${fault_dir}/report" EXIT 0
  SETS fault_report NEEDS fault_clean LABELS "fault;sanitize")
voxref_expect(fault.setup.fixtures
  COMMAND "${voxref_bin}|fixtures|generate|--dir|${fault_dir}/fixtures|--scene|buckyball|--frames|1" EXIT 0
  SETS fault_fixtures NEEDS fault_clean LABELS "fault;sanitize" TIMEOUT 600)
voxref_expect(fault.setup.stream
  COMMAND "${voxref_bin}|encode|--codec|timevarying|--plume|--side|16|--steps|2|--out|${fault_dir}/stream/plume.vxtv" EXIT 0
  SETS fault_stream NEEDS fault_mkdir LABELS "fault;sanitize")

function(voxref_fault name)
  cmake_parse_arguments(ARG "" "COMMAND;DIR;EXPECT;FSIZE;ENVIRONMENT;NEEDS" "" ${ARGN})
  add_test(NAME ${name} COMMAND ${CMAKE_COMMAND} "-DCOMMAND=${ARG_COMMAND}" "-DDIR=${ARG_DIR}" "-DEXPECT_OUTPUT=${ARG_EXPECT}"
           "-DFSIZE=${ARG_FSIZE}" "-DENVIRONMENT=${ARG_ENVIRONMENT}" -P "${CMAKE_CURRENT_SOURCE_DIR}/faults/check_fault.cmake")
  # One at a time on a folder: a check snapshots the folder before its command runs.
  set_tests_properties(${name} PROPERTIES LABELS "fault;sanitize" TIMEOUT 600 FIXTURES_REQUIRED "${ARG_NEEDS}" RESOURCE_LOCK "${ARG_DIR}")
endfunction()

# A full disk while a run writes its report into the folder of an earlier report: the error names
# the file, the earlier results.json, pages and images are untouched, no temporary file remains.
voxref_fault(fault.disk_full.report
  COMMAND "${voxref_bin}|conform|--filter|sparsegrid.combination.rgba8.l4.*|--all-images|--out|${fault_dir}/report"
  DIR "${fault_dir}/report" FSIZE 1 EXPECT "cannot write [^\n]*report/[^\n]*: File too large" NEEDS fault_report)
# ... while fixtures are regenerated over earlier ones.
voxref_fault(fault.disk_full.fixtures
  COMMAND "${voxref_bin}|fixtures|generate|--dir|${fault_dir}/fixtures|--scene|buckyball|--frames|1"
  DIR "${fault_dir}/fixtures" FSIZE 1 EXPECT "cannot write [^\n]*fixtures/[^\n]*File too large" NEEDS fault_fixtures)
# ... while a stream is encoded over an earlier one.
voxref_fault(fault.disk_full.stream
  COMMAND "${voxref_bin}|encode|--codec|timevarying|--plume|--side|32|--steps|4|--out|${fault_dir}/stream/plume.vxtv"
  DIR "${fault_dir}/stream" FSIZE 1 EXPECT "plume.vxtv[^\n]*: File too large" NEEDS fault_stream)
# ... while the LEB codec streams between files (conformance/io/leb_file_codec.h): the encoder's
# gradients file and the decoder's outputs are allocated before they are written through their
# mappings, so the limit is met there, as an error, never as a fault in the middle of the mapping.
# The volume is the bad-input catalogue's good one (32x32x16 uint8).
set(fault_leb_encode "${voxref_bin}|encode|--codec|leb|--input|${good}/steps/step_000.rgba|--dims|32|32|16|--out|${fault_dir}/leb/volume.vxleb")
voxref_expect(fault.setup.leb COMMAND "${fault_leb_encode}" EXIT 0 SETS fault_leb NEEDS "fault_mkdir;bi_volume" LABELS "fault;sanitize")
voxref_fault(fault.disk_full.leb_encode COMMAND "${fault_leb_encode}"
  DIR "${fault_dir}/leb" FSIZE 1 EXPECT "cannot write [^\n]*volume[^\n]*: File too large" NEEDS fault_leb)
voxref_fault(fault.disk_full.leb_decode
  COMMAND "${voxref_bin}|decode|--codec|leb|--input|${fault_dir}/leb/volume.vxleb|--out|${fault_dir}/leb/volume.raw|--gradients-out|${fault_dir}/leb/volume.grad"
  DIR "${fault_dir}/leb" FSIZE 1 EXPECT "cannot write [^\n]*volume[^\n]*: File too large" NEEDS fault_leb)
# No GL library: libOSMesa is loaded at run time, so the error is voxref's, naming the library.
voxref_fault(fault.gl_library_missing
  COMMAND "${voxref_bin}|conform|--filter|sparsegrid.hard.level1|--out|${fault_dir}/report"
  DIR "${fault_dir}/report" ENVIRONMENT "VOXREF_OSMESA=${fault_dir}/no-such-dir/libOSMesa.so.8"
  EXPECT "cannot load the OSMesa library [^\n]*no-such-dir/libOSMesa.so.8" NEEDS fault_report)
# A library that is not OSMesa at all.
voxref_fault(fault.gl_library_broken
  COMMAND "${voxref_bin}|conform|--filter|sparsegrid.hard.level1|--out|${fault_dir}/report"
  DIR "${fault_dir}/report" ENVIRONMENT "VOXREF_OSMESA=libz.so.1"
  EXPECT "the OSMesa library libz.so.1 has no OSMesaCreateContextAttribs" NEEDS fault_report)
# Commands that need no GL still run without the library.
voxref_expect(fault.gl_library_missing.list_still_works
  COMMAND "${voxref_bin}|list|--filter|iso.hard.empty_volume" EXIT 0 OUTPUT "iso.hard.empty_volume"
  ENVIRONMENT "VOXREF_OSMESA=${fault_dir}/no-such-dir/libOSMesa.so.8" LABELS "fault;sanitize")
# A context the driver refuses to create: Mesa capped below the 4.5 core context voxref asks for.
voxref_fault(fault.gl_context_refused
  COMMAND "${voxref_bin}|conform|--filter|sparsegrid.hard.level1|--out|${fault_dir}/report"
  DIR "${fault_dir}/report" ENVIRONMENT "MESA_GL_VERSION_OVERRIDE=3.1"
  EXPECT "no GL context for --driver llvmpipe: OSMesa could not create a 4.5 core context on llvmpipe" NEEDS fault_report)
# An EGL platform that does not exist.
voxref_fault(fault.egl_platform_unsupported
  COMMAND "${voxref_bin}|conform|--driver|egl|--filter|sparsegrid.hard.level1|--out|${fault_dir}/report"
  DIR "${fault_dir}/report" ENVIRONMENT "EGL_PLATFORM=nonsense"
  EXPECT "no GL context for --driver egl: EGL_PLATFORM=nonsense is not supported" NEEDS fault_report)
