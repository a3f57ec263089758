# Turning domain files into C++ and targets.
#
# ksmc_emit_factors(DOMAIN name FILE path/relative/to/source.ksm OUTPUT_DIR dir SOURCES_VAR var)
#   Runs `ksmc emit` at build time (from the source folder, so generated comments name
#   the file as written) and sets `var` to the generated sources.
set(KSMC_STDLIB_KSM
  ${PROJECT_SOURCE_DIR}/stdlib/core.ksm
  ${PROJECT_SOURCE_DIR}/stdlib/indoor.ksm
  ${PROJECT_SOURCE_DIR}/stdlib/tabletop.ksm)

function(ksmc_emit_factors)
  cmake_parse_arguments(E "" "DOMAIN;FILE;OUTPUT_DIR;SOURCES_VAR" "" ${ARGN})
  set(outputs ${E_OUTPUT_DIR}/${E_DOMAIN}_factors.h ${E_OUTPUT_DIR}/${E_DOMAIN}_factors.cpp)
  add_custom_command(
    OUTPUT ${outputs}
    COMMAND ksmc emit ${E_FILE} --out ${E_OUTPUT_DIR}
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
    DEPENDS ksmc ${PROJECT_SOURCE_DIR}/${E_FILE} ${KSMC_STDLIB_KSM}
    COMMENT "ksmc emit ${E_FILE}"
    VERBATIM)
  set(${E_SOURCES_VAR} ${outputs} PARENT_SCOPE)
endfunction()
