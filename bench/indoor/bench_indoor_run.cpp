// End-to-end indoor sampler throughput through the kit (IndoorModel + kernels + schedule of
// domains/indoor.ksm, the knowledge evaluated with every proposal) on lab_b.png, single thread:
//   bench_indoor_run [iterations] [--long N] [--window W] [--runs R] [--map FILE] [--flag NAME=VALUE ...]
// (--map: another map than lab_b.png, e.g. a Bormann map; bench/indoor/plateau_maps.sh runs
// the plateau on each of the 20.)
// 1. Iterations per second: median of R runs (default 5) of `iterations` (default 10000), seeds 1-R.
// 2. Plateau: R runs (seeds 1-R) of at most N iterations (default 200000). The best log
//    posterior is followed every iteration (engine observer) and fed to two PlateauDetectors
//    every 100 iterations: the run is on a plateau from iteration i when
//    best(i + W) - best(i) <= min_gain, W = 5000 by default, with min_gain = 0 (strict) and
//    min_gain = one_cell_gain() (the smallest gain of correcting one cell over the run's tables:
//    ln 8 for Table 3.1; the weakest table of the domain decides).
//    A run stops once both are reached (engine cancel flag). Per run: the plateau iteration i,
//    the wall seconds at i and when it became known (i + W); medians over the R runs.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "runtime/mcmc/engine.h"
#include "runtime/mcmc/plateau.h"
#include "stdlib/indoor/kit/indoor_model.h"
#include "tests/indoor_kit/kit_fixture.h"

namespace mcmc = ksmc::runtime::mcmc;
namespace kit = ksmc::stdlib::indoor::kit;
using namespace ksmc::tests::indoor_kit;

namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string cell(const std::optional<mcmc::PlateauPoint>& p, bool seconds) {
  if (!p) return "-";
  char buf[64];
  if (seconds) std::snprintf(buf, sizeof buf, "%.2f", p->seconds);
  else std::snprintf(buf, sizeof buf, "%llu", static_cast<unsigned long long>(p->iteration));
  return buf;
}

}  // namespace

