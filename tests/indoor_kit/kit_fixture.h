// Test helpers: write a class grid as a map_saver PGM and load it through the kit's DomainSpec.
#pragma once

#include <filesystem>
#include <string>

#include <opencv2/imgcodecs.hpp>

#include "runtime/cli/domain_spec.h"
#include "runtime/mcmc/engine.h"
#include "stdlib/indoor/cell.h"
#include "stdlib/indoor/kit/kit.h"
#include "tests/indoor_kit/binding.h"

namespace ksmc::tests::indoor_kit {

inline std::filesystem::path temp_dir(const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() / ("ksmc_indoor_kit_" + name);
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

// Free 254, unknown 205, occupied 0 (map_saver values).
inline std::filesystem::path write_pgm(const stdlib::indoor::ClassGrid& g, const std::filesystem::path& file) {
  cv::Mat1b img(g.rows, g.cols);
  for (int r = 0; r < g.rows; ++r)
    for (int c = 0; c < g.cols; ++c) {
      const auto v = static_cast<stdlib::indoor::Cell>(g(r, c));
      img(r, c) = v == stdlib::indoor::Cell::Free ? 254 : v == stdlib::indoor::Cell::Unknown ? 205 : 0;
    }
  cv::imwrite(file.string(), img);
  return file;
}

inline runtime::cli::DomainInput input_for(const runtime::cli::DomainSpec& spec, const std::filesystem::path& map,
                                           std::uint64_t seed, std::map<std::string, std::string> given = {}) {
  runtime::cli::DomainInput in;
  in.inputs = {map};
  in.seed = seed;
  for (const auto& f : spec.flags) {
    const auto it = given.find(f.name);
    if (it != given.end()) in.flags.set(f.name, it->second, true);
    else if (!f.default_value.empty()) in.flags.set(f.name, f.default_value, false);
  }
  return in;
}

inline runtime::cli::DomainSpec spec() { return stdlib::indoor::kit::domain_spec(indoor_binding()); }

// One chain of `iters` iterations of a loaded domain.
inline runtime::mcmc::RunResult run_chain(const runtime::cli::DomainSetup& s, std::uint64_t iters, std::uint64_t seed) {
  runtime::mcmc::Engine e(s.model_factory, s.kernels, s.schedule);
  runtime::mcmc::EngineConfig cfg;
  cfg.iterations = iters;
  cfg.seed = seed;
  cfg.chains = 1;
  return e.run(cfg);
}

}  // namespace ksmc::tests::indoor_kit
