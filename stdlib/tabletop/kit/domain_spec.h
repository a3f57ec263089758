// The table-top stdlib kit: turns a domain's generated binding (docs/binding.md §3,
// `<domain>_model.cpp`) into the common CLI's DomainSpec (runtime/cli/domain_spec.h).
//
//   tabletop scene.json --out DIR [--seed N] [--iterations N] [--input-format scene|hope]
//
// writes DIR/scene_graph.json, graph.dot, graph.png (when Graphviz is installed) and
// overlay.png from the best state of the chains. Nothing here names a predicate, type or
// kernel: evidence comes from the binding's extractors, the reported false / hidden
// probabilities from the predicates its `scene.decisions` output names, every query atom's
// marginal goes to scene_graph.json's "queries", kernels come from KernelDecl::move.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "runtime/cli/domain_spec.h"
#include "stdlib/tabletop/blocks.h"
#include "stdlib/tabletop/kit/tabletop_model.h"
#include "stdlib/tabletop/result.h"
#include "stdlib/tabletop/scene.h"

namespace ksmc::stdlib::tabletop::kit {

// The CLI spec of a domain run by this kit. The binding is checked when the binary loads
// its input: a binding the kit cannot run is a runtime::domain::ConfigError thrown by the
// spec's `load` (an internal error: `ksmc check` enforces the kit contract).
runtime::cli::DomainSpec domain_spec(const blocks::Binding& binding);

// Throws ConfigError when the kit cannot run the binding (kernel moves and sources, the
// decisions output's predicates, the model's shape).
void check_binding(const blocks::Binding& binding);

// Input readers used by the spec: scene.json (scene_io.h) or a HOPE meta_data.json.
// Warnings go to `warnings`.
Scene load_input(const std::filesystem::path& path, const std::string& format, std::vector<std::string>& warnings);

// Everything the spec's load step builds, for callers that drive mcmc::Engine themselves
// (tests, benchmarks). `binding` must outlive the setup.
struct KitSetup {
  std::shared_ptr<const Scene> scene;
  runtime::cli::DomainSetup setup;
};
KitSetup make_setup(const blocks::Binding& binding, std::shared_ptr<const Scene> scene, KitOptions options = {});

// The scene graph of a model's current state: poses, the geometric relations with the
// tolerances of the domain's extractors, and the decisions output's probabilities.
TabletopResult result_of(const TabletopModel& model);
// scene_graph.json: scene_graph_json of result_of plus "queries" (every query atom's
// marginal, constants named "table" and the object ids).
nlohmann::json scene_graph_of(const TabletopModel& model);
// The state's evidence as an Alchemy .db (replayable with `ksmc infer`).
std::string evidence_db_of(const TabletopModel& model);

}  // namespace ksmc::stdlib::tabletop::kit
