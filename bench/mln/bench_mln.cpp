// bench_mln: time per inference on table-top scenes (the knowledge base of
// domains/tabletop.ksm, grounded by the code `ksmc emit` generates from it) of 7, 20 and
// 100 objects, for grounding+folding and each engine, and on the indoor knowledge base
// (domains/indoor.ksm) with 20 units; median of several runs, and the max marginal error
// against exact inference. Then the indoor knowledge base on 60-unit floor plans
// (tests/mln/floor_plan.h): exact inference by variable elimination, exact MAP by
// max-product, and incremental re-inference after one unit moved.
//
// usage: bench_mln [runs=7] [tabletop|indoor|wing60|grid]  (a section name runs only that section)
#include <algorithm>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "runtime/mln/error.h"
#include "runtime/mln/exact.h"
#include "runtime/mln/components.h"
#include "runtime/mln/elimination.h"
#include "runtime/mln/gibbs.h"
#include "runtime/mln/grounder.h"
#include "runtime/mln/incremental.h"
#include "runtime/mln/inference.h"
#include "runtime/mln/log_z.h"
#include "runtime/mln/maxwalksat.h"
#include "runtime/mln/mcsat.h"
#include "indoor_factors.h"
#include "tabletop_factors.h"
#include "tests/mln/floor_plan.h"

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

// The indoor knowledge base on 20 units: a corridor (unit 0) with doors to 19 rooms along
// it, rooms next to each other adjacent too; a few rooms look like halls.
void bench_indoor(int runs) {
  namespace indoor = ksmc_generated::indoor;
  const Program& program = indoor::program();
  Domain domain = indoor::make_domain();
  constexpr int kUnits = 20;
  for (int u = 0; u < kUnits; ++u) domain.add(indoor::kType_unit, "U" + std::to_string(u));
  Evidence ev(program, domain);
  auto set1 = [&](std::int32_t p, std::int32_t a, bool v) { std::int32_t args[1] = {a}; ev.set(p, args, v); };
  auto set2 = [&](std::int32_t p, std::int32_t a, std::int32_t b, bool v) {
    std::int32_t args[2] = {a, b};
    ev.set(p, args, v);
  };
  for (int u = 0; u < kUnits; ++u) {
    set1(indoor::kPred_CoLi, u, u == 0);
    set1(indoor::kPred_HaLi, u, u % 7 == 3);
    set1(indoor::kPred_RoLi, u, u != 0 && u % 7 != 3);
    set1(indoor::kPred_MulDoor, u, u == 0 || u % 5 == 0);
    for (int v = 0; v < kUnits; ++v) {
      const bool adj = u != v && (u == 0 || v == 0 || std::abs(u - v) == 1);
      set2(indoor::kPred_Adj, u, v, adj);
    }
  }
  const auto g = indoor::ground(domain, ev);
  const auto& net = g.network;
  std::printf("\nbench_mln: indoor KB (DESIGN section 6), %d units, median of %d runs, CPU time per call in microseconds\n",
              kUnits, runs);
  std::printf("%-8s %5s %6s %-34s %12s %10s\n", "units", "atoms", "clauses", "step", "time_us", "max_err");
  const auto reference = exact_inference(net);
  std::printf("exact method: %s\n", reference.method.c_str());
  auto row = [&](const std::string& step, double us, double err) {
    if (err < 0) std::printf("%-8d %5d %6d %-34s %12.2f %10s\n", kUnits, net.num_atoms(), net.num_clauses(), step.c_str(), us, "-");
    else std::printf("%-8d %5d %6d %-34s %12.2f %10.4f\n", kUnits, net.num_atoms(), net.num_clauses(), step.c_str(), us, err);
  };
  row("ground+fold (generated code)", median_us(runs, [&] { keep(indoor::ground(domain, ev)); }), -1);
  try {
    keep(exact_inference(net));
    row("exact (marginals + log Z)", median_us(runs, [&] { keep(exact_inference(net)); }), -1);
  } catch (const MlnError& e) {
    std::printf("%-8d %5d %6d %-34s %12s %10s  (%s)\n", kUnits, net.num_atoms(), net.num_clauses(), "exact", "refused", "-",
                e.what());
  }
  for (std::int64_t sweeps : {100, 1000, 10000}) {
    GibbsOptions go;
    go.burn_in = 10;
    go.samples = sweeps;
    go.seed = 7;
    const double err = max_error(gibbs_sampling(net, go).marginals, reference.marginals);
    row("gibbs " + std::to_string(sweeps) + " sweeps", median_us(runs, [&] { keep(gibbs_sampling(net, go)); }), err);
  }
  for (std::int64_t samples : {100, 1000}) {
    McSatOptions mo;
    mo.burn_in = 10;
    mo.samples = samples;
    const double err = max_error(mc_sat(net, mo).marginals, reference.marginals);
    row("mcsat " + std::to_string(samples) + " samples", median_us(runs, [&] { keep(mc_sat(net, mo)); }), err);
  }
  MapOptions mapo;
  row("map (maxwalksat)", median_us(runs, [&] { keep(max_walksat(net, mapo)); }), -1);
  std::printf("max_err (indoor): max |marginal - exact|\n");
}

