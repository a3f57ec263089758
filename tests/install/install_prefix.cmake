# install_prefix: cmake --install BUILD_DIR --prefix PREFIX into a fresh prefix, then checks
# the layout (docs/install.md) and that the installed ksmc finds its own stdlib.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake)

file(REMOVE_RECURSE ${PREFIX})
ksmc_test_run(NAME "cmake --install" COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${PREFIX})

set(expected
  bin/ksmc
  lib/libksmc_runtime_io.a lib/libksmc_runtime_mln.a lib/libksmc_runtime_mcmc.a lib/libksmc_runtime_cli.a
  lib/libksmc_stdlib_tabletop_kit.a lib/libksmc_stdlib_tabletop.a lib/libksmc_stdlib_tabletop_output.a
  lib/libksmc_stdlib_indoor_kit.a lib/libksmc_stdlib_indoor.a lib/libksmc_stdlib_indoor_io.a
  lib/libksmc_stdlib_indoor_detect.a
  include/ksmc/runtime/ksmc_runtime.h include/ksmc/runtime/cli/domain_main.h include/ksmc/runtime/domain/binding.h include/ksmc/runtime/mln/program.h
  include/ksmc/runtime/mcmc/model.h include/ksmc/runtime/io/atomic_file.h
  include/ksmc/stdlib/tabletop/kit/kit.h include/ksmc/stdlib/indoor/kit/kit.h
  share/ksmc/stdlib/core.ksm share/ksmc/stdlib/tabletop.ksm share/ksmc/stdlib/indoor.ksm
  lib/cmake/ksmc/ksmcConfig.cmake lib/cmake/ksmc/ksmcConfigVersion.cmake lib/cmake/ksmc/ksmcTargets.cmake
  lib/cmake/ksmc/KsmcDomain.cmake)
if(EXISTS ${SOURCE_DIR}/stdlib/segments.ksm)
  list(APPEND expected share/ksmc/stdlib/segments.ksm lib/libksmc_stdlib_segments_kit.a)
endif()
# Compiler internals, tests and the simulation tools are not part of the package.
set(unexpected
  lib/libksmc_frontend.a lib/libksmc_grammar.a lib/libksmc_catch_main.a lib/libksmc_tabletop_sim.a
  bin/ksmc-scenegen bin/tabletop bin/indoor include/ksmc/compiler include/ksmc/tests)
foreach(f ${expected})
  if(NOT EXISTS ${PREFIX}/${f})
    message(FATAL_ERROR "not installed: ${PREFIX}/${f}")
  endif()
endforeach()
foreach(f ${unexpected})
  if(EXISTS ${PREFIX}/${f})
    message(FATAL_ERROR "installed but should not be: ${PREFIX}/${f}")
  endif()
endforeach()

# The installed headers include only installed headers (no path back into the tree).
file(GLOB_RECURSE headers ${PREFIX}/include/ksmc/*.h)
foreach(h ${headers})
  file(STRINGS ${h} includes REGEX "^#include \"")
  foreach(line ${includes})
    string(REGEX REPLACE "^#include \"([^\"]+)\".*" "\\1" inc "${line}")
    get_filename_component(dir ${h} DIRECTORY)
    if(NOT EXISTS ${PREFIX}/include/ksmc/${inc} AND NOT EXISTS ${dir}/${inc})
      message(FATAL_ERROR "${h} includes \"${inc}\", which is not installed")
    endif()
  endforeach()
endforeach()

ksmc_test_run(NAME "installed ksmc --version" COMMAND ${PREFIX}/bin/ksmc --version OUT out)
ksmc_test_expect("${out}" "^ksmc ${KSMC_VERSION}\n$" "ksmc --version")

# A domain file outside any source tree: its stdlib include resolves to PREFIX/share/ksmc.
ksmc_test_tempdir(tmp)
configure_file(${SOURCE_DIR}/domains/tabletop.ksm ${tmp}/scene.ksm COPYONLY)
ksmc_test_run(NAME "installed ksmc check" COMMAND ${PREFIX}/bin/ksmc check scene.ksm WORKING_DIRECTORY ${tmp} OUT out)
ksmc_test_expect("${out}" "^scene.ksm: ok" "installed ksmc check")
ksmc_test_run(NAME "installed ksmc kit" COMMAND ${PREFIX}/bin/ksmc kit scene.ksm WORKING_DIRECTORY ${tmp} OUT out)
ksmc_test_expect("${out}" "^tabletop tabletop\n$" "installed ksmc kit")
file(REMOVE_RECURSE ${tmp})
