// Development binary `tabletop-dev`: run_domain_main + kit + the test fixture's binding of
// domains/tabletop.ksm (binding_fixture.h), for experiments with the kit alone.
#include "runtime/cli/domain_main.h"
#include "stdlib/tabletop/kit/domain_spec.h"
#include "tests/tabletop_kit/binding_fixture.h"

int main(int argc, char** argv) {
  return ksmc::runtime::cli::run_domain_main(argc, argv,
                                             ksmc::stdlib::tabletop::kit::domain_spec(ksmc::tests::tabletop_kit::ksm_binding()));
}