// The indoor knowledge base on a floor plan: grounding, exact inference (the auto
// choice: elimination for the plan's component), the elimination plan alone, exact
// MAP, and incremental re-inference after one room's geometry changed (room-like <->
// hall-like, alternately), including its re-grounding.
void bench_plan(int runs, const std::string& name, const ksmc::tests::mln::FloorPlan& plan) {
  namespace indoor = ksmc_generated::indoor;
  const Program& program = indoor::program();
  Domain domain = indoor::make_domain();
  const std::string text = plan.db();
  collect_db_constants(text, name, program, domain);
  Evidence ev(program, domain);
  parse_db(text, name, program, domain, ev);
  const auto g = indoor::ground(domain, ev);
  const auto& net = g.network;
  const auto exact = exact_inference(net);
  std::printf("\n%s: %d units, %zu adjacent pairs, exact method: %s\n", name.c_str(), plan.units,
              plan.adjacent.size(), exact.method.c_str());
  auto row = [&](const std::string& step, double us) {
    std::printf("%-8d %5d %6d %-34s %12.2f\n", plan.units, net.num_atoms(), net.num_clauses(), step.c_str(), us);
  };
  row("ground+fold (generated code)", median_us(runs, [&] { keep(indoor::ground(domain, ev)); }));
  const auto comps = split_components(net);
  std::size_t big = 0;
  for (std::size_t i = 0; i < comps.size(); ++i)
    if (comps[i].atoms.size() > comps[big].atoms.size()) big = i;
  const auto eplan = plan_elimination(net, comps[big]);
  std::printf("largest component: %zu atoms, %zu clauses, %.0f state bits; elimination width %d, %.0f table entries\n",
              comps[big].atoms.size(), comps[big].clauses.size(), component_state_bits(net, comps[big]), eplan.width,
              eplan.total_entries);
  row("min-fill plan (largest component)", median_us(runs, [&] { keep(plan_elimination(net, comps[big])); }));
  row("exact (marginals + log Z)", median_us(runs, [&] { keep(exact_inference(net)); }));
  row("exact MAP (max-product)", median_us(runs, [&] { keep(exact_map(net)); }));
  const auto unit = *domain.find(indoor::kType_unit, "U12");
  IncrementalInference inc(program, domain, ev, {},
                           [](const Domain& d, const Evidence& e) { return indoor::ground(d, e); });
  bool hall = false;
  const double us = median_us(runs, [&] {
    hall = !hall;
    const EvidenceChange moved[] = {{indoor::kPred_RoLi, {unit}, static_cast<std::int8_t>(hall ? 0 : 1)},
                                    {indoor::kPred_HaLi, {unit}, static_cast<std::int8_t>(hall ? 1 : 0)}};
    keep(inc.update(moved));
  });
  row("incremental: one unit moved", us);
  std::printf("incremental: %s (plan reused: %d)\n", inc.result().method.c_str(), inc.stats().plans_reused);
}

// Table-top scenes of 7, 20 and 100 objects (tests/mln/data).
void bench_tabletop(int runs) {
  namespace tabletop = ksmc_generated::tabletop;
  const Program& program = tabletop::program();
  std::printf("bench_mln: table-top KB (16 rules), median of %d runs, CPU time per call in microseconds\n", runs);
  std::printf("%-8s %5s %6s %-34s %12s %10s\n", "objects", "atoms", "clauses", "step", "time_us", "max_err");
  for (const char* name : {"scene7.db", "scene20.db", "scene100.db"}) {
    const std::string path = std::string(KSMC_SOURCE_DIR) + "/tests/mln/data/" + name;
    const auto text = read_text_file(path);
    Domain domain = tabletop::make_domain();
    collect_db_constants(text, path, program, domain);
    Evidence ev(program, domain);
    parse_db(text, path, program, domain, ev);
    const int objects = domain.size(tabletop::kType_object) - 1;
    const auto g = tabletop::ground(domain, ev);
    const auto& net = g.network;
    const auto exact = exact_inference(net);
    auto row = [&](const std::string& step, double us, double err) {
      if (err < 0) std::printf("%-8d %5d %6d %-34s %12.2f %10s\n", objects, net.num_atoms(), net.num_clauses(),
                               step.c_str(), us, "-");
      else std::printf("%-8d %5d %6d %-34s %12.2f %10.4f\n", objects, net.num_atoms(), net.num_clauses(),
                       step.c_str(), us, err);
    };
    row("parse .db", median_us(runs, [&] {
          Evidence e(program, domain);
          parse_db(text, path, program, domain, e);
        }), -1);
    row("ground+fold (generated code)", median_us(runs, [&] { keep(tabletop::ground(domain, ev)); }), -1);
    row("ground+fold (generic grounder)", median_us(runs, [&] { keep(ground(program, domain, ev)); }), -1);
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
}

}  // namespace

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::max(5, std::atoi(argv[1])) : 7;
  const std::string only = argc > 2 ? argv[2] : "";
  if (!only.empty() && only != "tabletop" && only != "indoor" && only != "wing60" && only != "grid") {
    std::fprintf(stderr, "bench_mln: unknown section '%s' (tabletop, indoor, wing60 or grid)\n", only.c_str());
    return 2;
  }
  if (only.empty() || only == "tabletop") bench_tabletop(runs);
  if (only.empty() || only == "indoor") bench_indoor(runs);
  if (only.empty() || only == "wing60")
    bench_plan(runs, "wing60 (corridor with rooms on both sides)", ksmc::tests::mln::wing_plan(60));
  if (only.empty() || only == "grid")
    bench_plan(runs, "grid 6x10 (every unit adjacent to 4 neighbours)", ksmc::tests::mln::grid_plan(6, 10));
  return 0;
}

