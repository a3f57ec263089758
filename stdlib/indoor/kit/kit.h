// The indoor stdlib kit: turns a DomainConfig (generated from domains/indoor.ksm) and the
// generated Markov logic binding into the DomainSpec of the `indoor` binary:
//   indoor MAP.(png|pgm|yaml) --out DIR [--seed N] [--iterations N] [--resolution R]
//          [--robot x,y] [--thresholds ros|bormann] [--semantic-every K] [--semantic-after N]
//          [--source-refresh K]
// See docs/indoor_kit.md.
#pragma once

#include "runtime/cli/domain_spec.h"
#include "runtime/domain/config.h"

namespace ksmc::stdlib::indoor::kit {

// The config is validated on every load (ConfigError naming the call's `where`).
runtime::cli::DomainSpec domain_spec(const runtime::domain::DomainConfig& config,
                                     const runtime::domain::MlnBinding& binding);

}  // namespace ksmc::stdlib::indoor::kit
