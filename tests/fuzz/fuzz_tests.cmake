# --- Fuzzing: libFuzzer targets built with clang (tests/fuzz), run for a bounded time -----------
# Included from tests/CMakeLists.txt. docs/fuzzing.md describes the targets, their contracts, the
# seeds and how to run them for longer.
#
# Per target <name> (binary <name>_fuzz, built by the ExternalProject below):
#   fuzz.<name>.seeds        writes the seed corpus of valid files (FIXTURES_SETUP <name>_seeds,
#                            with fuzz.<name>.corpus, which makes the corpus directory)
#   fuzz.<name>              runs the target for VOXREF_FUZZ_SECONDS from the corpus in the build
#                            tree (fuzz-corpus/<name>, which grows) and the fresh seeds
#   fuzz.<name>.regressions  runs the target once on every input of tests/fuzz/regressions/<name>:
#                            each crashed a target once and is named after the bug it found
# Regressions in the main build of what the fuzz targets found in the command line's own use of
# the parsers: `voxref render --scene FILE` let nlohmann's out_of_range (a number beyond double)
# and type_error (a "system" that is not a string) through instead of a usage error.
file(WRITE "${test_out}/number_beyond_double.json" [=[{"system": "sparsegrid", "isovalue": 1e999}]=])
file(WRITE "${test_out}/system_not_a_string.json" [=[{"system": 5}]=])
voxref_expect(cli.render.number_beyond_double COMMAND "${voxref_bin}|render|--scene|${test_out}/number_beyond_double.json|--out|${test_out}/x.exr"
              EXIT 2 OUTPUT "number_beyond_double.json is not valid JSON: .*number overflow")
voxref_expect(cli.render.system_not_a_string COMMAND "${voxref_bin}|render|--scene|${test_out}/system_not_a_string.json|--out|${test_out}/x.exr"
              EXIT 2 OUTPUT "system: expected a string, got 5")

