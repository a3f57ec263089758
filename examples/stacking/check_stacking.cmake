# CTest example_stacking: runs bin/stacking on the bundled scene and checks that the domain's
# own query predicates reach scene_graph.json's "queries" with the arrangement of the scene
# (scene.truth.json): box_1 carries box_0, which carries box_6; box_4 carries box_2; box_3
# stands alone; box_5 leans against box_0; nothing floats. Decided: above 0.6 / below 0.4.
#   cmake -DBIN=... -DSCENE=... -DOUT=... -P check_stacking.cmake
cmake_minimum_required(VERSION 3.20)  # string(JSON), IN_LIST
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${BIN} ${SCENE} --out ${OUT} --seed 1 --iterations 500 -q
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "stacking exited with ${rc}: ${err}")
endif()
file(READ ${OUT}/scene_graph.json graph)

set(objects box_0 box_1 box_2 box_3 box_4 box_5 box_6)
set(true_onTable box_1 box_3 box_4)
set(true_stacked box_0 box_2 box_6)
set(true_base box_0 box_1 box_4)
set(true_leaning box_5)
set(true_floating)
set(failures "")
foreach(pred onTable stacked base leaning floating)
  foreach(id table ${objects})
    string(JSON p ERROR_VARIABLE missing GET "${graph}" queries ${pred} ${id})
    if(missing)
      string(APPEND failures "\n  queries.${pred}.${id} missing")
      continue()
    endif()
    if(id IN_LIST true_${pred})
      if(NOT p GREATER 0.6)
        string(APPEND failures "\n  ${pred}(${id}) = ${p}, expected > 0.6")
      endif()
    elseif(NOT p LESS 0.4)
      string(APPEND failures "\n  ${pred}(${id}) = ${p}, expected < 0.4")
    endif()
  endforeach()
endforeach()
# No decisions output in this domain: the objects carry relations only.
string(JSON fp ERROR_VARIABLE no_fp GET "${graph}" objects 0 false_prob)
if(NOT no_fp)
  string(APPEND failures "\n  objects[0].false_prob present without a scene.decisions output")
endif()
if(failures)
  message(FATAL_ERROR "example_stacking:${failures}")
endif()
message(STATUS "example_stacking: onTable, stacked, base, leaning, floating as in scene.truth.json")
