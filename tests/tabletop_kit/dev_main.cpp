// Development binary `tabletop-dev`: what the generated tabletop_main.cpp will be, with the
// hand-built configuration of config_fixture.h standing in for tabletop_model.cpp.
#include "runtime/cli/domain_main.h"
#include "stdlib/tabletop/kit/domain_spec.h"
#include "tabletop_factors.h"
#include "tests/tabletop_kit/config_fixture.h"

#include <iostream>

int main(int argc, char** argv) {
  try {
    ksmc::runtime::domain::MlnBinding binding{&ksmc_generated::tabletop::program,
                                            &ksmc_generated::tabletop::make_domain,
                                            &ksmc_generated::tabletop::ground};
    const auto spec = ksmc::stdlib::tabletop::kit::domain_spec(ksmc::tests::tabletop_kit::tabletop_config(), binding);
    return ksmc::runtime::cli::run_domain_main(argc, argv, spec);
  } catch (const std::exception& e) {  // a ConfigError: the domain file asks for something the kit lacks
    std::cerr << "tabletop: " << e.what() << "\n";
    return 1;
  }
}
