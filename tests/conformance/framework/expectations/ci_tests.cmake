# Running in a CI fleet as deqp-runner does (docs/ci.md): a fleet of three shards on this machine,
# the driver checks, and bad expectation files, case lists and CI variables. Included from
# tests/CMakeLists.txt (voxref_expect, voxref_bin, test_out).
add_test(NAME ci.fleet COMMAND ${CMAKE_COMMAND} -DVOXREF=$<TARGET_FILE:voxref> -DWORK=${test_out}/ci-fleet
                               -P ${CMAKE_CURRENT_SOURCE_DIR}/conformance/framework/runner/fleet_test.cmake)
set_tests_properties(ci.fleet PROPERTIES LABELS "runner;ci" TIMEOUT 900 COST 40)

set(ci_dir "${test_out}/ci-files")
file(MAKE_DIRECTORY "${ci_dir}")
file(WRITE "${ci_dir}/bad_status.txt" "# fails\nsparsegrid.hard.level1,Fail\nsparsegrid.hard.nodes.l4,Broken\n")
file(WRITE "${ci_dir}/bad_line.txt" "sparsegrid.hard.level1 Fail\n")
file(WRITE "${ci_dir}/bad_regex.txt" "^sparsegrid\n(unclosed\n")
file(WRITE "${ci_dir}/unknown_case.txt" "sparsegrid.hard.level1\nsparsegrid.no_such_case\n")
file(WRITE "${ci_dir}/two_cases.txt" "# two cases\nsparsegrid.hard.level1\nsparsegrid.hard.nodes.l4\n")
file(WRITE "${ci_dir}/expects_level1.txt" "sparsegrid.hard.level1,Fail\n")
# Each refusal names the file, the line and what was expected, exits 2 and writes nothing.
function(voxref_ci_refusal name args output)
  voxref_expect(ci.refuses.${name} COMMAND "${voxref_bin}|conform|${args}|--out|${ci_dir}/out-${name}" EXIT 2
                OUTPUT "${output}" CHECK "sh|-c|test ! -e ${ci_dir}/out-${name}" ${ARGN})
endfunction()
voxref_ci_refusal(unknown_status "--fails|${ci_dir}/bad_status.txt"
                  "bad_status.txt:3: unknown status 'Broken' \\(expected Fail, Crash, Timeout or Warn\\)")
voxref_ci_refusal(fails_line "--fails|${ci_dir}/bad_line.txt" "bad_line.txt:1: expected 'case.id,Status'")
voxref_ci_refusal(bad_regex "--flakes|${ci_dir}/bad_regex.txt" "bad_regex.txt:2: '\\(unclosed' is not a regular expression")
voxref_ci_refusal(missing_skips "--skips|${ci_dir}/no_such_skips.txt" "skips file .*no_such_skips.txt does not exist")
voxref_ci_refusal(unknown_case "--caselist|${ci_dir}/unknown_case.txt"
                  "unknown_case.txt:2: no case 'sparsegrid.no_such_case' in the catalogue")
voxref_ci_refusal(ci_node_alone "--filter|sparsegrid.hard.level1" "CI_NODE_INDEX is set but CI_NODE_TOTAL is not"
                  ENVIRONMENT "CI_NODE_INDEX=2")
voxref_ci_refusal(ci_node_range "--filter|sparsegrid.hard.level1" "CI_NODE_INDEX='4' and CI_NODE_TOTAL='3'"
                  ENVIRONMENT "CI_NODE_INDEX=4|CI_NODE_TOTAL=3")
voxref_ci_refusal(renderer_check "--filter|sparsegrid.hard.level1|--renderer-check|^radeonsi"
                  "--renderer-check '\\^radeonsi' does not match the renderer 'llvmpipe.*no case ran")
voxref_ci_refusal(version_check "--filter|sparsegrid.hard.level1|--version-check|Mesa 99\\."
                  "--version-check 'Mesa 99\\\\.' does not match the version")
voxref_ci_refusal(bad_check_regex "--filter|sparsegrid.hard.level1|--renderer-check|llvm(" "--renderer-check 'llvm\\(' is not a regular expression")

# A case list as the selection, with --filter, and the driver checks that hold.
voxref_expect(ci.caselist_and_checks
  COMMAND "${voxref_bin}|conform|--caselist|${ci_dir}/two_cases.txt|--filter|sparsegrid.hard.nodes.l4|--renderer-check|^llvmpipe|--version-check|Mesa [0-9]+\\.|--out|${ci_dir}/caselist"
  EXIT 0 OUTPUT "voxref conform: 1 case\\(s\\).*slowest: sparsegrid.hard.nodes.l4 [0-9.]+ s"
  CHECK "sh|-c|grep -qx 'sparsegrid.hard.nodes.l4,Pass,[0-9.]*' ${ci_dir}/caselist/results.csv && test ! -s ${ci_dir}/caselist/failures.csv"
  LABELS "runner;ci")
# A fails file that expects a case that passes: UnexpectedImprovement(Pass), exit 1, and junit.xml
# shows it as a failure.
voxref_expect(ci.unexpected_improvement
  COMMAND "${voxref_bin}|conform|--filter|sparsegrid.hard.level1|--fails|${ci_dir}/expects_level1.txt|--out|${ci_dir}/improvement"
  EXIT 1 OUTPUT "UnexpectedImprovement\\(Pass\\) \\(pass\\)  sparsegrid.hard.level1.*outcomes: 1 UnexpectedImprovement\\(Pass\\)"
  CHECK "sh|-c|grep -qx 'sparsegrid.hard.level1,UnexpectedImprovement(Pass),[0-9.]*' ${ci_dir}/improvement/results.csv && grep -q '<failure message=\"UnexpectedImprovement(Pass)' ${ci_dir}/improvement/junit.xml"
  LABELS "runner;ci")
