# KSMC_SANITIZE: sanitizers for the whole build, e.g. -DKSMC_SANITIZE=address,undefined
# (ASan + UBSan; scripts/test-sanitize.sh). Every project target is compiled and linked
# with -fsanitize=<list>; UBSan findings abort (-fno-sanitize-recover=all), so a test
# that triggers one fails. The installed runtime library carries the link flag as an
# INTERFACE link option (ksmc_sanitize_interface), so a user project or `ksmc build`
# linking against a sanitized install links the sanitizer runtimes without extra flags.
set(KSMC_SANITIZE "" CACHE STRING "Sanitizers for the whole build (e.g. address,undefined); empty = none")

if(KSMC_SANITIZE)
  if(NOT KSMC_SANITIZE MATCHES "^[a-z,]+$")
    message(FATAL_ERROR "KSMC_SANITIZE='${KSMC_SANITIZE}': expected a comma-separated list such as address,undefined")
  endif()
  set(KSMC_SANITIZE_FLAGS -fsanitize=${KSMC_SANITIZE} -fno-omit-frame-pointer)
  if(KSMC_SANITIZE MATCHES "undefined")
    list(APPEND KSMC_SANITIZE_FLAGS -fno-sanitize-recover=all)
  endif()
  # GCC's -Wmaybe-uninitialized misfires on instrumented code (std::regex's std::function
  # state at -O1 with ASan), so under -Werror it stays a warning in sanitized builds.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    list(APPEND KSMC_SANITIZE_FLAGS -Wno-error=maybe-uninitialized)
  endif()
  add_compile_options(${KSMC_SANITIZE_FLAGS})
  add_link_options(-fsanitize=${KSMC_SANITIZE})
  message(STATUS "ksmc: sanitizers: ${KSMC_SANITIZE}")
endif()

# ksmc_sanitize_interface(TARGET): consumers of TARGET (also through an installed package)
# link with the sanitizers this build uses.
function(ksmc_sanitize_interface target)
  if(KSMC_SANITIZE)
    target_link_options(${target} INTERFACE -fsanitize=${KSMC_SANITIZE})
  endif()
endfunction()
