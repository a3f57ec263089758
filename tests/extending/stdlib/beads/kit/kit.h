// The test kit `beads` (docs/extending.md, "A whole domain"): beads on a line fitted to 1D
// data, `beads_demo DATA.txt --out DIR` (one number per line) -> beads.json with "queries".
#pragma once

#include "runtime/cli/domain_spec.h"
#include "stdlib/beads/blocks.h"

namespace ksmc::stdlib::beads::kit {

runtime::cli::DomainSpec domain_spec(const blocks::Binding& binding);

}  // namespace ksmc::stdlib::beads::kit
