# ksmc_build_errors: `ksmc build` and `ksmc kit` refuse bad usage and bad input with a clear
# message and the documented exit status, and a build-tree ksmc says it needs an install.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake)
ksmc_test_tempdir(tmp)

ksmc_test_run(NAME "kit" COMMAND ${KSMC} kit domains/tabletop.ksm WORKING_DIRECTORY ${SOURCE_DIR} OUT out)
ksmc_test_expect("${out}" "^tabletop tabletop\n$" "ksmc kit tabletop")
ksmc_test_run(NAME "kit indoor" COMMAND ${KSMC} kit domains/indoor.ksm WORKING_DIRECTORY ${SOURCE_DIR} OUT out)
ksmc_test_expect("${out}" "^indoor indoor\n$" "ksmc kit indoor")

ksmc_test_run(NAME "build without -o" EXPECT 2
  COMMAND ${KSMC} build domains/tabletop.ksm WORKING_DIRECTORY ${SOURCE_DIR} OUT out)
ksmc_test_expect("${out}" "ksmc build: give one FILE and -o BIN" "build without -o")
ksmc_test_run(NAME "build -j 0" EXPECT 2
  COMMAND ${KSMC} build domains/tabletop.ksm -o ${tmp}/t -j 0 WORKING_DIRECTORY ${SOURCE_DIR} OUT out)
ksmc_test_expect("${out}" "-j: '0' is not a positive number" "build -j 0")
ksmc_test_run(NAME "build -o folder" EXPECT 2
  COMMAND ${KSMC} build domains/tabletop.ksm -o ${tmp} WORKING_DIRECTORY ${SOURCE_DIR} OUT out)
ksmc_test_expect("${out}" "is a folder" "build -o folder")

# Errors in the domain file: the usual diagnostics, exit 1, nothing written.
file(WRITE ${tmp}/bad.ksm "domain bad;\ninclude \"stdlib/tabletop.ksm\";\ntype object;\nhard nope(o).\n")
ksmc_test_run(NAME "build a bad file" EXPECT 1
  COMMAND ${KSMC} build bad.ksm -o bad -I ${SOURCE_DIR} WORKING_DIRECTORY ${tmp} OUT out)
ksmc_test_expect("${out}" "bad.ksm:4:6: error: " "build a bad file")
ksmc_test_run(NAME "kit of a bad file" EXPECT 1 COMMAND ${KSMC} kit -I ${SOURCE_DIR} bad.ksm WORKING_DIRECTORY ${tmp})

# A domain whose likelihood no kit declares: nothing to link against.
file(WRITE ${tmp}/nokit.ksm "domain nokit;\ntype t;\nevidence e(t);\nquery q(t);\nprob 0.9: e(x) => q(x).\n")
ksmc_test_run(NAME "kit of a kit-less file" EXPECT 1 COMMAND ${KSMC} kit nokit.ksm WORKING_DIRECTORY ${tmp} OUT out)
ksmc_test_expect("${out}" "nokit.ksm: error: the likelihood is not declared by a stdlib kit" "kit-less file")

# The build tree's ksmc is not an installed one.
ksmc_test_run(NAME "build from the build tree" EXPECT 1
  COMMAND ${KSMC} build domains/tabletop.ksm -o ${tmp}/t WORKING_DIRECTORY ${SOURCE_DIR} OUT out)
ksmc_test_expect("${out}" "ksmc build: needs an installed ksmc" "build from the build tree")
if(EXISTS ${tmp}/t OR EXISTS ${tmp}/bad)
  message(FATAL_ERROR "a failed ksmc build wrote its output")
endif()
file(REMOVE_RECURSE ${tmp})
