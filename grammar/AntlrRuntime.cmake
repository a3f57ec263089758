# Defines the INTERFACE target ksmc_antlr4_runtime (headers as SYSTEM + the runtime library:
# the static one when installed and KSMC_STATIC_ANTLR is on, else the shared one).
# Uses the runtime's CMake config when it has one, else looks for the header dir and library.
if(TARGET ksmc_antlr4_runtime)
  return()
endif()
# The static runtime, when installed, spares every ksmc process the dynamic linking of the
# shared one (about 0.8 ms of the 5 ms of a `ksmc infer` run on the seed's scene; docs/mln.md).
option(KSMC_STATIC_ANTLR "Link the ANTLR runtime statically when its static library is installed" ON)
find_package(antlr4-runtime CONFIG QUIET)
if(antlr4-runtime_FOUND AND TARGET antlr4_shared AND ANTLR4_INCLUDE_DIR)
  set(_ksmc_antlr_inc "${ANTLR4_INCLUDE_DIR}")
  set(_ksmc_antlr_lib antlr4_shared)
  if(KSMC_STATIC_ANTLR AND TARGET antlr4_static)
    set(_ksmc_antlr_lib antlr4_static)
  endif()
else()
  find_path(_ksmc_antlr_inc NAMES antlr4-runtime.h PATH_SUFFIXES antlr4-runtime REQUIRED)
  if(KSMC_STATIC_ANTLR)
    find_library(_ksmc_antlr_lib NAMES libantlr4-runtime.a antlr4-runtime REQUIRED)
  else()
    find_library(_ksmc_antlr_lib NAMES antlr4-runtime REQUIRED)
  endif()
endif()
add_library(ksmc_antlr4_runtime INTERFACE)
# clang rejects misc/InterpreterDataReader.h of the 4.9 runtime (a constructor that
# default-constructs a Vocabulary whose default constructor is deleted; g++ accepts it).
# Nothing of ours uses it, so for clang a copy of the umbrella header without that line is
# put first on the include path.
if(CMAKE_CXX_COMPILER_ID MATCHES "Clang" AND EXISTS "${_ksmc_antlr_inc}/antlr4-runtime.h")
  file(READ "${_ksmc_antlr_inc}/antlr4-runtime.h" _ksmc_umbrella)
  string(REPLACE "#include \"misc/InterpreterDataReader.h\"" "" _ksmc_umbrella "${_ksmc_umbrella}")
  # Written only when its text changes, so configuring again does not recompile the parser.
  file(WRITE "${CMAKE_BINARY_DIR}/antlr4-clang-shim/antlr4-runtime.h.new" "${_ksmc_umbrella}")
  configure_file("${CMAKE_BINARY_DIR}/antlr4-clang-shim/antlr4-runtime.h.new"
    "${CMAKE_BINARY_DIR}/antlr4-clang-shim/antlr4-runtime.h" COPYONLY)
  target_include_directories(ksmc_antlr4_runtime SYSTEM INTERFACE "${CMAKE_BINARY_DIR}/antlr4-clang-shim")
endif()
target_include_directories(ksmc_antlr4_runtime SYSTEM INTERFACE "${_ksmc_antlr_inc}")
target_link_libraries(ksmc_antlr4_runtime INTERFACE ${_ksmc_antlr_lib})
