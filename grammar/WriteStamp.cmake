# cmake -DGRAMMAR=<Ksm.g4> -DSTAMP=<file> -P WriteStamp.cmake : writes the grammar's SHA-256.
file(SHA256 ${GRAMMAR} _sha)
file(WRITE ${STAMP} "${_sha}\n")
