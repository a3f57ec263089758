# `cmake --install <build> --prefix P` lays out an installed ksmc:
#
#   P/bin/ksmc                          the compiler (finds P/share/ksmc/stdlib by itself)
#   P/lib/libksmc_*.a                   runtime, every stdlib kit and the libraries they link
#   P/include/ksmc/{runtime,stdlib}/... headers, same layout as the source tree, so generated
#                                       code compiles unchanged with -I P/include/ksmc
#   P/share/ksmc/stdlib/*.ksm           the stdlib signatures (`include "stdlib/x.ksm"`)
#   P/lib/cmake/ksmc/                   the CMake package: find_package(ksmc) gives the
#                                       targets ksmc::<name> (ksmc_<name> in this build),
#                                       ksmc::ksmc (the compiler) and ksmc_add_domain().
#
# Included from the top-level CMakeLists.txt after every target exists. What gets installed
# is derived, not listed: the runtime libraries, every kit ksmc_stdlib_<k>_kit for which a
# stdlib/<k>.ksm exists, and every ksmc library those link (transitively). Test, bench and
# simulation targets are installed only when a kit links them.

set(KSMC_INSTALL_BINDIR bin)
set(KSMC_INSTALL_LIBDIR lib)
set(KSMC_INSTALL_INCLUDEDIR include/ksmc)
set(KSMC_INSTALL_DATADIR share/ksmc)
set(KSMC_INSTALL_CMAKEDIR lib/cmake/ksmc)

# The kits: one per stdlib package that has a kit target.
set(KSMC_KITS "")
foreach(ksm ${KSMC_STDLIB_KSM})
  get_filename_component(stem ${ksm} NAME_WE)
  if(TARGET ksmc_stdlib_${stem}_kit)
    list(APPEND KSMC_KITS ${stem})
  endif()
endforeach()

# Third-party imported targets the installed libraries may link, and the find_dependency()
# call that recreates each in a user project. OpenCV is collected per component.
function(_ksmc_package_of lib out_var)
  set(pkg "")
  if(lib MATCHES "^fmt::")
    set(pkg "fmt")
  elseif(lib MATCHES "^nlohmann_json::")
    set(pkg "nlohmann_json 3")
  elseif(lib MATCHES "^Eigen3::")
    set(pkg "Eigen3 3.3 NO_MODULE")
  elseif(lib MATCHES "^CLI11::")
    set(pkg "CLI11")
  elseif(lib MATCHES "^yaml-cpp")
    set(pkg "yaml-cpp")
  elseif(lib MATCHES "^Threads::")
    set(pkg "Threads")
  elseif(lib MATCHES "^TBB::")
    set(pkg "TBB")
  elseif(lib MATCHES "^opencv_")
    set(pkg "OpenCV")
  endif()
  set(${out_var} "${pkg}" PARENT_SCOPE)
endfunction()

# Walks the link interface of `target`, appending ksmc targets to KSMC_INSTALL_TARGETS and
# third-party dependencies to _ksmc_deps / _ksmc_opencv_components (parent scope).
function(_ksmc_collect target)
  if(target IN_LIST KSMC_INSTALL_TARGETS)
    return()
  endif()
  # Recursive calls update these variables in this function's scope; pass them on at the end.
  list(APPEND KSMC_INSTALL_TARGETS ${target})
  get_target_property(links ${target} INTERFACE_LINK_LIBRARIES)
  if(NOT links)
    set(links "")
  endif()
  foreach(item ${links})
    string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" item "${item}")
    if(item MATCHES "^\\$<BUILD_INTERFACE:")
      continue()  # not exported
    endif()
    if(item MATCHES "^\\$<")
      message(WARNING "ksmc install: ${target} links '${item}' (a generator expression); "
                      "the installed package may miss that dependency")
      continue()
    endif()
    # Imported targets found in a subfolder are not visible here: go by their name.
    set(real ${item})
    if(TARGET ${item})
      get_target_property(aliased ${item} ALIASED_TARGET)
      if(aliased)
        set(real ${aliased})
      endif()
      get_target_property(imported ${real} IMPORTED)
      if(NOT imported)
        _ksmc_collect(${real})
        continue()
      endif()
    endif()
    _ksmc_package_of(${real} pkg)
    if(NOT pkg AND NOT TARGET ${real} AND NOT real MATCHES "::")
      continue()  # a plain library file or flag: exported as written
    endif()
    if(pkg STREQUAL "OpenCV")
      string(REGEX REPLACE "^opencv_" "" component ${real})
      list(APPEND _ksmc_opencv_components ${component})
    elseif(pkg)
      list(APPEND _ksmc_deps "${pkg}")
    else()
      message(WARNING "ksmc install: ${target} links the imported target ${real}, which "
                      "cmake/KsmcInstall.cmake does not know how to find_dependency(); "
                      "add it to _ksmc_package_of")
    endif()
  endforeach()
  set(KSMC_INSTALL_TARGETS ${KSMC_INSTALL_TARGETS} PARENT_SCOPE)
  set(_ksmc_deps "${_ksmc_deps}" PARENT_SCOPE)
  set(_ksmc_opencv_components ${_ksmc_opencv_components} PARENT_SCOPE)
endfunction()

set(KSMC_INSTALL_TARGETS "")
set(_ksmc_deps "")
set(_ksmc_opencv_components "")
foreach(root ksmc_runtime_io ksmc_runtime_mln ksmc_runtime_mcmc ksmc_runtime_cli ksmc_runtime_domain)
  _ksmc_collect(${root})
