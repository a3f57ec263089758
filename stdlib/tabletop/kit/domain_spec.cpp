#include "stdlib/tabletop/kit/domain_spec.h"

#include <iostream>
#include <span>
#include <utility>

#include <fmt/format.h>
#include <opencv2/imgcodecs.hpp>

#include "runtime/mcmc/engine.h"
#include "stdlib/tabletop/graph_dot.h"
#include "stdlib/tabletop/hope_import.h"
#include "stdlib/tabletop/kit/refine_kernel.h"
#include "stdlib/tabletop/overlay.h"
#include "stdlib/tabletop/scene_io.h"

namespace ksmc::stdlib::tabletop::kit {

namespace cli = ksmc::runtime::cli;
namespace rm = ksmc::runtime::mcmc;

Scene load_input(const std::filesystem::path& path, const std::string& format, std::vector<std::string>& warnings) {
  if (format == "scene") {
    SceneLoad l = load_scene(path);
    warnings.insert(warnings.end(), l.warnings.begin(), l.warnings.end());
    return std::move(l.scene);
  }
  if (format == "hope") {
    HopeImport h = import_hope_file(path);
    warnings.insert(warnings.end(), h.warnings.begin(), h.warnings.end());
    return std::move(h.scene);
  }
  throw cli::UsageError(fmt::format("--input-format: expected 'scene' or 'hope', got '{}'", format));
}

TabletopResult result_of(const TabletopModel& model) {
  TabletopResult r;
  r.scene = model.scene();
  r.evidence = model.evidence();
  const MlnOutcome& m = model.mln_outcome();
  for (std::size_t i = 0; i < r.scene.objects.size(); ++i)
    r.probabilities.push_back({m.false_prob.at(Evidence::body(i)), m.hidden_prob.at(Evidence::body(i))});
  return r;
}

namespace {

void write_outputs(const rm::RunResult&, rm::Model& best, cli::OutputDir& out) {
  const auto& model = static_cast<const TabletopModel&>(best);
  const TabletopResult result = result_of(model);
  validate_result(result);
  out.write("scene_graph.json", scene_graph_json(result).dump(2) + "\n");
  out.write("graph.dot", graph_dot(result));
  const std::string why = render_dot_png(out.path_of("graph.dot"), out.path_of("graph.png"));
  if (!why.empty()) std::cerr << "tabletop: graph.png skipped: " << why << "\n";
  std::vector<std::string> warnings;
  const cv::Mat img = render_overlay(result, warnings);
  for (const auto& w : warnings) std::cerr << "tabletop: " << w << "\n";
  std::vector<unsigned char> png;
  if (!cv::imencode(".png", img, png)) throw std::runtime_error("tabletop: cannot encode overlay.png");
  out.write("overlay.png", std::span<const unsigned char>(png.data(), png.size()));
}

}  // namespace

KitSetup make_setup(std::shared_ptr<const KitConfig> config, const runtime::domain::MlnBinding& binding,
                    std::shared_ptr<const Scene> scene) {
  KitSetup k;
  k.config = config;
  k.scene = scene;
  k.setup.model_factory = [config, binding, scene](unsigned) -> std::unique_ptr<rm::Model> {
    return std::make_unique<TabletopModel>(scene, config, binding);
  };
  for (const auto& kc : config->kernels) k.setup.kernels.push_back(std::make_shared<RefineKernel>(kc));
  try {
    k.setup.schedule = rm::Schedule(rm::kernel_infos(k.setup.kernels), config->schedule);
  } catch (const rm::ScheduleError& e) {
    throw runtime::domain::ConfigError(config->source + ": schedule: " + e.what());
  }
  k.setup.write_results = write_outputs;
  const auto& ev = config->evidence;
  k.setup.summary_extra = {
      {"objects", scene->objects.size()},
      {"evidence",
       {{"stable_tol_rad", ev.stable_tol_rad},
        {"contact_eps_m", ev.contact_eps},
        {"intersect_eps_m", ev.intersect_eps},
        {"vertical_contact_eps_m", ev.vertical_contact_eps},
        {"vertical_intersect_eps_m", ev.vertical_intersect_eps},
        {"higher_tol_m", ev.higher_tol}}},
      {"likelihood",
       {{"sigma_px", config->likelihood.sigma_px},
        {"robust", config->likelihood.robust},
        {"outlier_px", config->likelihood.outlier_px}}}};
  return k;
}

cli::DomainSpec domain_spec(const runtime::domain::DomainConfig& config, const runtime::domain::MlnBinding& binding) {
  // Validated now; a configuration error is reported by `load` (exit code 1 with the
  // message) so the generated main, which has no handler of its own, never terminates.
  std::shared_ptr<const KitConfig> kit;
  std::string config_error;
  try {
    kit = std::make_shared<const KitConfig>(read_kit_config(config));
    MlnEvaluator probe(binding, {std::string(kTableId)});  // the binding fits the kit
  } catch (const runtime::domain::ConfigError& e) {
    config_error = e.what();
  }
  cli::DomainSpec spec;
  spec.name = config.domain;
  spec.version = "1.0.0";
  spec.description = "table-top scene graph from 6D pose estimates (knowledge-supervised DDMCMC)";
  spec.inputs_help = "scene.json";
  spec.default_iterations = 2000;
  spec.flags = {{"input-format", "input format: scene (scene.json) or hope (HOPE meta_data.json)", "scene",
                 cli::DomainFlag::Kind::text}};
  spec.load = [kit, binding, config_error](const cli::DomainInput& in) {
    if (!config_error.empty()) throw runtime::domain::ConfigError(config_error);
    std::vector<std::string> warnings;
    auto scene = std::make_shared<const Scene>(load_input(in.inputs.at(0), in.flags.text("input-format"), warnings));
    for (const auto& w : warnings) std::cerr << "tabletop: warning: " << w << "\n";
    KitSetup k = make_setup(kit, binding, scene);
    if (!scene->image.empty()) k.setup.extra_inputs.push_back(scene->image);
    return std::move(k.setup);
  };
  return spec;
}

}  // namespace ksmc::stdlib::tabletop::kit
