# Turning domain files into C++ and targets.
#
# ksmc_emit_factors(DOMAIN name FILE path/relative/to/source.ksm OUTPUT_DIR dir SOURCES_VAR var)
#   Runs `ksmc emit` at build time (from the source folder, so generated comments name
#   the file as written) and sets `var` to the generated sources.
set(KSMC_STDLIB_KSM
  ${PROJECT_SOURCE_DIR}/stdlib/core.ksm
  ${PROJECT_SOURCE_DIR}/stdlib/indoor.ksm
  ${PROJECT_SOURCE_DIR}/stdlib/tabletop.ksm)
if(EXISTS ${PROJECT_SOURCE_DIR}/stdlib/segments.ksm)
  list(APPEND KSMC_STDLIB_KSM ${PROJECT_SOURCE_DIR}/stdlib/segments.ksm)
endif()

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

# ksmc_add_domain(NAME FILE [KIT kit])
#   Builds the domain binary bin/NAME from FILE (a path relative to the source folder):
#   `ksmc emit` generates <domain>_factors, <domain>_model and <domain>_main, which are
#   compiled and linked against the stdlib kit that runs the domain (default: NAME, i.e.
#   the target ksmc_stdlib_<kit>_kit) and the common domain CLI.
function(ksmc_add_domain NAME FILE)
  cmake_parse_arguments(D "" "KIT" "" ${ARGN})
  if(NOT D_KIT)
    set(D_KIT ${NAME})
  endif()
  get_filename_component(stem ${FILE} NAME_WE)
  set(dir ${CMAKE_CURRENT_BINARY_DIR}/${NAME}_generated)
  set(outputs
    ${dir}/${stem}_factors.h ${dir}/${stem}_factors.cpp
    ${dir}/${stem}_model.h ${dir}/${stem}_model.cpp ${dir}/${stem}_main.cpp)
  add_custom_command(
    OUTPUT ${outputs}
    COMMAND ksmc emit ${FILE} --out ${dir}
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
    DEPENDS ksmc ${PROJECT_SOURCE_DIR}/${FILE} ${KSMC_STDLIB_KSM}
    COMMENT "ksmc emit ${FILE}"
    VERBATIM)
  add_executable(${NAME} ${outputs})
  target_include_directories(${NAME} PRIVATE ${dir})
  target_link_libraries(${NAME} PRIVATE ksmc_stdlib_${D_KIT}_kit ksmc::runtime_cli ksmc::runtime_domain)
  ksmc_project_warnings(${NAME})
endfunction()
