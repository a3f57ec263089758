# bench/indoor/bench_indoor_run (included from bench/indoor/CMakeLists.txt): the kit end to end
# on lab_b.png. Needs the generated indoor factors of tests/indoor_kit.
if(TARGET ksmc_stdlib_indoor_kit)
  include(KsmcDomain)
  ksmc_emit_factors(DOMAIN indoor FILE domains/indoor.ksm
                    OUTPUT_DIR ${CMAKE_CURRENT_BINARY_DIR}/gen_indoor SOURCES_VAR bench_indoor_gen)
  add_executable(bench_indoor_run ${PROJECT_SOURCE_DIR}/bench/indoor/bench_indoor_run.cpp ${bench_indoor_gen})
  target_include_directories(bench_indoor_run PRIVATE ${CMAKE_CURRENT_BINARY_DIR}/gen_indoor)
  target_link_libraries(bench_indoor_run PRIVATE ksmc::stdlib_indoor_kit)
  target_compile_definitions(bench_indoor_run PRIVATE KSMC_SHARED_DIR="${KSMC_SHARED_DIR}")
  ksmc_project_warnings(bench_indoor_run)
endif()
