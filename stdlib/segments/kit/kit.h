// The segments stdlib kit: turns a DomainConfig (generated from a domain file that declares
// its likelihood with stdlib/segments.ksm, e.g. examples/segments/segments.ksm) and the
// generated Markov logic binding into the DomainSpec of the domain binary:
//   segments POINTS.txt --out DIR [--seed N] [--iterations N] ...
// Input: one point `x y` (metres) per line, `#` comments. Outputs: segments.json,
// overlay.png and the common best_state.json / summary.json. See docs/segments.md.
#pragma once

#include "runtime/cli/domain_spec.h"
#include "runtime/domain/config.h"

namespace ksmc::stdlib::segments::kit {

// The config is read once here (ConfigError naming the call's `where` for anything the kit
// does not implement) and again on every load.
runtime::cli::DomainSpec domain_spec(const runtime::domain::DomainConfig& config,
                                     const runtime::domain::MlnBinding& binding);

}  // namespace ksmc::stdlib::segments::kit
