// The common command line of every domain binary.
//
//   <domain> [flags] INPUT...
//     --seed N --iterations N --chains N --threads N --out DIR --samples N --thin K
//     --burn-in N --trace --trace-every K --quiet --help --version  + the domain's flags
//
// Writes into --out DIR (created if missing), every file atomically: the domain's own
// results, best_state.json, trace.csv (--trace), samples.jsonl (--samples N > 0),
// report.html (runtime/report) and, last, summary.json. Exit codes: 0 done, 1 error (bad input, cannot write; the message
// names the file), 2 usage error, 3 internal error (a runtime::domain::ConfigError: the kit
// cannot run a configuration `ksmc check` accepted), 130 interrupted by Ctrl-C (outputs
// still complete). `--evidence-out FILE` writes the best state's evidence as an Alchemy
// `.db` (DomainSetup::evidence_db), atomically.
#pragma once

#include <iostream>
#include <ostream>

#include "runtime/cli/domain_spec.h"

namespace ksmc::runtime::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitError = 1;
inline constexpr int kExitUsage = 2;
inline constexpr int kExitInternal = 3;
inline constexpr int kExitInterrupted = 130;

struct CliStreams {
  std::ostream& out;  // --help, --version
  std::ostream& err;  // progress, messages, errors
  bool tty = false;   // draw a progress bar (else plain periodic lines)
};

// Uses std::cout / std::cerr; the bar is drawn when stderr is a terminal.
int run_domain_main(int argc, const char* const* argv, const DomainSpec& spec);
int run_domain_main(int argc, const char* const* argv, const DomainSpec& spec, const CliStreams& io);

}  // namespace ksmc::runtime::cli
