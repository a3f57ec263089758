# Defines the INTERFACE target ksmc_antlr4_runtime (headers as SYSTEM + the shared runtime).
# Uses the runtime's CMake config when it has one, else looks for the header dir and library.
if(TARGET ksmc_antlr4_runtime)
  return()
endif()
find_package(antlr4-runtime CONFIG QUIET)
if(antlr4-runtime_FOUND AND TARGET antlr4_shared AND ANTLR4_INCLUDE_DIR)
  set(_ksmc_antlr_inc "${ANTLR4_INCLUDE_DIR}")
  set(_ksmc_antlr_lib antlr4_shared)
else()
  find_path(_ksmc_antlr_inc NAMES antlr4-runtime.h PATH_SUFFIXES antlr4-runtime REQUIRED)
  find_library(_ksmc_antlr_lib NAMES antlr4-runtime REQUIRED)
endif()
add_library(ksmc_antlr4_runtime INTERFACE)
# clang rejects misc/InterpreterDataReader.h of the 4.9 runtime (a constructor that
# default-constructs a Vocabulary whose default constructor is deleted; g++ accepts it).
# Nothing of ours uses it, so for clang a copy of the umbrella header without that line is
# put first on the include path.
if(CMAKE_CXX_COMPILER_ID MATCHES "Clang" AND EXISTS "${_ksmc_antlr_inc}/antlr4-runtime.h")
  file(READ "${_ksmc_antlr_inc}/antlr4-runtime.h" _ksmc_umbrella)
  string(REPLACE "#include \"misc/InterpreterDataReader.h\"" "" _ksmc_umbrella "${_ksmc_umbrella}")
  file(WRITE "${CMAKE_BINARY_DIR}/antlr4-clang-shim/antlr4-runtime.h" "${_ksmc_umbrella}")
  target_include_directories(ksmc_antlr4_runtime SYSTEM INTERFACE "${CMAKE_BINARY_DIR}/antlr4-clang-shim")
endif()
target_include_directories(ksmc_antlr4_runtime SYSTEM INTERFACE "${_ksmc_antlr_inc}")
target_link_libraries(ksmc_antlr4_runtime INTERFACE ${_ksmc_antlr_lib})
