# The order ctest -j starts tests in. A fresh clone has no timings of its own (Testing/Temporary/
# CTestCostData.txt), so ctest would start tests in the order they are declared, and a long run
# declared late would finish alone on one core. COST is about how many seconds a test ran on the
# 2-core CI machine (release build; the sanitizer build keeps the order); ctest starts the
# costliest first, as soon as its fixtures allow. Included last from tests/CMakeLists.txt.
set(voxref_test_costs
  conform.llvmpipe.sparsegrid.shard1 80  conform.llvmpipe.sparsegrid.shard2 80
  conform.llvmpipe.sparsegrid 110
  conform.softpipe.sparsegrid.shard1 120  conform.softpipe.sparsegrid.shard2 120  conform.softpipe.sparsegrid.shard3 120
  conform.softpipe.timevarying 130  conform.llvmpipe.timevarying 45  conform.llvmpipe.iso 50
  determinism.one_thread_one_process 45  determinism.reference 30  determinism.repeated_run 25
  determinism.in_process_vector_width_128 22
  # The HTML report's run and the bench study set up the browser tests, which take one lock
  # (html_tests.cmake): the chain starts early, beside the long runs, not last.
  report.html.run 40  bench.study.quick 35
  conform.llvmpipe_nofma.texture 30  conform.softpipe.iso 19  conform.zink.subset 17  conform.sse3.probed_by_auto 15
  fuzz.leb_stream 16  fuzz.results_json 16  fuzz.fixture_manifest 16  fuzz.huffman 16  fuzz.scene_json 16
  fuzz.raw_volume 16  fuzz.timevarying_container 16
  runner.envelope_alone 14)
get_property(voxref_declared_tests DIRECTORY PROPERTY TESTS)
while(voxref_test_costs)
  list(POP_FRONT voxref_test_costs test cost)
  if(test IN_LIST voxref_declared_tests)  # some tests exist only in one build (sanitizers, fuzzers)
    set_tests_properties(${test} PROPERTIES COST ${cost})
  endif()
endwhile()
