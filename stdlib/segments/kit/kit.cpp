#include "stdlib/segments/kit/kit.h"

#include <cstdio>
#include <memory>
#include <utility>
#include <vector>

#include "runtime/domain/kernels.h"
#include "runtime/io/cancel.h"
#include "stdlib/segments/cloud.h"
#include "stdlib/segments/kit/kernels.h"
#include "stdlib/segments/kit/output.h"
#include "stdlib/segments/kit/segments_model.h"

namespace ksmc::stdlib::segments::kit {

namespace cli = runtime::cli;
namespace dom = runtime::domain;
namespace mcmc = runtime::mcmc;

namespace {

using CandidateSet = std::shared_ptr<const std::vector<Candidate>>;

cli::DomainSetup load(const blocks::Binding& binding, const cli::DomainInput& in) {
  auto shared = std::make_shared<SharedInput>();
  shared->binding = &binding;
  shared->params = model_params(binding);
  const std::filesystem::path path = in.inputs.at(0);
  shared->points = std::make_shared<const std::vector<Vec2>>(load_points(path));
  runtime::io::throw_if_cancelled("segments: after reading the points");
  // Large clouds say their cost up front (issue 16: 1 M points took about 13 min at the
  // default iterations; the likelihood and RANSAC scale with the points).
  if (const std::size_t n = shared->points->size(); n > 100000) {
    std::fprintf(stderr, "segments: %zu points: expect about %.0f min at the default iterations\n", n,
                 13.0 * static_cast<double>(n) / 1e6);
  }
  const long long max_lines = in.flags.integer("max-segments");
  if (max_lines < 1 || max_lines > 10000) throw cli::UsageError("--max-segments must be in [1, 10000]");
  shared->max_lines = static_cast<std::size_t>(max_lines);

  // Birth candidates once per distinct detect.ransac parameter set (seeded by the run seed).
  std::vector<std::pair<RansacParams, CandidateSet>> detected;
  bool explain_set = false;
  auto data_of = [&](const dom::KernelDecl<blocks::Move, blocks::Source>& decl) {
    KernelData d;
    d.params = kernel_params(decl);
    if (d.params.move == blocks::Move::birth || d.params.move == blocks::Move::death) {
      if (!explain_set) shared->explain = d.params.death.explain;
      explain_set = true;
      CandidateSet found;
      for (const auto& [params, set] : detected)
        if (params == d.params.ransac) found = set;
      if (!found) {
        found = std::make_shared<const std::vector<Candidate>>(detect_candidates(*shared->points, d.params.ransac, in.seed));
        detected.emplace_back(d.params.ransac, found);
        shared->candidates += found->size();
      }
      d.candidates = found;
    }
    return d;
  };
  dom::KernelTable table = dom::make_kernels(binding.kernels, binding.schedule, [&](const auto& decl) {
    return std::make_shared<const SegmentKernel>(decl.name, decl.reverse, data_of(decl));
  });

  cli::DomainSetup setup;
  setup.kernels = std::move(table.kernels);
  setup.schedule = std::move(table.schedule);
  std::shared_ptr<const SharedInput> cshared = shared;
  { SegmentsModel check(cshared); }  // the program fits the binding (ConfigError otherwise)
  setup.model_factory = [cshared](unsigned) { return std::make_unique<SegmentsModel>(cshared); };
  const std::string source = path.filename().string();
  setup.write_results = [source](const mcmc::RunResult& run, mcmc::Model& best, cli::OutputDir& out) {
    auto& m = static_cast<SegmentsModel&>(best);
    const nlohmann::ordered_json result = result_json(m, run, source);
    out.write("segments.json", result.dump(2) + "\n");
    const auto png = overlay_png(m, result);
    out.write("overlay.png", std::span<const unsigned char>(png.data(), png.size()));
  };
  setup.evidence_db = [](mcmc::Model& best) {
    const auto& m = static_cast<const SegmentsModel&>(best);
    return m.semantics().evidence_db(*m.outcome(), m.constant_names());
  };
  setup.summary_extra = {{"points", shared->points->size()}, {"candidates", shared->candidates},
                         {"max_segments", shared->max_lines}};
  return setup;
}

}  // namespace

cli::DomainSpec domain_spec(const blocks::Binding& binding) {
  cli::DomainSpec spec;
  spec.name = binding.domain.empty() ? "segments" : binding.domain;
  spec.version = "1.0";
  spec.description = "line segments, corners and walls in a 2D point cloud (x y per line, metres)";
  spec.inputs_help = "POINTS.txt";
  spec.default_iterations = 20000;
  using K = cli::DomainFlag::Kind;
  spec.flags = {{"max-segments", "upper bound on the number of segments (births and splits decline beyond it)", "200", K::integer}};
  spec.load = [&binding](const cli::DomainInput& in) { return load(binding, in); };
  return spec;
}

}  // namespace ksmc::stdlib::segments::kit
