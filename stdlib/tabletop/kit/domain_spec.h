// The table-top stdlib kit: turns the domain file's configuration (generated
// <domain>_model.cpp, runtime/domain/config.h) and the generated Markov logic part into
// the common CLI's DomainSpec (runtime/cli/domain_spec.h).
//
//   tabletop scene.json --out DIR [--seed N] [--iterations N] [--input-format scene|hope]
//
// writes DIR/scene_graph.json, graph.dot, graph.png (when Graphviz is installed) and
// overlay.png from the best state of the chains.
#pragma once

#include <filesystem>
#include <memory>

#include "runtime/cli/domain_spec.h"
#include "runtime/domain/config.h"
#include "stdlib/tabletop/kit/kit_config.h"
#include "stdlib/tabletop/kit/tabletop_model.h"
#include "stdlib/tabletop/result.h"
#include "stdlib/tabletop/scene.h"

namespace ksmc::stdlib::tabletop::kit {

// Reads and validates the configuration now; the returned spec loads the input when the
// binary runs. A ConfigError (naming file:line of the item the kit does not implement) is
// raised by the spec's `load`, so the CLI reports it (exit code 1) instead of the process
// terminating; read_kit_config() throws it directly.
runtime::cli::DomainSpec domain_spec(const runtime::domain::DomainConfig& config,
                                     const runtime::domain::MlnBinding& binding);

// Input readers used by the spec: scene.json (scene_io.h) or a HOPE meta_data.json.
// Warnings go to `warnings`.
Scene load_input(const std::filesystem::path& path, const std::string& format, std::vector<std::string>& warnings);

// Everything the spec's load step builds, for callers that drive mcmc::Engine themselves
// (tests, benchmarks).
struct KitSetup {
  std::shared_ptr<const KitConfig> config;
  std::shared_ptr<const Scene> scene;
  runtime::cli::DomainSetup setup;
};
KitSetup make_setup(std::shared_ptr<const KitConfig> config, const runtime::domain::MlnBinding& binding,
                    std::shared_ptr<const Scene> scene);

// The scene graph of a model's current state: best poses, evidence, and the MLN query
// marginals at that state (falseEst → false_prob, hidden → hidden_prob).
TabletopResult result_of(const TabletopModel& model);

}  // namespace ksmc::stdlib::tabletop::kit
