# Helpers of the install tests (cmake -P scripts).

# ksmc_test_run(NAME <what> COMMAND <argv...> [WORKING_DIRECTORY dir] [EXPECT code] [OUT var])
# Runs a command, fails the test (showing its output) unless it exits with EXPECT (default 0).
function(ksmc_test_run)
  cmake_parse_arguments(R "" "NAME;WORKING_DIRECTORY;EXPECT;OUT" "COMMAND" ${ARGN})
  if(NOT DEFINED R_EXPECT)
    set(R_EXPECT 0)
  endif()
  if(NOT R_WORKING_DIRECTORY)
    set(R_WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  endif()
  string(TIMESTAMP t0 "%s")
  execute_process(COMMAND ${R_COMMAND}
    WORKING_DIRECTORY ${R_WORKING_DIRECTORY}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(TIMESTAMP t1 "%s")
  math(EXPR dt "${t1} - ${t0}")
  if(NOT "${rc}" STREQUAL "${R_EXPECT}")
    string(REPLACE ";" " " line "${R_COMMAND}")
    message(FATAL_ERROR "${R_NAME}: exit ${rc}, expected ${R_EXPECT}\n  command: ${line}\n"
                        "--- stdout\n${out}--- stderr\n${err}")
  endif()
  message(STATUS "${R_NAME}: exit ${rc} (${dt} s)")
  if(R_OUT)
    set(${R_OUT} "${out}${err}" PARENT_SCOPE)
  endif()
endfunction()

# ksmc_test_expect(<text> <regex> <what>): fails unless text matches.
function(ksmc_test_expect text regex what)
  if(NOT text MATCHES "${regex}")
    message(FATAL_ERROR "${what}: expected output matching '${regex}', got:\n${text}")
  endif()
endfunction()

# ksmc_test_tempdir(var): a fresh folder under the system temp folder (outside any source
# tree, so `include "stdlib/..."` cannot be found by walking up to this checkout).
function(ksmc_test_tempdir var)
  set(base "$ENV{TMPDIR}")
  if(NOT base OR NOT IS_DIRECTORY "${base}")
    set(base /tmp)
  endif()
  execute_process(COMMAND mktemp -d "${base}/ksmc-install-test-XXXXXX"
    RESULT_VARIABLE rc OUTPUT_VARIABLE dir OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT rc EQUAL 0 OR NOT IS_DIRECTORY "${dir}")
    message(FATAL_ERROR "cannot create a temporary folder under ${base}")
  endif()
  set(${var} "${dir}" PARENT_SCOPE)
endfunction()

function(ksmc_test_require_installed)
  if(NOT EXISTS ${PREFIX}/bin/ksmc OR NOT EXISTS ${PREFIX}/lib/cmake/ksmc/ksmcConfig.cmake)
    message(FATAL_ERROR "no installed ksmc at ${PREFIX} (the install_prefix test sets it up)")
  endif()
endfunction()
