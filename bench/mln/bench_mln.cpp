// bench_mln: time per inference on table-top scenes (seed Table 4.3 KB) of 7, 20 and
// 100 objects, for grounding+folding and each engine; median of several runs, and
// the max marginal error against exact inference.
//
// usage: bench_mln [runs=7]
#include <algorithm>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "runtime/mln/exact.h"
#include "runtime/mln/gibbs.h"
#include "runtime/mln/grounder.h"
#include "runtime/mln/inference.h"
#include "runtime/mln/log_z.h"
#include "runtime/mln/maxwalksat.h"
#include "runtime/mln/mcsat.h"
#include "tests/mln/tabletop_kb.h"

using namespace ksmc::runtime::mln;

namespace {

// Thread CPU time in microseconds (the machine is shared: wall time would include
// other processes' load).
double cpu_us() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e6 + static_cast<double>(ts.tv_nsec) * 1e-3;
}

// Median over `runs` of the mean CPU time (µs) of `fn`, each run repeated until >= 5 ms.
double median_us(int runs, const std::function<void()>& fn) {
  std::vector<double> t;
  for (int r = 0; r < runs; ++r) {
    int reps = 0;
    const double start = cpu_us();
    double elapsed = 0.0;
    do {
      fn();
      ++reps;
      elapsed = cpu_us() - start;
    } while (elapsed < 5000.0);
    t.push_back(elapsed / reps);
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

// Keeps a result alive so the optimiser cannot drop the work that produced it.
template <typename T>
void keep(const T& x) {
  asm volatile("" : : "g"(&x) : "memory");
}

double max_error(const std::vector<double>& a, const std::vector<double>& b) {
  double e = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) e = std::max(e, std::abs(a[i] - b[i]));
  return e;
}

}  // namespace

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::max(5, std::atoi(argv[1])) : 7;
  ksmc::tests::mln::TabletopKb kb;
  std::printf("bench_mln: table-top KB (16 rules), median of %d runs, CPU time per call in microseconds\n", runs);
  std::printf("%-8s %5s %6s %-34s %12s %10s\n", "objects", "atoms", "clauses", "step", "time_us", "max_err");
  for (const char* name : {"scene7.db", "scene20.db", "scene100.db"}) {
    const std::string path = std::string(KSMC_SOURCE_DIR) + "/tests/mln/data/" + name;
    const auto text = read_text_file(path);
    Domain domain;
    collect_db_constants(text, path, kb.program, domain);
    Evidence ev(kb.program, domain);
    parse_db(text, path, kb.program, domain, ev);
    const int objects = domain.size(kb.object) - 1;
    const auto g = ground(kb.program, domain, ev);
    const auto& net = g.network;
    const auto exact = exact_inference(net);
    auto row = [&](const std::string& step, double us, double err) {
      if (err < 0) std::printf("%-8d %5d %6d %-34s %12.2f %10s\n", objects, net.num_atoms(), net.num_clauses(),
                               step.c_str(), us, "-");
      else std::printf("%-8d %5d %6d %-34s %12.2f %10.4f\n", objects, net.num_atoms(), net.num_clauses(),
                       step.c_str(), us, err);
    };
    row("parse .db", median_us(runs, [&] {
          Evidence e(kb.program, domain);
          parse_db(text, path, kb.program, domain, e);
        }), -1);
    row("ground+fold", median_us(runs, [&] { keep(ground(kb.program, domain, ev)); }), -1);
    row("exact (marginals + log Z)", median_us(runs, [&] { keep(exact_inference(net)); }), 0.0);
    row("exact MAP", median_us(runs, [&] { keep(exact_map(net)); }), -1);
    for (std::int64_t sweeps : {100, 1000, 10000}) {
      GibbsOptions go;
      go.burn_in = 10;
      go.samples = sweeps;
      const double err = max_error(gibbs_sampling(net, go).marginals, exact.marginals);
      row("gibbs " + std::to_string(sweeps) + " sweeps", median_us(runs, [&] { keep(gibbs_sampling(net, go)); }),
          err);
    }
    for (std::int64_t samples : {100, 1000, 10000}) {
      McSatOptions mo;
      mo.burn_in = 10;
      mo.samples = samples;
      const double err = max_error(mc_sat(net, mo).marginals, exact.marginals);
      row("mcsat " + std::to_string(samples) + " samples", median_us(runs, [&] { keep(mc_sat(net, mo)); }), err);
    }
    MapOptions mapo;
    const auto mode = exact_map(net);
    const auto map = max_walksat(net, mapo);
    std::printf("%-8d %5d %6d %-34s %12.2f %10s\n", objects, net.num_atoms(), net.num_clauses(), "map (maxwalksat)",
                median_us(runs, [&] { keep(max_walksat(net, mapo)); }),
                std::abs(map.log_weight - mode.log_weight) < 1e-9 ? "=mode" : "!=mode");
    LogZOptions lzo;
    lzo.force_ais = true;
    lzo.chains = 16;
    lzo.temperatures = 100;
    const auto lz = log_partition(net, lzo);
    row("log Z by AIS (16 chains x 100 T)", median_us(runs, [&] { keep(log_partition(net, lzo)); }),
        std::abs(lz.log_z - exact.log_z));
  }
  std::printf("max_err: max |marginal - exact| over atoms (for log Z: |estimate - exact|)\n");
  return 0;
}
