# ksmc_add_unit_test(NAME name SOURCES a.cpp ... LIBS lib ... [LABELS l ...])
# One Catch2 (v2) executable per module, registered with CTest under its own name.
# Tests that read ../shared get KSMC_SHARED_DIR as a compile definition and must skip
# cleanly (print a message, pass) when that folder is absent.
function(ksmc_add_unit_test)
  cmake_parse_arguments(T "" "NAME" "SOURCES;LIBS;LABELS" ${ARGN})
  add_executable(${T_NAME} ${T_SOURCES})
  target_link_libraries(${T_NAME} PRIVATE ksmc_catch_main ${T_LIBS})
  target_compile_definitions(${T_NAME} PRIVATE
    KSMC_SHARED_DIR="${KSMC_SHARED_DIR}"
    KSMC_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    KSMC_BINARY_DIR="${PROJECT_BINARY_DIR}")
  ksmc_project_warnings(${T_NAME})
  add_test(NAME ${T_NAME} COMMAND ${T_NAME})
  if(T_LABELS)
    set_tests_properties(${T_NAME} PROPERTIES LABELS "${T_LABELS}")
  endif()
endfunction()
