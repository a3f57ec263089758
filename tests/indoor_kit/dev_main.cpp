// Development binary `indoor-dev`: what the generated indoor_main.cpp will be, with the
// hand-built configuration of config_fixture.h standing in for indoor_model.cpp.
#include <iostream>

#include "runtime/cli/domain_main.h"
#include "stdlib/indoor/kit/kit.h"
#include "tests/indoor_kit/binding.h"
#include "tests/indoor_kit/config_fixture.h"

int main(int argc, char** argv) {
  try {
    const auto spec = ksmc::stdlib::indoor::kit::domain_spec(ksmc::tests::indoor_kit::indoor_config(),
                                                             ksmc::tests::indoor_kit::indoor_binding());
    return ksmc::runtime::cli::run_domain_main(argc, argv, spec);
  } catch (const std::exception& e) {  // a ConfigError: the domain file asks for something the kit lacks
    std::cerr << "indoor: " << e.what() << "\n";
    return 1;
  }
}
