# bench_tabletop_iteration (source in bench/tabletop/, included from bench/tabletop/CMakeLists.txt):
# time per DDMCMC iteration of the table-top kit and the share spent in Markov logic.
if(TARGET ksmc_stdlib_tabletop_kit AND TARGET ksmc_tabletop_sim)
  include(KsmcDomain)
  ksmc_emit_factors(DOMAIN tabletop FILE domains/tabletop.ksm
                    OUTPUT_DIR ${CMAKE_CURRENT_BINARY_DIR}/gen_tabletop SOURCES_VAR ttkit_bench_gen)
  add_executable(bench_tabletop_iteration ${PROJECT_SOURCE_DIR}/bench/tabletop/bench_tabletop_iteration.cpp
                 ${ttkit_bench_gen})
  target_include_directories(bench_tabletop_iteration PRIVATE ${CMAKE_CURRENT_BINARY_DIR}/gen_tabletop)
  target_link_libraries(bench_tabletop_iteration PRIVATE ksmc::stdlib_tabletop_kit ksmc::tabletop_sim fmt::fmt)
  ksmc_project_warnings(bench_tabletop_iteration)
endif()