int main(int argc, char** argv) {
  std::uint64_t iters = 10000, long_iters = 200000, window = 5000;
  int runs = 5;
  std::filesystem::path map = std::filesystem::path(KSMC_SHARED_DIR) / "data/maps/bormann_ipa/test_maps/lab_b.png";
  std::map<std::string, std::string> flags{{"resolution", "0.05"}};  // kit flags (--flag NAME=VALUE)
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--long" && i + 1 < argc) long_iters = std::stoull(argv[++i]);
    else if (a == "--window" && i + 1 < argc) window = std::stoull(argv[++i]);
    else if (a == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
    else if (a == "--map" && i + 1 < argc) map = argv[++i];
    else if (a == "--flag" && i + 1 < argc && std::string(argv[i + 1]).find('=') != std::string::npos) {
      const std::string f = argv[++i];
      flags[f.substr(0, f.find('='))] = f.substr(f.find('=') + 1);
    }
    else if (!a.empty() && a.find_first_not_of("0123456789") == std::string::npos) iters = std::stoull(a);
    else {
      std::fprintf(stderr, "usage: bench_indoor_run [iterations] [--long N] [--window W] [--runs R] [--map FILE] [--flag NAME=VALUE ...]\n");
      return 2;
    }
  }
  if (window == 0) {
    std::fprintf(stderr, "bench_indoor_run: --window must be at least 1\n");
    return 2;
  }
  if (!std::filesystem::exists(map)) {
    std::printf("bench_indoor_run: %s not found - skipped\n", map.string().c_str());
    return 0;
  }
  const auto sp = spec();
  const auto setup = sp.load(input_for(sp, map, 1, flags));
  const mcmc::Engine engine(setup.model_factory, setup.kernels, setup.schedule);
  std::printf("%s, kit config = domains/indoor.ksm, 1 chain, 1 thread, flags:", map.filename().string().c_str());
  for (const auto& [k, v] : flags) std::printf(" --%s %s", k.c_str(), v.c_str());
  std::printf("\n\n");
  std::printf("| run | iterations | seconds | it/s | K(W,M) | units |\n|---|---|---|---|---|---|\n");
  std::vector<double> ips;
  for (int r = 0; r < runs && iters > 0; ++r) {
    mcmc::EngineConfig cfg;
    cfg.iterations = iters;
    cfg.seed = 1 + static_cast<std::uint64_t>(r);
    cfg.threads = 1;
    const auto res = engine.run(cfg);
    auto best = setup.model_factory(0);
    best->restore(res.best().best_state);
    const auto& m = static_cast<kit::IndoorModel&>(*best);
    ips.push_back(static_cast<double>(res.iterations) / res.seconds);
    std::printf("| %d | %llu | %.3f | %.0f | %.4f | %zu |\n", r + 1, static_cast<unsigned long long>(res.iterations),
                res.seconds, ips.back(), m.scored().cell_prediction_rate(), m.scored().world().units().size());
  }
  std::printf("\nmedian iterations per second: %.0f\n\n", median(ips));
  if (long_iters == 0) return 0;

  // The gain of one corrected cell under the run's own likelihood tables.
  const double one_cell = [&] {
    auto m0 = setup.model_factory(0);
    return ksmc::stdlib::indoor::one_cell_gain(ksmc::stdlib::indoor::LikelihoodModel(
        static_cast<kit::IndoorModel&>(*m0).input().score.tables));
  }();
  std::printf("plateau: best(i + %llu) - best(i) <= min_gain; strict: min_gain = 0; one cell: min_gain = %.3f nats\n"
              "(the smallest log-likelihood gain of correcting one cell); at most %llu iterations per run, best\n"
              "followed every iteration, judged every 100; seconds = wall time at i / when known (i + window)\n\n",
              static_cast<unsigned long long>(window), one_cell, static_cast<unsigned long long>(long_iters));
  std::printf("| run | iterations run | seconds | best log posterior | K(W,M) | one cell: i | s at i | s known | strict: i | s at i | s known |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::vector<double> one_it, one_s, one_known, strict_it, strict_s;
  int strict_missing = 0, one_missing = 0;
  for (int r = 0; r < runs; ++r) {
    mcmc::PlateauDetector strict({window, 0.0}), loose({window, one_cell});
    std::atomic<bool> stop{false};
    double best = -std::numeric_limits<double>::infinity();
    const auto t0 = std::chrono::steady_clock::now();
    mcmc::EngineConfig cfg;
    cfg.iterations = long_iters;
    cfg.seed = 1 + static_cast<std::uint64_t>(r);
    cfg.threads = 1;
    cfg.cancel = &stop;
    cfg.observer = [&](unsigned, std::uint64_t it, const mcmc::Model& m) {
      best = std::max(best, m.log_posterior());
      if (it % 100 != 0) return;
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const bool a = strict.observe(it, best, s);
      const bool b = loose.observe(it, best, s);
      if (a && b) stop.store(true, std::memory_order_relaxed);
    };
    const auto res = engine.run(cfg);
    auto bm = setup.model_factory(0);
    bm->restore(res.best().best_state);
    const auto& m = static_cast<kit::IndoorModel&>(*bm);
    std::printf("| %d | %llu | %.2f | %.1f | %.4f | %s | %s | %s | %s | %s | %s |\n", r + 1,
                static_cast<unsigned long long>(res.iterations), res.seconds, res.best().best_log_posterior,
                m.scored().cell_prediction_rate(), cell(loose.plateau(), false).c_str(), cell(loose.plateau(), true).c_str(),
                cell(loose.detected(), true).c_str(), cell(strict.plateau(), false).c_str(),
                cell(strict.plateau(), true).c_str(), cell(strict.detected(), true).c_str());
    if (loose.reached()) {
      one_it.push_back(static_cast<double>(loose.plateau()->iteration));
      one_s.push_back(loose.plateau()->seconds);
      one_known.push_back(loose.detected()->seconds);
    } else {
      ++one_missing;
    }
    if (strict.reached()) {
      strict_it.push_back(static_cast<double>(strict.plateau()->iteration));
      strict_s.push_back(strict.plateau()->seconds);
    } else {
      ++strict_missing;
    }
  }
  std::printf("\none-cell plateau: reached in %d of %d runs; median iteration %.0f, median wall time %.2f s "
              "(known after %.2f s)\n",
              runs - one_missing, runs, median(one_it), median(one_s), median(one_known));
  std::printf("strict plateau: reached in %d of %d runs; median iteration %.0f, median wall time %.2f s\n", runs - strict_missing, runs,
              median(strict_it), median(strict_s));
  std::printf("(medians over the runs that reached it)\n");
  return 0;
}
