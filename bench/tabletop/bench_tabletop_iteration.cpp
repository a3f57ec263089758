// bench_tabletop_iteration: time per DDMCMC iteration of the table-top kit (the kernels and
// schedule of domains/tabletop.ksm: refine with n = 20 candidates and the pose.fit mixture,
// incremental evidence, MLN lookup / re-run, MH accept/reject) on
// physics-generated scenes of 5, 10 and 20 boxes, and the share of it spent in Markov
// logic (evidence hashing, cache lookups, grounding + inference of new evidence).
// Each run starts from a fresh model (cold MLN cache). Median of 7 runs. "kept" is the share
// of iterations whose move declined (refine: the current pose had the best weight);
// "us/MLN run" is one uncached evaluation of the scene's input (full extraction,
// grounding, exact marginals and log Z, exact MAP), median of 7 fresh models: the cost an
// iteration pays on top when its evidence is new.
//
//   bench_tabletop_iteration [iterations per run, default 2000]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "runtime/mcmc/rng.h"
#include "stdlib/tabletop/kit/domain_spec.h"
#include "stdlib/tabletop/kit/tabletop_model.h"
#include "stdlib/tabletop/scene_io.h"
#include "tools/tabletop_sim/generator.h"
#include "tools/tabletop_sim/scene_writer.h"
#include "tests/tabletop_kit/binding_fixture.h"

namespace kit = ksmc::stdlib::tabletop::kit;
namespace tt = ksmc::stdlib::tabletop;
namespace sim = ksmc::tools::tabletop_sim;
namespace rm = ksmc::runtime::mcmc;

namespace {

struct RunStats {
  double us_per_iter = 0.0;
  double mln_share = 0.0;
  double mln_runs_per_1k = 0.0;
  double acceptance = 0.0;
  double kept = 0.0;
};

double cold_mln_us(const std::shared_ptr<const tt::Scene>& scene) {
  std::vector<double> us;
  for (int r = 0; r < 7; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    const kit::TabletopModel fresh(scene, ksmc::tests::tabletop_kit::ksm_binding());  // extraction + one run
    us.push_back(1e6 * std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    if (!std::isfinite(fresh.log_prior())) std::cerr << "bench_tabletop_iteration: impossible input evidence\n";
  }
  std::sort(us.begin(), us.end());
  return us[us.size() / 2];
}

RunStats run_once(const std::shared_ptr<const tt::Scene>& scene, long iterations, std::uint64_t seed) {
  const auto& binding = ksmc::tests::tabletop_kit::ksm_binding();
  kit::TabletopModel model(scene, binding);
  const kit::KitSetup setup = kit::make_setup(binding, scene);
  const rm::Schedule& schedule = setup.setup.schedule;
  rm::Rng rng(seed);
  const auto before = model.semantics().core().stats();
  long accepted = 0, kept = 0;
  const auto t0 = std::chrono::steady_clock::now();
  double lp = model.log_posterior();
  for (long it = 0; it < iterations; ++it) {
    const std::size_t row = schedule.row_index(static_cast<std::uint64_t>(it));
    const std::size_t k = schedule.pick(row, rng);
    const rm::Proposal p = setup.setup.kernels.at(k)->propose(model, rng);
    if (p.was_declined()) {
      ++kept;
      continue;
    }
    const double lp_new = model.log_posterior();
    const double log_a = lp_new - lp + p.log_q_bwd - p.log_q_fwd + schedule.log_selection_ratio(row, k);
    if (std::log(rng.uniform_pos()) < log_a) {
      model.accept();
      lp = lp_new;
      ++accepted;
    } else {
      model.reject();
    }
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto after = model.semantics().core().stats();
  RunStats s;
  s.us_per_iter = 1e6 * secs / static_cast<double>(iterations);
  s.mln_share = (after.inference_seconds - before.inference_seconds) / secs;
  s.mln_runs_per_1k = 1000.0 * static_cast<double>(after.inferences - before.inferences) / static_cast<double>(iterations);
  s.acceptance = static_cast<double>(accepted) / static_cast<double>(iterations);
  s.kept = static_cast<double>(kept) / static_cast<double>(iterations);
  return s;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

}  // namespace

int main(int argc, char** argv) {
  long iterations = 2000;
  if (argc > 1) {
    iterations = std::strtol(argv[1], nullptr, 10);
    if (iterations <= 0) {
      std::cerr << "bench_tabletop_iteration: iterations must be a positive integer\n";
      return 2;
    }
  }
  constexpr int kRuns = 7;
  std::cout << fmt::format("table-top kit, domains/tabletop.ksm kernels and schedule, {} iterations per run, median of {} runs\n",
                           iterations, kRuns);
  std::cout << "| boxes | objects | us/iteration | MLN share | MLN runs /1k it | acceptance | kept | us/MLN run |\n"
               "|------:|--------:|-------------:|----------:|----------------:|-----------:|-----:|-----------:|\n";
  for (const int n : {5, 10, 20}) {
    sim::GeneratorOptions opt;
    opt.min_objects = opt.max_objects = n;
    const auto g = sim::generate_scene(sim::scene_seed(77, static_cast<std::uint64_t>(n)), opt);
    auto load = tt::parse_scene(nlohmann::json::parse(sim::scene_json(g)), "bench_scene.json", ".");
    const auto scene = std::make_shared<const tt::Scene>(std::move(load.scene));
    std::vector<double> us, share, runs, acc, kept;
    for (int r = 0; r < kRuns; ++r) {
      const RunStats s = run_once(scene, iterations, 1 + static_cast<std::uint64_t>(r));
      us.push_back(s.us_per_iter);
      share.push_back(s.mln_share);
      runs.push_back(s.mln_runs_per_1k);
      acc.push_back(s.acceptance);
      kept.push_back(s.kept);
    }
    std::cout << fmt::format("| {:>5} | {:>7} | {:>12.1f} | {:>8.1f}% | {:>15.1f} | {:>10.3f} | {:>4.2f} | {:>10.0f} |\n",
                             n, scene->objects.size(), median(us), 100.0 * median(share), median(runs), median(acc),
                             median(kept), cold_mln_us(scene));
  }
  return 0;
}
