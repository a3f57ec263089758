# Table-top weights learned from simulated labelled scenes against the hand-set weights
# of domains/tabletop.ksm (docs/mln.md): generates training and held-back scenes
# (ksmc-scenegen), turns them into labelled worlds (ksmc-mln-tabletop worlds), learns by
# the conditional likelihood (ksmc learn --method cll), scores both weight sets on both
# sets of worlds (ksmc-mln-tabletop evaluate) and prints the table. Fails when a step
# fails, or when the learned weights do not reach a higher joint conditional
# log-likelihood than the hand-set ones on the training worlds (what the learner
# maximises; the held-back comparison is reported, not asserted).
# Variables: SCENEGEN, TOOL, KSMC, SOURCE_DIR, WORK.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
include(${CMAKE_CURRENT_LIST_DIR}/../../cmake/RunStep.cmake)
run(${SCENEGEN} --seed 101 --count 40 --objects 3..10 --out ${WORK}/train_scenes)
run(${SCENEGEN} --seed 202 --count 30 --objects 3..10 --out ${WORK}/test_scenes)
run(${TOOL} worlds --scenes ${WORK}/train_scenes --out ${WORK}/train)
run(${TOOL} worlds --scenes ${WORK}/test_scenes --out ${WORK}/test)
file(GLOB train ${WORK}/train/*.db)
file(GLOB test ${WORK}/test/*.db)
run(${KSMC} learn domains/tabletop.ksm --data ${train} --method cll --out ${WORK}/learned.ksm)
foreach(set train test)
  run(${TOOL} evaluate domains/tabletop.ksm ${WORK}/learned.ksm --data ${${set}} -I ${SOURCE_DIR})
  message(STATUS "${set} worlds:\n${out}")
  string(REGEX MATCHALL "joint CLL per world -?[0-9.]+" cll "${out}")
  list(LENGTH cll n)
  if(NOT n EQUAL 2)
    message(FATAL_ERROR "unexpected evaluation output:\n${out}")
  endif()
  list(GET cll 0 hand)
  list(GET cll 1 learned)
  string(REPLACE "joint CLL per world " "" hand "${hand}")
  string(REPLACE "joint CLL per world " "" learned "${learned}")
  set(${set}_hand ${hand})
  set(${set}_learned ${learned})
endforeach()
if(NOT train_learned GREATER train_hand)
  message(FATAL_ERROR "learned weights: training joint CLL ${train_learned} not above the hand-set ${train_hand}")
endif()
message(STATUS "joint CLL per world: training ${train_hand} (hand-set) -> ${train_learned} (learned); "
               "held-back ${test_hand} -> ${test_learned}")
