// The common output files of a domain run, rendered as text (written by domain_main):
//   summary.json     run summary (schema below, documented in docs/sampler.md)
//   trace.csv        one row per chain and trace point (--trace)
//   samples.jsonl    one posterior sample per line (--samples N)
//   best_state.json  the best state over all chains (always)
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "runtime/cli/file_hash.h"
#include "runtime/io/staged_dir.h"
#include "runtime/mcmc/engine.h"

namespace ksmc::runtime::cli {

// ksmc's version (CMake PROJECT_VERSION).
std::string_view ksmc_version() noexcept;

struct RunInfo {
  std::string domain_name;
  std::string domain_version;
  mcmc::EngineConfig config;           // the effective settings of the run
  std::vector<FileHash> inputs;        // positional inputs, then the domain's extra inputs
  std::vector<io::StagedDir::Entry> outputs;  // every file of the folder but summary.json
  std::string interrupted;             // the signal that stopped the run ("SIGTERM"), "" = none
  nlohmann::json domain_extra = nlohmann::json::object();
  std::string plateau_gain_what;       // what config.stop_at_plateau->min_gain stands for
};

nlohmann::json make_summary(const mcmc::RunResult& result, const mcmc::Schedule& schedule,
                            const RunInfo& info);
std::string trace_csv(const mcmc::RunResult& result);
std::string samples_jsonl(const mcmc::RunResult& result);
nlohmann::json best_state_json(const mcmc::RunResult& result);

}  // namespace ksmc::runtime::cli
