# Tests of the runner (issue 6): isolation, time limits, --jobs, --shard, Ctrl-C, --baseline.
# Included from tests/CMakeLists.txt (voxref_test_executable, voxref_expect, voxref_bin, test_out).

voxref_test_executable(runner_tests
  SOURCES
    conformance/framework/isolation/child_processes_test.cpp
    conformance/framework/shard_test.cpp
    conformance/framework/report/baseline_diff_test.cpp
    conformance/framework/report/results_reader_test.cpp
    conformance/framework/report/results_csv_test.cpp
    conformance/framework/report/junit_xml_test.cpp
    conformance/framework/expectations/expectation_files_test.cpp
    conformance/framework/expectations/outcomes_test.cpp
  LIBS voxref_catalog)

set(check "$<TARGET_FILE:check_results>")

# Every way a case can die, among cases that pass: each is its own status with its stderr kept,
# and the run goes on to the cases after it (the controls come first in the catalogue). Each
# failed case runs once more (a flake check, docs/ci.md): the dying ones die again, the flaky
# control passes on its rerun and is a Flake.
set(controls driver_crash=crash segfault=crash abort=crash exit=crash hang=timeout exception=crash)
set(expect "")
foreach(c IN LISTS controls)
  string(REPLACE "=" ";" pair "${c}")
  list(GET pair 0 id)
  string(APPEND expect "|--expect-status|runner.control.${c}|--expect-stderr|runner.control.${id}=runner control:")
endforeach()
voxref_expect(runner.crash_and_hang_isolated
  COMMAND "${voxref_bin}|conform|--runner-controls|--filter|runner.control.*,sparsegrid.hard.level1,sparsegrid.hard.data_extremes.zero|--timeout|5|--jobs|2|--out|${test_out}/runner-controls"
  EXIT 1 OUTPUT "rerunning 7 case\\(s\\) that failed unexpectedly.*crash  runner.control.driver_crash: the case's process was killed by signal 11 \\(SIGSEGV.*timeout  runner.control.hang: .*time limit of 5 s.*Flake \\(fail\\)  runner.control.flaky: .*\\[reruns: pass\\].*summary: 2 pass 0 warn 1 fail 0 skip 5 crash 1 timeout.outcomes: 5 Crash 1 Flake 2 Pass 1 Timeout"
  CHECK "${check}|${test_out}/runner-controls/results.json|--min-cases|9|--expect-status|runner.control.flaky=fail${expect}"
  LABELS runner TIMEOUT 120)
voxref_expect(runner.controls_not_in_default_list COMMAND "${voxref_bin}|list|--filter|runner.*" EXIT 2 OUTPUT "no case matches")
voxref_expect(runner.in_process_refuses_controls
  COMMAND "${voxref_bin}|conform|--in-process|--runner-controls|--filter|runner.*|--out|${test_out}/runner-inproc" EXIT 2
  OUTPUT "--in-process cannot run the runner's control cases")

# --jobs and --in-process do not change a bit: tests/conformance/determinism_tests.cmake
# (determinism.one_thread_one_process, determinism.in_process_vector_width_128) and its negative
# control runner.same_bits_check_can_fail.

add_test(NAME runner.shard COMMAND ${CMAKE_COMMAND} -DVOXREF=$<TARGET_FILE:voxref> -P ${CMAKE_CURRENT_SOURCE_DIR}/conformance/framework/runner/shard_test.cmake)
set_tests_properties(runner.shard PROPERTIES LABELS runner)
voxref_expect(runner.shard_conform COMMAND "${voxref_bin}|conform|--filter|sparsegrid.hard.*|--shard|2/5|--out|${test_out}/runner-shard"
  EXIT 0 OUTPUT "case\\(s\\) \\(shard 2/5 of [0-9]+\\)" LABELS runner)

add_test(NAME runner.interrupt_leaves_partial_report
  COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/conformance/framework/runner/interrupt_test.sh $<TARGET_FILE:voxref> $<TARGET_FILE:check_results> ${test_out}/runner-interrupt)
set_tests_properties(runner.interrupt_leaves_partial_report PROPERTIES LABELS runner TIMEOUT 300)

# --baseline: the right profile's run is the baseline; the wrong profile's run regresses (exit 3)
# and names the case and its moved figures; the other way round the case is fixed (exit 0).
set(baseline_case sparsegrid.texture.r32f.exact.linear.clamp_to_edge)
voxref_expect(runner.baseline_good COMMAND "${voxref_bin}|conform|--filter|${baseline_case}|--out|${test_out}/runner-baseline-good"
  EXIT 0 ENVIRONMENT "GALLIUM_OVERRIDE_CPU_CAPS=sse4.1" LABELS runner SETS runner_baseline_good)
voxref_expect(runner.baseline_regression
  COMMAND "${voxref_bin}|conform|--profile|llvmpipe|--filter|${baseline_case}|--baseline|${test_out}/runner-baseline-good/results.json|--out|${test_out}/runner-baseline-bad"
  EXIT 3 ENVIRONMENT "GALLIUM_OVERRIDE_CPU_CAPS=sse4.1"
  OUTPUT "1 newly failing.*REGRESSED  ${baseline_case}: pass -> fail; exact.mismatched_pixels 0 -> [1-9]"
  CHECK "${check}|${test_out}/runner-baseline-bad/results.json|--expect-regressed|${baseline_case}|--expect-status|${baseline_case}=fail"
  LABELS runner NEEDS runner_baseline_good SETS runner_baseline_bad)
voxref_expect(runner.baseline_fixed
  COMMAND "${voxref_bin}|conform|--filter|${baseline_case}|--baseline|${test_out}/runner-baseline-bad/results.json|--out|${test_out}/runner-baseline-fixed"
  EXIT 0 ENVIRONMENT "GALLIUM_OVERRIDE_CPU_CAPS=sse4.1" OUTPUT "0 newly failing, 0 newly warning, 1 fixed"
  CHECK "${check}|${test_out}/runner-baseline-fixed/results.json|--expect-fixed|${baseline_case}"
  LABELS runner NEEDS runner_baseline_bad)
voxref_expect(runner.baseline_unreadable
  COMMAND "${voxref_bin}|conform|--filter|${baseline_case}|--baseline|${test_out}/no-such-dir/results.json|--out|${test_out}/runner-baseline-missing"
  EXIT 2 OUTPUT "--baseline: .*no-such-dir/results.json")

# A driver judged by the envelope alone (as an unknown driver is): --profile envelope. The report
# says so; the exact oracle does not run; the envelope judges every case of all three kinds of
# envelope-judged scenes.
voxref_expect(runner.envelope_alone
  COMMAND "${voxref_bin}|conform|--profile|envelope|--filter|sparsegrid.combination.rgba8.l5.*,sparsegrid.texture.r8.*.linear.repeat,timevarying.decode.*.voxel_centres|--out|${test_out}/runner-envelope"
  EXIT 0 OUTPUT "profile none: envelope oracle alone.*summary: [1-9][0-9]* pass 0 warn 0 fail"
  CHECK "${check}|${test_out}/runner-envelope/results.json|--expect-envelope-alone|--min-cases|10"
  LABELS runner TIMEOUT 600)
