# cmake "-DCOMMAND=prog;args" -DEXPECT_RC=n "-DEXPECT_MATCH=text" -P ExpectFail.cmake
# Runs COMMAND; passes when it exits with EXPECT_RC and its stderr contains EXPECT_MATCH
# (also used for runs expected to succeed, EXPECT_RC=0).
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
if(NOT rc EQUAL EXPECT_RC)
  message(FATAL_ERROR "expected exit status ${EXPECT_RC}, got ${rc}\n${o}${e}")
endif()
string(FIND "${e}" "${EXPECT_MATCH}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "stderr lacks '${EXPECT_MATCH}':\n${e}")
endif()
