# install_find_package: a user project outside the source tree (user_project/ plus a copy of
# domains/tabletop.ksm named scene.ksm, built as `mytabletop`) configures against the
# installed package with find_package(ksmc) + ksmc_add_domain and builds; the binary runs.
# A copy with an error in the domain file fails to configure, naming the file and place.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake)
ksmc_test_require_installed()
ksmc_test_tempdir(tmp)
file(COPY ${PROJECT_TEMPLATE}/CMakeLists.txt DESTINATION ${tmp}/src)
configure_file(${SOURCE_DIR}/domains/tabletop.ksm ${tmp}/src/scene.ksm COPYONLY)

ksmc_test_run(NAME "configure the user project"
  COMMAND ${CMAKE_COMMAND} -S ${tmp}/src -B ${tmp}/build -DCMAKE_PREFIX_PATH=${PREFIX} -DCMAKE_BUILD_TYPE=Release
  OUT out)
ksmc_test_expect("${out}" "ksmc ${KSMC_VERSION} from ${PREFIX}, kits: [a-z;]*tabletop" "user project configure")
ksmc_test_run(NAME "build the user project" COMMAND ${CMAKE_COMMAND} --build ${tmp}/build -j 2)
ksmc_test_run(NAME "mytabletop --help" COMMAND ${tmp}/build/mytabletop --help OUT out)
ksmc_test_expect("${out}" "--iterations" "mytabletop --help")
ksmc_test_run(NAME "mytabletop on the seed example"
  COMMAND ${tmp}/build/mytabletop ${SOURCE_DIR}/examples/tabletop/seed_example.json --out ${tmp}/out
          --iterations 20 --seed 1 --quiet)
if(NOT EXISTS ${tmp}/out/scene_graph.json)
  message(FATAL_ERROR "mytabletop wrote no scene_graph.json")
endif()

# A domain file with an error stops the configure with ksmc's diagnostic (file:line:col).
file(COPY ${PROJECT_TEMPLATE}/CMakeLists.txt DESTINATION ${tmp}/bad)
file(WRITE ${tmp}/bad/scene.ksm "domain bad;\ninclude \"stdlib/tabletop.ksm\";\ntype object;\nhard nope(o).\n")
ksmc_test_run(NAME "configure a project with a bad domain file" EXPECT 1
  COMMAND ${CMAKE_COMMAND} -S ${tmp}/bad -B ${tmp}/bad/build -DCMAKE_PREFIX_PATH=${PREFIX} OUT out)
ksmc_test_expect("${out}" "ksmc_add_domain\\(mytabletop\\): `ksmc kit scene.ksm` failed:[ \n]+scene.ksm:4:6: error: "
                 "bad domain file")
file(REMOVE_RECURSE ${tmp})
