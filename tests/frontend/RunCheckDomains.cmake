# `ksmc check domains/*.ksm` succeeds with no diagnostics at all (no warnings either).
execute_process(COMMAND ${KSMC} check domains/indoor.ksm domains/tabletop.ksm
  WORKING_DIRECTORY ${ROOT} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
message("${out}")
if(NOT rc EQUAL 0 OR NOT err STREQUAL "")
  message(FATAL_ERROR "ksmc check of the domain files: exit ${rc}\n${err}")
endif()
if(NOT out MATCHES "domains/indoor.ksm: ok \\(17 rules, 11 evidence, 5 query predicates, 5 kernel pairs, 3 schedule phases\\)")
  message(FATAL_ERROR "unexpected summary for indoor: ${out}")
endif()
if(NOT out MATCHES "domains/tabletop.ksm: ok \\(32 rules, 15 evidence, 4 query predicates, 2 kernel pairs, 1 schedule phase\\)")
  message(FATAL_ERROR "unexpected summary for tabletop: ${out}")
endif()
