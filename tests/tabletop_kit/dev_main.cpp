// Development binary `tabletop-dev`: run_domain_main + kit + the generated binding of
// domains/tabletop.ksm, built with the kit's tests (the same program as bin/tabletop).
#include "runtime/cli/domain_main.h"
#include "stdlib/tabletop/kit/domain_spec.h"
#include "tests/tabletop_kit/binding_fixture.h"

int main(int argc, char** argv) {
  return ksmc::runtime::cli::run_domain_main(argc, argv,
                                             ksmc::stdlib::tabletop::kit::domain_spec(ksmc::tests::tabletop_kit::ksm_binding()));
}
