# `ksmc import-mln` end to end: imports MLN (an Alchemy file) into OUT_KSM, runs `ksmc infer`
# on it with EVIDENCE, and requires the same marginals as EXPECTED (the stdout of the same
# rule base written natively in .ksm).
#   cmake -DKSMC=<ksmc> -DSOURCE_DIR=<src> -DMLN=<f.mln> -DQUERY=<p,q> -DEVIDENCE=<e.db>
#         -DEXPECTED=<expected.stdout> -DOUT_KSM=<build/x.ksm> -P RunImportInfer.cmake
execute_process(COMMAND ${KSMC} import-mln ${MLN} --query ${QUERY} --out ${OUT_KSM}
                WORKING_DIRECTORY ${SOURCE_DIR} RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "import-mln failed (${rc}):\n${err}")
endif()
execute_process(COMMAND ${KSMC} infer ${OUT_KSM} --evidence ${EVIDENCE}
                WORKING_DIRECTORY ${SOURCE_DIR} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
file(READ ${SOURCE_DIR}/${EXPECTED} want)
if(NOT rc EQUAL 0 OR NOT out STREQUAL want)
  message(FATAL_ERROR "infer on the imported rule base (exit ${rc}) differs.\n--- expected\n${want}--- got\n${out}${err}")
endif()
