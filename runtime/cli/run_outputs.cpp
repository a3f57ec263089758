#include "runtime/cli/run_outputs.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#ifndef KSMC_VERSION
#error "KSMC_VERSION must be defined by the build (PROJECT_VERSION)"
#endif

namespace ksmc::runtime::cli {

namespace {

// JSON has no infinities: -inf log posteriors (impossible states) become null.
nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json kernel_json(const mcmc::KernelStats& k, const std::string& reverse) {
  return {{"name", k.name},
          {"reverse", reverse},
          {"selected", k.selected},
          {"proposed", k.proposed()},
          {"declined", k.declined},
          {"accepted", k.accepted},
          {"rejected", k.rejected()},
          {"acceptance_rate", k.acceptance_rate()}};
}

}  // namespace

std::string_view ksmc_version() noexcept { return KSMC_VERSION; }

nlohmann::json make_summary(const mcmc::RunResult& r, const mcmc::Schedule& schedule, const RunInfo& info) {
  nlohmann::json j;
  j["ksmc_version"] = std::string(ksmc_version());
  j["domain"] = info.domain_extra;
  j["domain"]["name"] = info.domain_name;
  j["domain"]["version"] = info.domain_version;
  j["seed"] = info.config.seed;
  j["chains"] = info.config.chains;
  j["iterations_per_chain"] = info.config.iterations;  // with until_plateau: the most a chain runs
  if (info.config.stop_at_plateau) {
    j["until_plateau"] = {{"window", info.config.stop_at_plateau->window},
                          {"min_gain", info.config.stop_at_plateau->min_gain},
                          {"min_gain_is", info.plateau_gain_what},
                          {"judged_every", info.config.plateau_every},
                          {"chains_reached", std::count_if(r.chains.begin(), r.chains.end(),
                                                           [](const mcmc::ChainResult& c) { return c.plateau.has_value(); })}};
  } else {
    j["until_plateau"] = nullptr;
  }
  j["iterations"] = r.iterations;
  j["burn_in"] = info.config.burn_in;
  j["thin"] = info.config.thin;
  j["cancelled"] = r.cancelled || !info.interrupted.empty();
  j["interrupted"] = info.interrupted.empty() ? nlohmann::json(nullptr) : nlohmann::json(info.interrupted);
  j["seconds"] = r.seconds;
  j["iterations_per_second"] = r.seconds > 0.0 ? static_cast<double>(r.iterations) / r.seconds : 0.0;
  j["acceptance_rate"] = r.acceptance_rate();
  const auto& best = r.best();
  j["best"] = {{"log_posterior", number(best.best_log_posterior)},
               {"chain", best.chain},
               {"iteration", best.best_iteration}};
  nlohmann::json kernels = nlohmann::json::array();
  for (std::size_t k = 0; k < r.kernels.size(); ++k) {
    kernels.push_back(kernel_json(r.kernels[k], schedule.kernels()[k].reverse));
  }
  j["kernels"] = std::move(kernels);
  nlohmann::json chains = nlohmann::json::array();
  std::uint64_t samples = 0;
  for (const auto& c : r.chains) {
    std::uint64_t selected = 0;
    for (const auto& k : c.kernels) selected += k.selected;
    chains.push_back({{"chain", c.chain},
                      {"iterations", c.iterations},
                      {"cancelled", c.cancelled},
                      {"seconds", c.seconds},
                      {"initial_log_posterior", number(c.initial_log_posterior)},
                      {"final_log_posterior", number(c.final_log_posterior)},
                      {"best_log_posterior", number(c.best_log_posterior)},
                      {"best_iteration", c.best_iteration},
                      {"acceptance_rate", selected == 0 ? 0.0
                                                        : static_cast<double>(c.accepted()) /
                                                              static_cast<double>(selected)},
                      {"samples", c.samples.size()},
                      {"plateau_iteration", c.plateau ? nlohmann::json(c.plateau->iteration) : nlohmann::json(nullptr)},
                      {"plateau_seconds", c.plateau ? nlohmann::json(c.plateau->seconds) : nlohmann::json(nullptr)}});
    samples += c.samples.size();
  }
  j["chain_results"] = std::move(chains);
  j["samples"] = samples;
  j["hash_algorithm"] = "fnv1a-64";
  nlohmann::json inputs = nlohmann::json::array();
  for (const auto& h : info.inputs) {
    inputs.push_back({{"path", h.path.string()}, {"bytes", h.bytes}, {"fnv1a64", h.hex()}});
  }
  j["inputs"] = std::move(inputs);
  nlohmann::json outputs = nlohmann::json::array();
  for (const auto& f : info.outputs) outputs.push_back({{"path", f.path}, {"bytes", f.bytes}, {"sha256", f.sha256}});
  j["outputs"] = std::move(outputs);
  return j;
}

std::string trace_csv(const mcmc::RunResult& r) {
  std::string out =
      "chain,iteration,log_posterior,log_likelihood,log_prior,best_log_posterior,acceptance_window,"
      "acceptance_total";
  for (const auto& k : r.kernels) out += ",acceptance_" + k.name;
  out += '\n';
  for (const auto& c : r.chains) {
    for (const auto& t : c.trace) {
      out += fmt::format("{},{},{},{},{},{},{},{}", c.chain, t.iteration, t.log_posterior,
                         t.log_likelihood, t.log_prior, t.best_log_posterior, t.acceptance_window,
                         t.acceptance_total);
      // Empty cell: the kernel was not selected in that window.
      for (const double a : t.kernel_acceptance_window) {
        out += std::isnan(a) ? std::string(",") : fmt::format(",{}", a);
      }
      out += '\n';
    }
  }
  return out;
}

std::string samples_jsonl(const mcmc::RunResult& r) {
  std::string out;
  for (const auto& c : r.chains) {
    for (const auto& s : c.samples) {
      const nlohmann::json line = {{"chain", c.chain},
                                   {"iteration", s.iteration},
                                   {"log_posterior", number(s.log_posterior)},
                                   {"state", s.state}};
      out += line.dump();
      out += '\n';
    }
  }
  return out;
}

nlohmann::json best_state_json(const mcmc::RunResult& r) {
  const auto& best = r.best();
  return {{"chain", best.chain},
          {"iteration", best.best_iteration},
          {"log_posterior", number(best.best_log_posterior)},
          {"state", best.best_state}};
}

}  // namespace ksmc::runtime::cli
