cmake_minimum_required(VERSION 3.25)
# Script mode: what suite.three_drivers wrote (suite_tests.cmake). OUT: the suite's --out.
# Each entry has its own report; the combined results.csv is the entries' rows with their
# prefixes; softpipe's expected failure is ExpectedFail and the combined failures.csv lists it
# under its prefix; llvmpipe's skips file took its case out; zink ran on zink.
foreach(entry llvmpipe softpipe zink)
  if(NOT EXISTS "${OUT}/${entry}/results.json" OR NOT EXISTS "${OUT}/${entry}/results.csv")
    message(FATAL_ERROR "entry ${entry} wrote no report in ${OUT}/${entry}")
  endif()
endforeach()
file(READ "${OUT}/results.csv" csv)
foreach(row "llvmpipe.sparsegrid.hard.level1,Pass," "llvmpipe.sparsegrid.hard.nodes.l4,Pass,"
            "softpipe.sparsegrid.hard.level1,Pass," "softpipe.iso.frames.blobs_not_a_cube,ExpectedFail,"
            "zink.sparsegrid.hard.level1,Pass," "zink.sparsegrid.texture.r8.exact.linear.repeat,Pass,")
  string(FIND "${csv}" "${row}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the suite's results.csv has no row '${row}':\n${csv}")
  endif()
endforeach()
if(csv MATCHES "flag_collision")
  message(FATAL_ERROR "llvmpipe's skips file did not take flag_collision out:\n${csv}")
endif()
file(READ "${OUT}/failures.csv" failures)
if(NOT failures STREQUAL "softpipe.iso.frames.blobs_not_a_cube,Fail\n")
  message(FATAL_ERROR "the suite's failures.csv is '${failures}'")
endif()
file(READ "${OUT}/zink/results.json" zink)
if(NOT zink MATCHES "\"renderer\": \"zink")
  message(FATAL_ERROR "the zink entry did not run on zink")
endif()
message("suite: three entries, results.csv and failures.csv together, with their prefixes")
