// End-to-end indoor sampler throughput through the kit (IndoorModel + kernels + schedule of
// domains/indoor.ksm, semantic refreshes included) on lab_b.png, single thread:
//   bench_indoor_run [iterations] [--long N]
// Prints iterations per second (median of 5 runs of `iterations`, default 10000) and, from
// one run of N iterations (default 60000, trace every 100), the iteration and wall time after
// which the best log posterior gains nothing more over 5,000 iterations.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "runtime/mcmc/engine.h"
#include "stdlib/indoor/kit/indoor_model.h"
#include "tests/indoor_kit/kit_fixture.h"

namespace mcmc = ksmc::runtime::mcmc;
using namespace ksmc::tests::indoor_kit;

int main(int argc, char** argv) {
  std::uint64_t iters = 10000, long_iters = 60000;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--long" && i + 1 < argc) long_iters = std::stoull(argv[++i]);
    else if (!a.empty() && a.find_first_not_of("0123456789") == std::string::npos) iters = std::stoull(a);
    else {
      std::fprintf(stderr, "usage: bench_indoor_run [iterations] [--long N]\n");
      return 2;
    }
  }
  const std::filesystem::path map = std::filesystem::path(KSMC_SHARED_DIR) / "data/maps/bormann_ipa/test_maps/lab_b.png";
  if (!std::filesystem::exists(map)) {
    std::printf("bench_indoor_run: %s not found - skipped\n", map.string().c_str());
    return 0;
  }
  const auto sp = spec();
  const auto setup = sp.load(input_for(sp, map, 1, {{"resolution", "0.05"}}));
  const mcmc::Engine engine(setup.model_factory, setup.kernels, setup.schedule);
  std::printf("lab_b.png 1237x672, kit config = domains/indoor.ksm, 1 chain, 1 thread\n\n");
  std::printf("| run | iterations | seconds | it/s | K(W,M) | units |\n|---|---|---|---|---|---|\n");
  std::vector<double> ips;
  for (int r = 0; r < 5; ++r) {
    mcmc::EngineConfig cfg;
    cfg.iterations = iters;
    cfg.seed = 1 + static_cast<std::uint64_t>(r);
    cfg.threads = 1;
    const auto res = engine.run(cfg);
    auto best = setup.model_factory(0);
    best->restore(res.best().best_state);
    const auto& m = static_cast<ksmc::stdlib::indoor::kit::IndoorModel&>(*best);
    ips.push_back(static_cast<double>(res.iterations) / res.seconds);
    std::printf("| %d | %llu | %.3f | %.0f | %.4f | %zu |\n", r + 1, static_cast<unsigned long long>(res.iterations),
                res.seconds, ips.back(), m.scored().cell_prediction_rate(), m.scored().world().units().size());
  }
  std::sort(ips.begin(), ips.end());
  std::printf("\nmedian iterations per second: %.0f\n\n", ips[ips.size() / 2]);

  mcmc::EngineConfig cfg;
  cfg.iterations = long_iters;
  cfg.seed = 1;
  cfg.threads = 1;
  cfg.trace_every = 100;
  const auto res = engine.run(cfg);
  const auto& tr = res.best().trace;
  std::uint64_t plateau = res.iterations;
  for (std::size_t i = 0; i < tr.size(); ++i) {
    std::size_t j = i;
    while (j + 1 < tr.size() && tr[j + 1].iteration <= tr[i].iteration + 5000) ++j;
    if (tr[j].iteration < tr[i].iteration + 5000) break;  // not enough trace left to judge
    if (!(tr[j].best_log_posterior > tr[i].best_log_posterior)) {
      plateau = tr[i].iteration;
      break;
    }
  }
  const double secs = res.seconds * static_cast<double>(plateau) / static_cast<double>(res.iterations);
  std::printf("long run: %llu iterations in %.2f s; best log posterior %.1f at iteration %llu\n",
              static_cast<unsigned long long>(res.iterations), res.seconds, res.best().best_log_posterior,
              static_cast<unsigned long long>(res.best().best_iteration));
  std::printf("no gain over 5000 iterations from iteration %llu: wall time %.2f s\n",
              static_cast<unsigned long long>(plateau), secs);
  return 0;
}
