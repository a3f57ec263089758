# Two switches that make a build faster without changing the code it generates.
#
# KSMC_LINKER (auto | lld | gold | default): the linker. `auto` takes lld when the compiler
#   can use it (Debian package `lld`), else the system default. The domain and test binaries
#   link PCL, VTK and OpenCV: GNU ld takes 3-8 s per binary and there are about 170 of them;
#   lld about a fifth of that (tabletop: 6.3 s with ld, 3.8 s gold, 1.1 s lld).
# KSMC_DEBUG_INFO (ON | OFF): OFF drops -g from the RelWithDebInfo flags. GCC emits the same
#   code with and without -g, so tests see the same binaries; compiling is about 20 % faster.
#   CI turns it off (.ci/run); debuggers and callgrind's line view want it on (the default).
include(CheckLinkerFlag)

set(KSMC_LINKER "auto" CACHE STRING "Linker: auto (lld when usable), lld, gold or default")
set_property(CACHE KSMC_LINKER PROPERTY STRINGS auto lld gold default)
option(KSMC_DEBUG_INFO "Debug info (-g) in RelWithDebInfo builds" ON)

set(_ksmc_linker "")
if(KSMC_LINKER STREQUAL "auto")
  check_linker_flag(CXX "-fuse-ld=lld" KSMC_HAVE_LLD)
  if(KSMC_HAVE_LLD)
    set(_ksmc_linker lld)
  endif()
elseif(KSMC_LINKER STREQUAL "lld" OR KSMC_LINKER STREQUAL "gold")
  check_linker_flag(CXX "-fuse-ld=${KSMC_LINKER}" KSMC_HAVE_${KSMC_LINKER})
  if(NOT KSMC_HAVE_${KSMC_LINKER})
    message(FATAL_ERROR "KSMC_LINKER=${KSMC_LINKER}: the compiler cannot link with -fuse-ld=${KSMC_LINKER} "
                        "(install the Debian package `lld` or `binutils`, or use -DKSMC_LINKER=default)")
  endif()
  set(_ksmc_linker ${KSMC_LINKER})
elseif(NOT KSMC_LINKER STREQUAL "default")
  message(FATAL_ERROR "KSMC_LINKER=${KSMC_LINKER}: expected auto, lld, gold or default")
endif()
if(_ksmc_linker)
  add_link_options(-fuse-ld=${_ksmc_linker})
  message(STATUS "ksmc: linking with ${_ksmc_linker}")
else()
  message(STATUS "ksmc: linking with the default linker")
endif()

if(NOT KSMC_DEBUG_INFO)
  foreach(lang C CXX)
    string(REGEX REPLACE "(^| )-g[0-9]?( |$)" " " CMAKE_${lang}_FLAGS_RELWITHDEBINFO
           "${CMAKE_${lang}_FLAGS_RELWITHDEBINFO}")
  endforeach()
endif()
