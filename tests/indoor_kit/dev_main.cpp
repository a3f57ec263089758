// Development binary `indoor-dev`: bin/indoor built in the test tree (the generated binding of
// domains/indoor.ksm through the kit), so the kit tests run it without the domains/ build.
#include "runtime/cli/domain_main.h"
#include "stdlib/indoor/kit/kit.h"
#include "tests/indoor_kit/binding.h"

int main(int argc, char** argv) {
  return ksmc::runtime::cli::run_domain_main(argc, argv, ksmc::stdlib::indoor::kit::domain_spec(ksmc::tests::indoor_kit::indoor_binding()));
}
