// The segments stdlib kit: turns the generated binding of a domain file written against
// stdlib/segments.ksm (e.g. examples/segments/segments.ksm) into the DomainSpec of the domain
// binary:
//   segments POINTS.txt --out DIR [--seed N] [--iterations N] [--evidence-out FILE] ...
// Input: one point `x y` (metres) per line, `#` comments. Outputs: segments.json (with
// "queries"), overlay.png and the common best_state.json / summary.json. See docs/segments.md.
#pragma once

#include "runtime/cli/domain_spec.h"
#include "stdlib/segments/blocks.h"

namespace ksmc::stdlib::segments::kit {

// Never throws; `binding` must outlive the spec (generated code keeps it in a static). What
// the kit cannot run is a runtime::domain::ConfigError from `load` (an internal error).
runtime::cli::DomainSpec domain_spec(const blocks::Binding& binding);

}  // namespace ksmc::stdlib::segments::kit
