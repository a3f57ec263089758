// The toy domain as a real binary, written like a generated <domain>_main.cpp; used by
// test_cli to test Ctrl-C from outside the process.
#include "runtime/cli/domain_main.h"
#include "tests/mcmc/toy_domain.h"

int main(int argc, char** argv) {
  return ksmc::runtime::cli::run_domain_main(argc, argv, ksmc::tests::mcmc::toy_domain_spec());
}
