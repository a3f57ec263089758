// The indoor stdlib kit: turns the binding generated from a domain file (docs/binding.md §3)
// into the DomainSpec of the domain binary:
//   indoor MAP.(png|pgm|yaml) --out DIR [--seed N] [--iterations N] [--resolution R]
//          [--robot x,y] [--thresholds ros|bormann]
//          [--source-refresh K]
// See docs/indoor_kit.md.
#pragma once

#include "runtime/cli/domain_spec.h"
#include "stdlib/indoor/blocks.h"

namespace ksmc::stdlib::indoor::kit {

// The spec keeps its own copy of the binding.
runtime::cli::DomainSpec domain_spec(const blocks::Binding& binding);

}  // namespace ksmc::stdlib::indoor::kit
