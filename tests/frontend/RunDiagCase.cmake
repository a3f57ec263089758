# One diagnostics golden case: runs `ksmc check input.ksm` in CASE_DIR (so paths in the
# output are exactly as given) and compares stderr with expected.stderr and the exit code
# with expected.exit. With UPDATE=ON the expected files are rewritten instead.
#   cmake -DKSMC=<ksmc> -DCASE_DIR=<dir> -DUPDATE=<ON|OFF> -P RunDiagCase.cmake
execute_process(
  COMMAND ${KSMC} check input.ksm
  WORKING_DIRECTORY ${CASE_DIR}
  RESULT_VARIABLE rc
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err
  TIMEOUT 60)
if(UPDATE)
  file(WRITE ${CASE_DIR}/expected.stderr "${err}")
  file(WRITE ${CASE_DIR}/expected.exit "${rc}\n")
  message(STATUS "updated ${CASE_DIR}")
  return()
endif()
if(NOT EXISTS ${CASE_DIR}/expected.stderr OR NOT EXISTS ${CASE_DIR}/expected.exit)
  message(FATAL_ERROR "${CASE_DIR}: no expected.stderr / expected.exit (run with -DKSMC_UPDATE_GOLDEN=ON)")
endif()
file(READ ${CASE_DIR}/expected.stderr want_err)
file(READ ${CASE_DIR}/expected.exit want_rc)
string(STRIP "${want_rc}" want_rc)
set(failed FALSE)
if(NOT rc STREQUAL want_rc)
  message("exit code: got '${rc}', expected '${want_rc}'")
  set(failed TRUE)
endif()
if(NOT err STREQUAL want_err)
  message("stderr differs.\n--- expected\n${want_err}--- got\n${err}---")
  set(failed TRUE)
endif()
if(failed)
  message(FATAL_ERROR "diagnostics golden mismatch in ${CASE_DIR}")
endif()
