# install_and_build_example: from a folder outside the source tree, the installed ksmc builds
# domains/tabletop.ksm into a binary, which then analyses the bundled seed example.
# When the segments example exists (examples/segments/segments.ksm), it is built the same way
# and runs on examples/segments/room.txt.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake)
ksmc_test_require_installed()
ksmc_test_tempdir(tmp)
set(ksmc ${PREFIX}/bin/ksmc)

ksmc_test_run(NAME "ksmc build tabletop"
  COMMAND ${ksmc} build ${SOURCE_DIR}/domains/tabletop.ksm -o ${tmp}/bin/tabletop -j 2
  WORKING_DIRECTORY ${tmp} OUT out)
ksmc_test_expect("${out}" "ksmc build: .*bin/tabletop \\(domain tabletop, kit tabletop\\) in [0-9.]+ s" "ksmc build tabletop")
message(STATUS "${out}")
ksmc_test_run(NAME "tabletop on the seed example"
  COMMAND ${tmp}/bin/tabletop ${SOURCE_DIR}/examples/tabletop/seed_example.json --out ${tmp}/out
          --iterations 50 --seed 1 --quiet
  WORKING_DIRECTORY ${tmp})
foreach(f scene_graph.json summary.json)
  if(NOT EXISTS ${tmp}/out/${f})
    message(FATAL_ERROR "tabletop built by ksmc build wrote no ${f} in ${tmp}/out")
  endif()
endforeach()
# No temporary work folder or half-written binary is left next to the output.
file(GLOB leftovers ${tmp}/bin/.*)
if(leftovers)
  message(FATAL_ERROR "ksmc build left files next to the binary: ${leftovers}")
endif()

if(EXISTS ${SOURCE_DIR}/examples/segments/segments.ksm)
  ksmc_test_run(NAME "ksmc build segments"
    COMMAND ${ksmc} build ${SOURCE_DIR}/examples/segments/segments.ksm -o ${tmp}/bin/segments -j 2
    WORKING_DIRECTORY ${tmp} OUT out)
  message(STATUS "${out}")
  ksmc_test_run(NAME "segments --help" COMMAND ${tmp}/bin/segments --help OUT out)
  ksmc_test_expect("${out}" "--iterations" "segments --help")
  if(EXISTS ${SOURCE_DIR}/examples/segments/room.txt)
    ksmc_test_run(NAME "segments on examples/segments/room.txt"
      COMMAND ${tmp}/bin/segments ${SOURCE_DIR}/examples/segments/room.txt --out ${tmp}/segments_out
              --iterations 200 --seed 1 --quiet)
    if(NOT EXISTS ${tmp}/segments_out/summary.json)
      message(FATAL_ERROR "segments built by ksmc build wrote no summary.json in ${tmp}/segments_out")
    endif()
  endif()
else()
  message(STATUS "examples/segments/segments.ksm absent: segments example skipped")
endif()

file(REMOVE_RECURSE ${tmp})
