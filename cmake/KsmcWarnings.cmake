# ksmc_project_warnings(TARGET): warnings as errors on the project's own code.
# Third-party headers come in through imported targets, which CMake treats as SYSTEM.
function(ksmc_project_warnings target)
  target_compile_options(${target} PRIVATE
    $<$<COMPILE_LANGUAGE:CXX>:-Wall -Wextra -Wpedantic -Werror -Wno-error=deprecated-declarations>)
endfunction()
