# bench_tabletop_iteration (source in bench/tabletop/, included from bench/tabletop/CMakeLists.txt):
# time per DDMCMC iteration of the table-top kit and the share spent in Markov logic, on the
# generated binding of domains/tabletop.ksm (ksmc_tabletop_kit_factors, tests/tabletop_kit).
if(TARGET ksmc_stdlib_tabletop_kit AND TARGET ksmc_tabletop_sim AND TARGET ksmc_tabletop_kit_factors)
  add_executable(bench_tabletop_iteration ${PROJECT_SOURCE_DIR}/bench/tabletop/bench_tabletop_iteration.cpp)
  target_link_libraries(bench_tabletop_iteration PRIVATE ksmc::stdlib_tabletop_kit ksmc_tabletop_kit_factors
                        ksmc::tabletop_sim fmt::fmt)
  ksmc_project_warnings(bench_tabletop_iteration)
endif()
