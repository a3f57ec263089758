# cmake -DGRAMMAR=<Ksm.g4> -DSTAMP=<file> -P CheckStamp.cmake : fails when the checked-in
# parser's stamp is not the grammar's SHA-256 (Ksm.g4 edited without ksmc_grammar_refresh).
file(SHA256 ${GRAMMAR} _sha)
file(READ ${STAMP} _stamp)
string(STRIP "${_stamp}" _stamp)
if(NOT _sha STREQUAL _stamp)
  message(FATAL_ERROR "${STAMP}: stamp ${_stamp} is not the SHA-256 of ${GRAMMAR} (${_sha}); "
                      "run `cmake --build <dir> --target ksmc_grammar_refresh` and commit grammar/generated/")
endif()
message(STATUS "grammar/generated/ matches Ksm.g4 (${_sha})")