endforeach()
foreach(kit ${KSMC_KITS})
  _ksmc_collect(ksmc_stdlib_${kit}_kit)
endforeach()

# find_dependency() lines for ksmcConfig.cmake, in a fixed order.
list(REMOVE_DUPLICATES _ksmc_deps)
list(SORT _ksmc_deps)
set(KSMC_FIND_DEPENDENCIES "")
foreach(dep ${_ksmc_deps})
  string(APPEND KSMC_FIND_DEPENDENCIES "find_dependency(${dep})\n")
endforeach()
if(_ksmc_opencv_components)
  list(REMOVE_DUPLICATES _ksmc_opencv_components)
  list(SORT _ksmc_opencv_components)
  list(JOIN _ksmc_opencv_components " " cv)
  string(APPEND KSMC_FIND_DEPENDENCIES "find_dependency(OpenCV COMPONENTS ${cv})\n")
endif()

# Exported names drop the ksmc_ prefix (ksmc_runtime_cli -> ksmc::runtime_cli, as the
# aliases in the build); consumers compile as C++20 and find the headers under include/ksmc.
# Headers: those in the folders of each installed library's sources, and the umbrella
# headers directly in runtime/ and stdlib/ (runtime/ksmc_runtime.h).
foreach(top runtime stdlib)
  file(GLOB headers CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${top}/*.h)
  if(headers)
    install(FILES ${headers} DESTINATION ${KSMC_INSTALL_INCLUDEDIR}/${top} COMPONENT ksmc)
  endif()
endforeach()
set(_ksmc_header_dirs "")
foreach(target ${KSMC_INSTALL_TARGETS})
  string(REGEX REPLACE "^ksmc_" "" export_name ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${export_name})
  target_include_directories(${target} INTERFACE $<INSTALL_INTERFACE:${KSMC_INSTALL_INCLUDEDIR}>)
  target_compile_features(${target} INTERFACE cxx_std_20)
  get_target_property(dir ${target} SOURCE_DIR)
  get_target_property(sources ${target} SOURCES)
  set(header_dirs ${dir})
  if(sources)
    foreach(src ${sources})
      if(NOT src MATCHES "^\\$<")
        get_filename_component(src_path ${src} ABSOLUTE BASE_DIR ${dir})
        get_filename_component(src_dir ${src_path} DIRECTORY)
        list(APPEND header_dirs ${src_dir})
      endif()
    endforeach()
  endif()
  list(REMOVE_DUPLICATES header_dirs)
  foreach(hdir ${header_dirs})
    if(hdir IN_LIST _ksmc_header_dirs)
      continue()  # a folder shared by two libraries
    endif()
    list(APPEND _ksmc_header_dirs ${hdir})
    file(RELATIVE_PATH rel ${PROJECT_SOURCE_DIR} ${hdir})
    if(rel MATCHES "^\\.\\.")
      continue()  # generated sources in the build tree
    endif()
    file(GLOB headers CONFIGURE_DEPENDS ${hdir}/*.h)
    if(headers)
      install(FILES ${headers} DESTINATION ${KSMC_INSTALL_INCLUDEDIR}/${rel} COMPONENT ksmc)
    endif()
  endforeach()
endforeach()
list(JOIN KSMC_INSTALL_TARGETS " " _ksmc_target_list)
message(STATUS "ksmc install: kits {${KSMC_KITS}}; libraries ${_ksmc_target_list}")

install(TARGETS ksmc ${KSMC_INSTALL_TARGETS}
  EXPORT ksmcTargets
  RUNTIME DESTINATION ${KSMC_INSTALL_BINDIR}
  ARCHIVE DESTINATION ${KSMC_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${KSMC_INSTALL_LIBDIR}
  COMPONENT ksmc)
install(EXPORT ksmcTargets
  NAMESPACE ksmc::
  DESTINATION ${KSMC_INSTALL_CMAKEDIR}
  COMPONENT ksmc)
install(FILES ${KSMC_STDLIB_KSM} DESTINATION ${KSMC_INSTALL_DATADIR}/stdlib COMPONENT ksmc)

include(CMakePackageConfigHelpers)
set(KSMC_CONFIG_STDLIB_ROOT ${KSMC_INSTALL_DATADIR})
set(KSMC_CONFIG_KSMC ${KSMC_INSTALL_BINDIR}/ksmc)
configure_package_config_file(
  ${CMAKE_CURRENT_LIST_DIR}/ksmcConfig.cmake.in
  ${PROJECT_BINARY_DIR}/package/ksmcConfig.cmake
  INSTALL_DESTINATION ${KSMC_INSTALL_CMAKEDIR}
  PATH_VARS KSMC_CONFIG_STDLIB_ROOT KSMC_CONFIG_KSMC)
# 0.x: minor versions may break the generated-code contract.
write_basic_package_version_file(
  ${PROJECT_BINARY_DIR}/package/ksmcConfigVersion.cmake
  VERSION ${PROJECT_VERSION}
  COMPATIBILITY SameMinorVersion)
install(FILES
  ${PROJECT_BINARY_DIR}/package/ksmcConfig.cmake
  ${PROJECT_BINARY_DIR}/package/ksmcConfigVersion.cmake
  ${CMAKE_CURRENT_LIST_DIR}/KsmcDomain.cmake
  DESTINATION ${KSMC_INSTALL_CMAKEDIR}
  COMPONENT ksmc)
