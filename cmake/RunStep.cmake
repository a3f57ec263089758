# run(COMMAND...) for `cmake -P` test scripts: runs the command in ${SOURCE_DIR}; on a
# non-zero exit stops the script with the command, its stdout and stderr. Sets `out` and
# `err` in the caller's scope.
function(run)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY ${SOURCE_DIR} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
  set(err "${err}" PARENT_SCOPE)
endfunction()
