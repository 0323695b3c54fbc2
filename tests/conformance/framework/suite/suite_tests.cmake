# Suite files (conformance/framework/suite/suite_file.h, docs/ci.md): one job runs llvmpipe,
# softpipe and zink, each with its own report, checks, expectation files and prefix, and one exit
# status; bad suite files are refused naming the file and the line. Included from
# tests/CMakeLists.txt (voxref_expect, voxref_bin, test_out).
set(suite_dir "${CMAKE_CURRENT_SOURCE_DIR}/conformance/framework/suite")
set(suite_out "${test_out}/suite")
voxref_expect(suite.three_drivers
  COMMAND "${voxref_bin}|suite|${suite_dir}/three_drivers.toml|--out|${suite_out}"
  EXIT 0 OUTPUT "suite: llvmpipe exit 0; softpipe exit 0; zink exit 0; 3 of 3 entries ran"
  CHECK "${CMAKE_COMMAND}|-DOUT=${suite_out}|-P|${suite_dir}/check_suite.cmake"
  LABELS "runner;ci" TIMEOUT 600)
set(bad "${test_out}/suite-bad")
file(MAKE_DIRECTORY "${bad}")
file(WRITE "${bad}/unknown_key.toml" "[[conform]]\nname = \"a\"\nfilter = \"sparsegrid.hard.level1\"\ndriverr = \"softpipe\"\n")
file(WRITE "${bad}/wrong_type.toml" "[[conform]]\nname = \"a\"\nfraction = \"two\"\n")
file(WRITE "${bad}/syntax.toml" "[[conform]]\nname = \"a\n")
file(WRITE "${bad}/no_name.toml" "# no name\n[[conform]]\ndriver = \"softpipe\"\n")
file(WRITE "${bad}/twice.toml" "[[conform]]\nname = \"a\"\n[[conform]]\nname = \"a\"\n")
file(WRITE "${bad}/top_key.toml" "jobs = 2\n")
foreach(case "unknown_key|unknown_key.toml:4: unknown key 'driverr' in \\[\\[conform\\]\\]"
              "wrong_type|wrong_type.toml:3: fraction must be a whole number of at least 1"
              "syntax|syntax.toml:2: "
              "no_name|no_name.toml:2: a \\[\\[conform\\]\\] entry needs a name"
              "twice|twice.toml:3: a second entry named 'a'"
              "top_key|top_key.toml:1: unknown key 'jobs'"
              "missing|suite file .*missing.toml does not exist")
  string(REPLACE "|" ";" parts "${case}")
  list(GET parts 0 name)
  list(GET parts 1 output)
  voxref_expect(suite.refuses.${name} COMMAND "${voxref_bin}|suite|${bad}/${name}.toml|--out|${bad}/out-${name}" EXIT 2
                OUTPUT "${output}" CHECK "sh|-c|test ! -e ${bad}/out-${name}" LABELS "cli;ci")
endforeach()
