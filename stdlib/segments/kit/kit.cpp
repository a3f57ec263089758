#include "stdlib/segments/kit/kit.h"

#include <memory>

#include "runtime/mcmc/schedule.h"
#include "stdlib/segments/cloud.h"
#include "stdlib/segments/kit/kernels.h"
#include "stdlib/segments/kit/output.h"
#include "stdlib/segments/kit/segments_model.h"

namespace ksmc::stdlib::segments::kit {

namespace cli = runtime::cli;
namespace dom = runtime::domain;
namespace mcmc = runtime::mcmc;

namespace {

cli::DomainSetup load(const dom::DomainConfig& config, const dom::MlnBinding& binding, const cli::DomainInput& in) {
  auto shared = std::make_shared<SharedInput>();
  shared->settings = read_settings(config);
  shared->binding = binding;
  const std::filesystem::path path = in.inputs.at(0);
  shared->points = std::make_shared<const std::vector<Vec2>>(load_points(path));
  const long long max_lines = in.flags.integer("max-segments");
  if (max_lines < 1 || max_lines > 10000) throw cli::UsageError("--max-segments must be in [1, 10000]");
  shared->max_lines = static_cast<std::size_t>(max_lines);
  shared->candidates = detect_candidates(*shared->points, shared->settings.ransac, in.seed);

  cli::DomainSetup setup;
  std::vector<mcmc::KernelInfo> infos;
  for (const KernelSpec& k : shared->settings.kernels) {
    setup.kernels.push_back(std::make_shared<SegmentKernel>(k.name, k.reverse, k.kind));
    infos.push_back({k.name, k.reverse});
  }
  std::vector<mcmc::ScheduleRow> rows;
  for (const auto& r : shared->settings.schedule) rows.push_back({r.begin, r.end, r.probabilities});
  try {
    setup.schedule = mcmc::Schedule(infos, rows);
  } catch (const mcmc::ScheduleError& e) {
    throw dom::ConfigError(config.source + ": schedule: " + e.what());
  }
  std::shared_ptr<const SharedInput> cshared = shared;
  { SegmentsModel check(cshared); }  // the knowledge base fits the settings (ConfigError otherwise)
  setup.model_factory = [cshared](unsigned) { return std::make_unique<SegmentsModel>(cshared); };
  const std::string source = path.filename().string();
  setup.write_results = [source](const mcmc::RunResult& run, mcmc::Model& best, cli::OutputDir& out) {
    auto& m = static_cast<SegmentsModel&>(best);
    const nlohmann::json result = result_json(m, run, source);
    out.write("segments.json", result.dump(2) + "\n");
    const auto png = overlay_png(m, result);
    out.write("overlay.png", std::span<const unsigned char>(png.data(), png.size()));
  };
  setup.summary_extra = {{"points", shared->points->size()}, {"candidates", shared->candidates.size()},
                         {"max_segments", shared->max_lines}};
  return setup;
}

}  // namespace

cli::DomainSpec domain_spec(const dom::DomainConfig& config, const dom::MlnBinding& binding) {
  (void)read_settings(config);
  cli::DomainSpec spec;
  spec.name = config.domain.empty() ? "segments" : config.domain;
  spec.version = "1.0";
  spec.description = "line segments, corners and walls in a 2D point cloud (x y per line, metres)";
  spec.inputs_help = "POINTS.txt";
  spec.default_iterations = 20000;
  using K = cli::DomainFlag::Kind;
  spec.flags = {{"max-segments", "upper bound on the number of segments (BIRTH and SPLIT decline beyond it)", "200", K::integer}};
  spec.load = [config, binding](const cli::DomainInput& in) { return load(config, binding, in); };
  return spec;
}

}  // namespace ksmc::stdlib::segments::kit
