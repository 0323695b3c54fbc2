# The HTML report in a real browser (Debian's chromium, headless): a small run with a pass, a
# failure (llvmpipe's FMA profile on llvmpipe without FMA), a crash and three systems; then its
# index and one case page are loaded and checked against results.json (check_html_page.cmake);
# and negative controls prove that the check catches a script error, a wrong count and an image
# that does not load. Included from tests/CMakeLists.txt (voxref_expect, test_out, voxref_bin).
# One browser at a time (RESOURCE_LOCK chromium): the first start in a fresh machine waits about
# 20 s on the disk with almost no CPU, and three such waits side by side left both cores idle.
find_program(VOXREF_CHROMIUM NAMES chromium chromium-browser DOC "headless browser for the tests of the HTML report")
set(html_report "${test_out}/report-html")
# A fresh directory: pages left by an earlier run must not stand in for pages this run failed to write.
add_test(NAME report.html.clean COMMAND ${CMAKE_COMMAND} -E rm -rf "${html_report}")
set_tests_properties(report.html.clean PROPERTIES FIXTURES_SETUP html_report_clean LABELS report)
voxref_expect(report.html.run
  COMMAND "${voxref_bin}|conform|--profile|llvmpipe|--runner-controls|--all-images|--timeout|60|--filter|sparsegrid.texture.r32f.exact.linear.repeat,sparsegrid.combination.rgba8.l4.*,iso.hard.single_voxel,runner.control.segfault|--out|${html_report}"
  EXIT 1 ENVIRONMENT "GALLIUM_OVERRIDE_CPU_CAPS=sse4.1" OUTPUT "summary: 4 pass 0 warn 1 fail 0 skip 1 crash 0 timeout"
  SETS html_report NEEDS html_report_clean LABELS report)

function(voxref_html_check name page)
  cmake_parse_arguments(ARG "" "BREAK;EXPECT_PROBLEM" "" ${ARGN})
  set(args "-DCHROMIUM=${VOXREF_CHROMIUM}" "-DREPORT_DIR=${html_report}" "-DPAGE=${page}" "-DSCRATCH=${test_out}/chromium/${name}")
  if(ARG_BREAK)
    list(APPEND args "-DBREAK=${ARG_BREAK}" "-DEXPECT_PROBLEM=${ARG_EXPECT_PROBLEM}")
  endif()
  add_test(NAME ${name} COMMAND ${CMAKE_COMMAND} ${args} -P "${CMAKE_CURRENT_SOURCE_DIR}/conformance/framework/report/check_html_page.cmake")
  set_tests_properties(${name} PROPERTIES FIXTURES_REQUIRED html_report LABELS report TIMEOUT 300 RESOURCE_LOCK chromium
                       SKIP_REGULAR_EXPRESSION "VOXREF_TEST_SKIPPED:" COST 10)
endfunction()

voxref_html_check(report.html.index_in_chromium index)
voxref_html_check(report.html.case_page_in_chromium case)
voxref_html_check(report.html.negative_control.script_error index BREAK script_error EXPECT_PROBLEM "voxrefNoSuchFunction is not defined")
voxref_html_check(report.html.negative_control.wrong_count index BREAK wrong_count EXPECT_PROBLEM "count-pass shows 987654, results.json says")
voxref_html_check(report.html.negative_control.missing_image case BREAK missing_image EXPECT_PROBLEM "could not load img [^ ]*/images/no-such-")

# The page of `voxref bench` (bench.study.quick in tests/CMakeLists.txt sets it up): every plot
# shown and loaded, a section per table; a plot that does not load must be caught.
add_test(NAME bench.study.page_in_chromium
         COMMAND ${CMAKE_COMMAND} "-DCHROMIUM=${VOXREF_CHROMIUM}" "-DREPORT_DIR=${test_out}/bench-study" -DPAGE=bench
                 "-DSCRATCH=${test_out}/chromium/bench-study" -P "${CMAKE_CURRENT_SOURCE_DIR}/conformance/framework/report/check_html_page.cmake")
add_test(NAME bench.study.page_negative_control.missing_image
         COMMAND ${CMAKE_COMMAND} "-DCHROMIUM=${VOXREF_CHROMIUM}" "-DREPORT_DIR=${test_out}/bench-study" -DPAGE=bench -DBREAK=missing_image
                 "-DEXPECT_PROBLEM=could not load img [^ ]*plots/no-such-" "-DSCRATCH=${test_out}/chromium/bench-study-nc"
                 -P "${CMAKE_CURRENT_SOURCE_DIR}/conformance/framework/report/check_html_page.cmake")
set_tests_properties(bench.study.page_in_chromium bench.study.page_negative_control.missing_image PROPERTIES
                     FIXTURES_REQUIRED bench_study LABELS "bench;report" TIMEOUT 300 SKIP_REGULAR_EXPRESSION "VOXREF_TEST_SKIPPED:"
                     RESOURCE_LOCK chromium COST 10)