option(VOXREF_FUZZ "build the libFuzzer targets and run them for a bounded time (clang, libclang-rt-14-dev)" ON)
# CI budget: 10 targets x 15 s with ctest -j2 is about a minute and a quarter. An existing build tree keeps the
# value it was configured with (a cache variable): -DVOXREF_FUZZ_SECONDS=15 resets it.
set(VOXREF_FUZZ_SECONDS 15 CACHE STRING "seconds each fuzz target runs under ctest")
if(VOXREF_FUZZ)
  find_program(VOXREF_CLANGXX NAMES clang++ clang++-14)
  if(NOT VOXREF_CLANGXX)
    message(FATAL_ERROR "clang++ not found: the fuzz targets need clang and libFuzzer (apt-get install clang libclang-rt-14-dev; "
                        "cmake/setup-debian.sh does), or configure with -DVOXREF_FUZZ=OFF")
  endif()
  include(ExternalProject)
  ExternalProject_Add(voxref_fuzz
    SOURCE_DIR "${CMAKE_CURRENT_LIST_DIR}"
    BINARY_DIR "${PROJECT_BINARY_DIR}/fuzz"
    CMAKE_ARGS "-DCMAKE_CXX_COMPILER=${VOXREF_CLANGXX}" "-DVOXREF_SOURCE_DIR=${PROJECT_SOURCE_DIR}" -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_UNITY_BUILD=${VOXREF_UNITY_BUILD}"
    CMAKE_GENERATOR "${CMAKE_GENERATOR}"
    BUILD_ALWAYS ON
    INSTALL_COMMAND "")

  # Seed makers, built by the main build with the product's own writers (the seeds follow the
  # formats as they change).
  add_executable(make_leb_seeds fuzz/make_leb_seeds.cpp)
  target_link_libraries(make_leb_seeds PRIVATE voxref_reference)
  voxref_warnings(make_leb_seeds)
  add_executable(make_fuzz_seeds fuzz/make_fuzz_seeds.cpp)
  target_link_libraries(make_fuzz_seeds PRIVATE voxref_catalog ZLIB::ZLIB)
  voxref_include_folder(make_fuzz_seeds PRIVATE "tests/fuzz")  # context_page_input.h, shared with its target
  voxref_warnings(make_fuzz_seeds)

  set(fuzz_corpus "${PROJECT_BINARY_DIR}/fuzz-corpus")
  set(fuzz_options -seed=1 -max_total_time=${VOXREF_FUZZ_SECONDS} -timeout=20 -rss_limit_mb=2048 -print_final_stats=1)

  # voxref_fuzz_test(NAME SEEDS command... [OPTIONS libFuzzer options...]): the three tests of
  # target NAME (binary NAME_fuzz); OPTIONS go to both the bounded run and the regressions.
  function(voxref_fuzz_test name)
    cmake_parse_arguments(ARG "" "" "SEEDS;OPTIONS" ${ARGN})
    set(binary "${PROJECT_BINARY_DIR}/fuzz/${name}_fuzz")
    add_test(NAME fuzz.${name}.seeds COMMAND ${ARG_SEEDS} "${fuzz_corpus}/${name}_seeds")
    # libFuzzer needs the corpus directory to exist: made again if someone cleared fuzz-corpus.
    add_test(NAME fuzz.${name}.corpus COMMAND "${CMAKE_COMMAND}" -E make_directory "${fuzz_corpus}/${name}")
    set_tests_properties(fuzz.${name}.seeds fuzz.${name}.corpus PROPERTIES FIXTURES_SETUP ${name}_seeds LABELS fuzz)
    # The corpus grows in the build tree; the seeds are regenerated from the current writers.
    add_test(NAME fuzz.${name} COMMAND "${binary}" ${fuzz_options} ${ARG_OPTIONS} "${fuzz_corpus}/${name}" "${fuzz_corpus}/${name}_seeds")
    set_tests_properties(fuzz.${name} PROPERTIES FIXTURES_REQUIRED ${name}_seeds LABELS fuzz TIMEOUT 600
                         PASS_REGULAR_EXPRESSION "Done [0-9]+ runs in [0-9]+ second")
    # Every crash once found, run once each (libFuzzer runs the files given as arguments).
    file(GLOB regressions CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/fuzz/regressions/${name}/*")
    if(regressions)
      add_test(NAME fuzz.${name}.regressions COMMAND "${binary}" -timeout=20 -rss_limit_mb=2048 ${ARG_OPTIONS} ${regressions})
      set_tests_properties(fuzz.${name}.regressions PROPERTIES LABELS fuzz TIMEOUT 300)
    endif()
  endfunction()

  # The JSON targets share a dictionary of JSON tokens, edge numbers and the formats' keys. The raw
  # volume reader must not allocate for the size it is told, only for what the file holds: 16 MiB
  # is far above what 4 kB of input (libFuzzer's default -max_len here) inflates to.
  set(json_dict "-dict=${CMAKE_CURRENT_LIST_DIR}/dicts/json.dict")
  voxref_fuzz_test(leb_stream SEEDS $<TARGET_FILE:make_leb_seeds>)
  voxref_fuzz_test(huffman SEEDS $<TARGET_FILE:make_fuzz_seeds> huffman)
  voxref_fuzz_test(adaptive_page SEEDS $<TARGET_FILE:make_fuzz_seeds> adaptive_page)
  voxref_fuzz_test(context_page SEEDS $<TARGET_FILE:make_fuzz_seeds> context_page)
  voxref_fuzz_test(timevarying_container SEEDS $<TARGET_FILE:make_fuzz_seeds> timevarying)
  voxref_fuzz_test(scene_json SEEDS $<TARGET_FILE:make_fuzz_seeds> scene OPTIONS ${json_dict})
  voxref_fuzz_test(raw_volume SEEDS $<TARGET_FILE:make_fuzz_seeds> raw_volume OPTIONS -malloc_limit_mb=16)
  voxref_fuzz_test(fixture_manifest SEEDS $<TARGET_FILE:make_fuzz_seeds> manifest OPTIONS ${json_dict})
  voxref_fuzz_test(results_json SEEDS $<TARGET_FILE:make_fuzz_seeds> results OPTIONS ${json_dict})
  voxref_fuzz_test(expectation_files SEEDS $<TARGET_FILE:make_fuzz_seeds> expectations)
endif()
