# bench/indoor/bench_indoor_run (included from bench/indoor/CMakeLists.txt): the kit end to end
# on lab_b.png, with the generated binding of domains/indoor.ksm.
if(TARGET ksmc_stdlib_indoor_kit)
  include(${CMAKE_CURRENT_LIST_DIR}/emit_binding.cmake)
  indoor_emit_binding(OUTPUT_DIR ${CMAKE_CURRENT_BINARY_DIR}/gen_indoor SOURCES_VAR bench_indoor_gen)
  add_executable(bench_indoor_run ${PROJECT_SOURCE_DIR}/bench/indoor/bench_indoor_run.cpp ${bench_indoor_gen})
  target_include_directories(bench_indoor_run PRIVATE ${CMAKE_CURRENT_BINARY_DIR}/gen_indoor)
  target_link_libraries(bench_indoor_run PRIVATE ksmc::stdlib_indoor_kit)
  target_compile_definitions(bench_indoor_run PRIVATE KSMC_SHARED_DIR="${KSMC_SHARED_DIR}")
  ksmc_project_warnings(bench_indoor_run)
endif()
