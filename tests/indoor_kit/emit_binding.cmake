# The generated binding of domains/indoor.ksm (factors and model, as bin/indoor has them) for
# the indoor kit's tests and benchmarks:
#   indoor_emit_binding(OUTPUT_DIR dir SOURCES_VAR var)
include(KsmcDomain)
function(indoor_emit_binding)
  cmake_parse_arguments(E "" "OUTPUT_DIR;SOURCES_VAR" "" ${ARGN})
  set(outputs ${E_OUTPUT_DIR}/indoor_factors.h ${E_OUTPUT_DIR}/indoor_factors.cpp
              ${E_OUTPUT_DIR}/indoor_model.h ${E_OUTPUT_DIR}/indoor_model.cpp)
  add_custom_command(
    OUTPUT ${outputs} ${E_OUTPUT_DIR}/indoor_main.cpp
    COMMAND ksmc emit domains/indoor.ksm --out ${E_OUTPUT_DIR}
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
    DEPENDS ksmc ${PROJECT_SOURCE_DIR}/domains/indoor.ksm ${KSMC_STDLIB_KSM}
    COMMENT "ksmc emit domains/indoor.ksm (indoor kit tests)"
    VERBATIM)
  set(${E_SOURCES_VAR} ${outputs} PARENT_SCOPE)
endfunction()
