// Development binary `indoor-dev`: what the generated indoor_main.cpp is, with the hand-written
// binding of tests/indoor_kit/binding.h standing in for the generated indoor_model.cpp.
#include "runtime/cli/domain_main.h"
#include "stdlib/indoor/kit/kit.h"
#include "tests/indoor_kit/binding.h"

int main(int argc, char** argv) {
  return ksmc::runtime::cli::run_domain_main(argc, argv, ksmc::stdlib::indoor::kit::domain_spec(ksmc::tests::indoor_kit::indoor_binding()));
}
