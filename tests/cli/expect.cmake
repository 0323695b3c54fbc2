cmake_minimum_required(VERSION 3.25)
# Script mode: runs COMMAND (a |-separated argument list) with optional ENVIRONMENT
# (|-separated NAME=VALUE), and fails unless its exit status is EXPECT_EXIT (a |-separated set of
# allowed values) and its combined output matches EXPECT_OUTPUT (a regular expression, optional).
# Then, optionally, runs CHECK (another |-separated command) which must exit 0.
# REQUIRES_FILE (optional): a data file the test needs; when it is missing the script stops with
# a line that the test's SKIP_REGULAR_EXPRESSION turns into "Skipped" (never passed), naming the file.
if(REQUIRES_FILE AND NOT EXISTS "${REQUIRES_FILE}")
  message(FATAL_ERROR "VOXREF_TEST_SKIPPED: ${REQUIRES_FILE} is missing (set VOXREF_SHARED_DIR to the shared data folder)")
endif()
string(REPLACE "|" ";" command "${COMMAND}")
if(ENVIRONMENT)
  string(REPLACE "|" ";" env "${ENVIRONMENT}")
  set(command ${CMAKE_COMMAND} -E env ${env} ${command})
endif()
execute_process(COMMAND ${command} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
string(REPLACE "|" ";" allowed "${EXPECT_EXIT}")
if(NOT status IN_LIST allowed)
  message(FATAL_ERROR "exit status ${status}, expected one of ${allowed}")
endif()
if(EXPECT_OUTPUT AND NOT "${out}${err}" MATCHES "${EXPECT_OUTPUT}")
  message(FATAL_ERROR "output does not match: ${EXPECT_OUTPUT}")
endif()
if(CHECK)
  string(REPLACE "|" ";" check "${CHECK}")
  execute_process(COMMAND ${check} RESULT_VARIABLE checkStatus OUTPUT_VARIABLE checkOut ERROR_VARIABLE checkErr)
  message("${checkOut}${checkErr}")
  if(NOT checkStatus EQUAL 0)
    message(FATAL_ERROR "check failed (${checkStatus})")
  endif()
endif()
