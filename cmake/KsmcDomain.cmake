# Turning domain files into C++ and targets. Used two ways:
#
#   * in this source tree (included by the top-level CMakeLists.txt): FILE is relative to
#     the source folder, the tool is the `ksmc` target, kits are the ksmc_stdlib_<kit>_kit
#     targets of this build;
#   * from an installed package (included by ksmcConfig.cmake, which sets
#     KSMC_PACKAGE_MODE, KSMC_EXECUTABLE and KSMC_STDLIB_ROOT): FILE is relative to the
#     calling CMakeLists.txt's folder, the tool is the installed ksmc, kits are the imported
#     ksmc::stdlib_<kit>_kit targets, and the kit defaults to the one the compiler picks
#     (`ksmc kit FILE` prints the domain name and kit; run when CMake configures).
#
# ksmc_emit_factors(DOMAIN name FILE path OUTPUT_DIR dir SOURCES_VAR var)
#   Runs `ksmc emit` at build time (from the source folder, so generated comments name
#   the file as written) and sets `var` to the generated factor sources.
#
# ksmc_add_domain(NAME FILE [KIT kit])
#   Builds the domain binary NAME from FILE: `ksmc emit` generates <domain>_factors,
#   <domain>_model and <domain>_main, which are compiled and linked against the stdlib kit
#   that runs the domain and the common domain CLI. In this tree the kit defaults to NAME.

if(KSMC_PACKAGE_MODE)
  file(GLOB KSMC_STDLIB_KSM ${KSMC_STDLIB_ROOT}/stdlib/*.ksm)
  set(_ksmc_tool ${KSMC_EXECUTABLE})
  set(_ksmc_tool_dep ${KSMC_EXECUTABLE})
  set(_ksmc_include_args)  # the installed ksmc searches its own share/ksmc
else()
  set(KSMC_STDLIB_KSM
    ${PROJECT_SOURCE_DIR}/stdlib/core.ksm
    ${PROJECT_SOURCE_DIR}/stdlib/indoor.ksm
    ${PROJECT_SOURCE_DIR}/stdlib/tabletop.ksm)
  if(EXISTS ${PROJECT_SOURCE_DIR}/stdlib/segments.ksm)
    list(APPEND KSMC_STDLIB_KSM ${PROJECT_SOURCE_DIR}/stdlib/segments.ksm)
  endif()
  set(_ksmc_tool ksmc)
  set(_ksmc_tool_dep ksmc)
  # `include "stdlib/..."` is found by searching up from the including file; a domain file
  # written into a build folder outside the source tree (a test's edited copy) finds it here.
  set(_ksmc_include_args -I ${PROJECT_SOURCE_DIR})
endif()

# The folder ksmc runs in and the absolute path of FILE (sets <prefix>_workdir, _abs).
macro(_ksmc_locate FILE prefix)
  if(KSMC_PACKAGE_MODE)
    set(${prefix}_workdir ${CMAKE_CURRENT_SOURCE_DIR})
  else()
    set(${prefix}_workdir ${PROJECT_SOURCE_DIR})
  endif()
  get_filename_component(${prefix}_abs ${FILE} ABSOLUTE BASE_DIR ${${prefix}_workdir})
endmacro()

function(ksmc_emit_factors)
  cmake_parse_arguments(E "" "DOMAIN;FILE;OUTPUT_DIR;SOURCES_VAR" "" ${ARGN})
  _ksmc_locate(${E_FILE} loc)
  set(outputs ${E_OUTPUT_DIR}/${E_DOMAIN}_factors.h ${E_OUTPUT_DIR}/${E_DOMAIN}_factors.cpp)
  add_custom_command(
    OUTPUT ${outputs}
    COMMAND ${_ksmc_tool} emit ${_ksmc_include_args} ${E_FILE} --out ${E_OUTPUT_DIR}
    WORKING_DIRECTORY ${loc_workdir}
    DEPENDS ${_ksmc_tool_dep} ${loc_abs} ${KSMC_STDLIB_KSM}
    COMMENT "ksmc emit ${E_FILE}"
    VERBATIM)
  set(${E_SOURCES_VAR} ${outputs} PARENT_SCOPE)
endfunction()

function(ksmc_add_domain NAME FILE)
  cmake_parse_arguments(D "" "KIT" "" ${ARGN})
  _ksmc_locate(${FILE} loc)
  if(KSMC_PACKAGE_MODE)
    # Ask the compiler for the domain name (it names the generated files) and its kit;
    # asked again whenever the domain file changes.
    execute_process(
      COMMAND ${KSMC_EXECUTABLE} kit ${FILE}
      WORKING_DIRECTORY ${loc_workdir}
      RESULT_VARIABLE status
      OUTPUT_VARIABLE answer
      ERROR_VARIABLE diagnostics
      OUTPUT_STRIP_TRAILING_WHITESPACE)
    if(NOT status EQUAL 0 OR NOT answer MATCHES "^([A-Za-z0-9_]+) ([A-Za-z0-9_]+)$")
      message(FATAL_ERROR "ksmc_add_domain(${NAME}): `ksmc kit ${FILE}` failed:\n${diagnostics}${answer}")
    endif()
    set(stem ${CMAKE_MATCH_1})
    if(NOT D_KIT)
      set(D_KIT ${CMAKE_MATCH_2})
    endif()
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${loc_abs})
    set(kit_target ksmc::stdlib_${D_KIT}_kit)
    if(NOT TARGET ${kit_target})
      message(FATAL_ERROR "ksmc_add_domain(${NAME}): the installed ksmc has no kit '${D_KIT}' "
                          "(installed kits: ${KSMC_KITS})")
    endif()
  else()
    if(NOT D_KIT)
      set(D_KIT ${NAME})
    endif()
    set(kit_target ksmc_stdlib_${D_KIT}_kit)
    get_filename_component(stem ${FILE} NAME_WE)
  endif()
  set(dir ${CMAKE_CURRENT_BINARY_DIR}/${NAME}_generated)
  set(outputs
    ${dir}/${stem}_factors.h ${dir}/${stem}_factors.cpp
    ${dir}/${stem}_model.h ${dir}/${stem}_model.cpp ${dir}/${stem}_main.cpp)
  add_custom_command(
    OUTPUT ${outputs}
    COMMAND ${_ksmc_tool} emit ${_ksmc_include_args} ${FILE} --out ${dir}
    WORKING_DIRECTORY ${loc_workdir}
    DEPENDS ${_ksmc_tool_dep} ${loc_abs} ${KSMC_STDLIB_KSM}
    COMMENT "ksmc emit ${FILE}"
    VERBATIM)
  add_executable(${NAME} ${outputs})
  target_include_directories(${NAME} PRIVATE ${dir})
  target_link_libraries(${NAME} PRIVATE ${kit_target} ksmc::runtime_cli ksmc::runtime_domain)
  if(NOT KSMC_PACKAGE_MODE)
    ksmc_project_warnings(${NAME})
  endif()
endfunction()
