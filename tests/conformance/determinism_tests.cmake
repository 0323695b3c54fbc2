# Determinism (issue 7): the same inputs give the same bits on every run, for 1 and 2 CPU threads,
# and for both llvmpipe vector widths (LP_NATIVE_VECTOR_WIDTH 256, the default here, and 128).
# One selection of all three systems (Embree ray casting and the LEB hierarchy included, through
# iso.frames.buckyball) runs four ways; check_results --same-results-as compares every case field
# but times and stderr, and every image file byte for byte, with the --threads 2 run.
# Included from tests/CMakeLists.txt (voxref_expect, voxref_bin, test_out).
set(det_filter "sparsegrid.combination.rgba8.l5.*,sparsegrid.combination.rgba16f.l6.xray,sparsegrid.texture.r8.*.linear.repeat,timevarying.decode.*.voxel_centres,timevarying.composite.*,iso.frames.buckyball,iso.hard.*,iso.accuracy.*")
set(det_check "$<TARGET_FILE:check_results>")
voxref_expect(determinism.threads2
  COMMAND "${voxref_bin}|conform|--filter|${det_filter}|--threads|2|--jobs|2|--all-images|--out|${test_out}/det-threads2"
  EXIT 0 LABELS determinism TIMEOUT 600 SETS det_threads2)
voxref_expect(determinism.repeated_run
  COMMAND "${voxref_bin}|conform|--filter|${det_filter}|--threads|2|--jobs|2|--all-images|--out|${test_out}/det-repeat"
  EXIT 0 CHECK "${det_check}|${test_out}/det-repeat/results.json|--same-results-as|${test_out}/det-threads2/results.json|--min-cases|20"
  LABELS determinism TIMEOUT 600 NEEDS det_threads2)
voxref_expect(determinism.threads1
  COMMAND "${voxref_bin}|conform|--filter|${det_filter}|--threads|1|--jobs|2|--all-images|--out|${test_out}/det-threads1"
  EXIT 0 CHECK "${det_check}|${test_out}/det-threads1/results.json|--same-results-as|${test_out}/det-threads2/results.json|--min-cases|20"
  LABELS determinism TIMEOUT 600 NEEDS det_threads2)
voxref_expect(determinism.vector_width_128
  COMMAND "${voxref_bin}|conform|--filter|${det_filter}|--threads|2|--jobs|2|--all-images|--out|${test_out}/det-v128"
  EXIT 0 ENVIRONMENT "LP_NATIVE_VECTOR_WIDTH=128"
  CHECK "${det_check}|${test_out}/det-v128/results.json|--same-results-as|${test_out}/det-threads2/results.json|--min-cases|20"
  LABELS determinism TIMEOUT 600 NEEDS det_threads2)
