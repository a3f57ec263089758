#include "stdlib/tabletop/kit/domain_spec.h"

#include <algorithm>
#include <cctype>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <span>
#include <utility>

#include <fmt/format.h>
#include <opencv2/imgcodecs.hpp>

#include "runtime/domain/kernels.h"
#include "runtime/mcmc/engine.h"
#include "stdlib/tabletop/cloud_likelihood.h"
#include "stdlib/tabletop/graph_dot.h"
#include "stdlib/tabletop/hope_import.h"
#include "stdlib/tabletop/kit/fit_kernel.h"
#include "stdlib/tabletop/kit/kit_likelihood.h"
#include "stdlib/tabletop/kit/input_cost.h"
#include "stdlib/tabletop/kit/refine_kernel.h"
#include "stdlib/tabletop/overlay.h"
#include "stdlib/tabletop/scene_io.h"
#ifdef KSMC_HAVE_PERCEPTION
#include "stdlib/tabletop/perception/point_grid.h"
#include "stdlib/tabletop/perception/scene_from_cloud.h"
#include "stdlib/tabletop/perception/scene_json.h"
#endif
#ifdef KSMC_HAVE_STEREO
#include "stdlib/tabletop/perception/stereo/scene_from_stereo.h"
#endif

namespace ksmc::stdlib::tabletop::kit {

namespace cli = ksmc::runtime::cli;
namespace rd = ksmc::runtime::domain;
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

void check_binding(const blocks::Binding& b) {
  const std::string where = b.source.empty() ? std::string("tabletop kit") : b.source;
  if (!b.mln.program) throw rd::ConfigError(where + ": incomplete Markov logic binding");
  const auto& program = b.mln.program();
  if (b.constant_type < 0 || static_cast<std::size_t>(b.constant_type) >= program.types.size())
    throw rd::ConfigError(where + ": the binding names no constant type of the program");
  if (b.outputs.size() > 1) throw rd::ConfigError(where + ": the tabletop kit reports one scene.decisions output");
  for (const auto& out : b.outputs)
    for (const std::int32_t p : {out.false_est, out.hidden}) {
      if (p < 0 || static_cast<std::size_t>(p) >= program.predicates.size())
        throw rd::ConfigError(where + ": scene.decisions names no predicate of the program");
      const auto& pred = program.predicates[static_cast<std::size_t>(p)];
      if (!pred.query || pred.arg_types.size() != 1 || pred.arg_types[0] != b.constant_type)
        throw rd::ConfigError(fmt::format("{}: scene.decisions: '{}' must be a unary query over the scene's constants",
                                          where, pred.name));
    }
  if (b.kernels.empty()) throw rd::ConfigError(where + ": the tabletop kit needs at least one kernel");
  for (const auto& k : b.kernels) {  // throws for what it cannot run
    if (k.move == blocks::Move::fit) FitKernel check(k, b.likelihood.estimate_sigma_t, b.likelihood.estimate_sigma_r);
    else RefineKernel check(k, true);
  }
}

// --cloud: the point-cloud front end (docs/perception.md). The boxes it found are written
// with the run's other outputs as OUT/scene.json (`scene_json`).
Scene load_cloud_input(const cli::DomainInput& in, const blocks::Binding& binding, std::string& scene_json) {
#ifdef KSMC_HAVE_PERCEPTION
  perception::CloudOptions options;
  try {
    options.units = perception::parse_units(in.flags.text("cloud-units"));
  } catch (const std::invalid_argument& e) {
    throw cli::UsageError(std::string("--cloud-units: ") + e.what());
  }
  const std::string file = in.flags.text("cloud");
  std::size_t missing = 0;
  const perception::Points points = perception::load_cloud(file, options.units, &missing);
  if (missing > 0)
    std::cerr << fmt::format("tabletop: warning: {}: {} missing returns left out (points at (0, 0, 0), or NaN in an organised PCD)\n",
                             file, missing);
  cli::check_work(cloud_estimate(file, points.size(), in), in);  // large clouds: cost up front
  options.stage = [&in](std::string_view what) { cli::stage(in, what); };
  perception::CloudScene cs = perception::scene_from_points(points, file, options);
  scene_json = perception::scene_json_text(cs.scene);
  // What the front end saw stays with the scene for `cloud.surface`: each box's points and,
  // when the domain prices free space, the cloud's rays (table frame).
  if (const auto& term = binding.likelihood.cloud) {
    auto seen = std::make_shared<CloudObservation>();
    seen->object_points = std::move(cs.object_points);
    seen->sensor = cs.sensor_in_table;  // inside a box, no point is measured to the face it stands on
    if (term->voxel > 0.0)  // one point per voxel: the likelihood's independent observations
      for (perception::Points& own : seen->object_points) own = perception::voxel_subsample(own, term->voxel);
    if (term->free_space_cost > 0.0) {
      cli::stage(in, fmt::format("indexing {} rays for the free-space term", cs.cloud_in_table.size()));
      FreeSpace rays;
      rays.points = std::move(cs.cloud_in_table);
      rays.sensor = cs.sensor_in_table;
      seen->rays = RayIndex(std::move(rays));
    }
    cs.scene.cloud = std::move(seen);
  }
  return std::move(cs.scene);
#else
  (void)in;
  (void)binding;
  (void)scene_json;
  throw cli::UsageError("--cloud: this tabletop was built without PCL");
#endif
}

// --stereo LEFT RIGHT --calib stereo.yaml --db DIR: the stereo front end (seed Alg. 2,
// docs/perception_stereo.md). The objects found, with their keypoints, are written as OUT/scene.json.
Scene load_stereo_input(const cli::DomainInput& in, std::string& scene_json) {
  const std::vector<std::string> pair = in.flags.words("stereo");
  if (pair.size() != 2) throw cli::UsageError("--stereo: expected LEFT RIGHT (two image files)");
  if (!in.flags.given("calib") || !in.flags.given("db")) throw cli::UsageError("--stereo needs --calib FILE and --db DIR");
#if defined(KSMC_HAVE_STEREO) && defined(KSMC_HAVE_PERCEPTION)
  namespace st = perception::stereo;
  st::StereoScene ss = st::scene_from_stereo(pair[0], pair[1], in.flags.text("calib"), in.flags.text("db"));
  scene_json = perception::scene_json_text(ss.scene);
  return std::move(ss.scene);
#else
  (void)scene_json;
  throw cli::UsageError("--stereo: this tabletop was built without the stereo front end (OpenCV features2d)");
#endif
}

TabletopResult result_of(const TabletopModel& model) {
  TabletopResult r;
  r.scene = model.scene();
  r.evidence = extract_evidence(r.scene, model.block_scene().relation_params());
  const auto& outputs = model.binding().outputs;
  if (!outputs.empty()) {
    const blocks::Decisions& d = outputs.front();
    for (std::size_t i = 0; i < r.scene.objects.size(); ++i) {
      const std::int32_t c = blocks::Scene::body_of_object(i);
      const std::span<const std::int32_t> args(&c, 1);
      r.probabilities.push_back(
          {model.semantics().value(model.outcome(), d.false_est, args), model.semantics().value(model.outcome(), d.hidden, args)});
    }
  }
  return r;
}

namespace {

nlohmann::json scene_graph_with_queries(const TabletopModel& model, const TabletopResult& result) {
  nlohmann::json j = scene_graph_json(result);
  j["queries"] = nlohmann::json(model.semantics().queries_json(model.outcome(), model.block_scene().names()));
  return j;
}

}  // namespace

nlohmann::json scene_graph_of(const TabletopModel& model) { return scene_graph_with_queries(model, result_of(model)); }

std::string evidence_db_of(const TabletopModel& model) {
  const std::vector<std::string> names = model.block_scene().names();
  for (const auto& id : names) {
    const bool ok = !id.empty() && std::all_of(id.begin(), id.end(), [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
    });
    if (!ok)
      throw std::invalid_argument(fmt::format("--evidence-out: object id \"{}\" is not a valid .db constant "
                                              "(letters, digits, '_', '-', '.')", id));
  }
  return model.semantics().evidence_db(model.outcome(), names);
}

namespace {

void write_outputs(const rm::RunResult&, rm::Model& best, cli::OutputDir& out) {
  const auto& model = static_cast<const TabletopModel&>(best);
  const TabletopResult result = result_of(model);
  out.write("scene_graph.json", scene_graph_with_queries(model, result).dump(2) + "\n");
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

KitSetup make_setup(const blocks::Binding& binding, std::shared_ptr<const Scene> scene, KitOptions options) {
  check_binding(binding);
  KitSetup k;
  k.scene = scene;
  const blocks::Binding* b = &binding;
  k.setup.model_factory = [b, scene, options](unsigned) -> std::unique_ptr<rm::Model> {
    return std::make_unique<TabletopModel>(scene, *b, options);
  };
  const double estimate_sigma_t = options.pose_sigma_t.value_or(binding.likelihood.estimate_sigma_t);
  const double estimate_sigma_r = options.pose_sigma_r.value_or(binding.likelihood.estimate_sigma_r);
  rd::KernelTable table = rd::make_kernels(binding.kernels, binding.schedule, [&](const auto& decl) {
    if (decl.move == blocks::Move::fit)
      return std::shared_ptr<const rm::Kernel>(std::make_shared<const FitKernel>(decl, estimate_sigma_t, estimate_sigma_r));
    return std::shared_ptr<const rm::Kernel>(std::make_shared<const RefineKernel>(decl, options.current_competes));
  });
  k.setup.kernels = std::move(table.kernels);
  k.setup.schedule = std::move(table.schedule);
  k.setup.write_results = write_outputs;
  k.setup.evidence_db = [](rm::Model& best) { return evidence_db_of(static_cast<const TabletopModel&>(best)); };
  nlohmann::json extractors = nlohmann::json::array();
  for (const auto& e : binding.extractors) extractors.push_back(e.text);
  k.setup.summary_extra = {{"objects", scene->objects.size()},
                           {"extractors", std::move(extractors)},
                           {"likelihood", nlohmann::json::object()}};
  nlohmann::json& likelihood = k.setup.summary_extra["likelihood"];
  if (binding.likelihood.keypoint_term)
    likelihood.update({{"sigma_px", binding.likelihood.sigma_px},
                       {"robust", binding.likelihood.robust},
                       {"outlier_px", binding.likelihood.outlier_px},
                       {"sigma_from_scene", binding.likelihood.sigma_from_scene}});
  if (const auto& c = binding.likelihood.cloud) {
    likelihood["cloud"] = {{"sigma_m", c->sigma},
                           {"robust", c->robust},
                           {"outlier_m", c->outlier},
                           {"free_space_cost", c->free_space_cost},
                           {"inside_sigma_m", c->inside_sigma},
                           {"voxel_m", c->voxel},
                           {"scene_has_cloud", scene->cloud != nullptr}};
    if (scene->cloud != nullptr) {
      std::size_t scored = 0;
      for (const auto& own : scene->cloud->object_points) scored += own.size();
      likelihood["cloud"]["points_scored"] = scored;
    }
  }
  if (binding.likelihood.keypoint_term && binding.likelihood.sigma_from_scene) {  // what this scene is scored with
    const blocks::KeypointGaussian used = scene_likelihood(*scene, binding.likelihood);
    k.setup.summary_extra["likelihood"]["scene_sigma_px"] = used.sigma_px;
    k.setup.summary_extra["likelihood"]["scene_outlier_px"] = used.outlier_px;
  }
  return k;
}

cli::DomainSpec domain_spec(const blocks::Binding& binding) {
  cli::DomainSpec spec;
  spec.name = binding.domain;
  spec.version = "1.0.0";
  spec.description = "table-top scene graph from 6D pose estimates (knowledge-supervised DDMCMC)";
  spec.inputs_help = "scene.json";
  spec.default_iterations = 2000;
  spec.flags = {{"input-format", "input format: scene (scene.json) or hope (HOPE meta_data.json)", "scene",
                 cli::DomainFlag::Kind::text},
                {"cloud", "point cloud (.ply/.pcd) instead of scene.json: table and boxes found, OUT/scene.json written",
                 "", cli::DomainFlag::Kind::path},
                {"cloud-units", "units of the --cloud coordinates: m, cm or mm", "m", cli::DomainFlag::Kind::text},
                {"stereo", "stereo pair LEFT RIGHT instead of scene.json (with --calib, --db): objects found, OUT/scene.json written",
                 "", cli::DomainFlag::Kind::text, false, 2},
                {"calib", "stereo rig calibration (stereo.yaml) for --stereo", "", cli::DomainFlag::Kind::path},
                {"db", "object database folder for --stereo", "", cli::DomainFlag::Kind::path}};
  spec.min_inputs = 0;
  const blocks::Binding* b = &binding;
  // The binding is checked by make_setup inside `load`, where the CLI reports a ConfigError.
  spec.load = [b](const cli::DomainInput& in) {
    std::vector<std::string> warnings;
    const bool cloud = in.flags.given("cloud"), stereo = in.flags.given("stereo");
    if (cloud && stereo) throw cli::UsageError("--cloud and --stereo exclude each other");
    if (in.inputs.size() != (cloud || stereo ? 0u : 1u))
      throw cli::UsageError(cloud ? "--cloud replaces the scene.json input"
                                  : stereo ? "--stereo replaces the scene.json input" : "expected one scene.json input");
    std::string scene_json;
    auto scene = std::make_shared<const Scene>(
        cloud    ? load_cloud_input(in, *b, scene_json)
        : stereo ? load_stereo_input(in, scene_json)
                 : load_input(in.inputs.at(0), in.flags.text("input-format"), warnings));
    for (const auto& w : warnings) std::cerr << "tabletop: warning: " << w << "\n";
    const std::vector<std::string> pair = stereo ? in.flags.words("stereo") : std::vector<std::string>{};  // LEFT RIGHT
    const std::string left = stereo ? pair.at(0) : std::string();
    // (The cloud front end checked its estimate before reading the points.)
    if (!cloud) cli::check_work(scene_estimate(stereo ? left : in.inputs.at(0).string(), scene->objects.size(), in), in);
    cli::stage(in, fmt::format("preparing the model of {} objects", scene->objects.size()));
    KitSetup k = make_setup(*b, scene);
    if (!scene->image.empty()) k.setup.extra_inputs.push_back(scene->image);
    if (stereo) {
      k.setup.extra_inputs.push_back(pair.at(0));
      k.setup.extra_inputs.push_back(pair.at(1));
      k.setup.extra_inputs.push_back(in.flags.text("calib"));
    }
    if (cloud || stereo) {
      if (cloud) k.setup.extra_inputs.push_back(in.flags.text("cloud"));
      k.setup.write_results = [write = std::move(k.setup.write_results), scene_json](
                                  const rm::RunResult& run, rm::Model& best, cli::OutputDir& out) {
        out.write("scene.json", scene_json);
        write(run, best, out);
      };
    }
    return std::move(k.setup);
  };
  return spec;
}

}  // namespace ksmc::stdlib::tabletop::kit
