// tabletop_family_eval: the per-family table of the table-top kit (issue 12).
//   tabletop_family_eval [--families all|a,b,...] [--scenes N] [--seed S] [--iterations I]
//                        [--binding ksm|seed] [--kinds] [--write-db DIR]
//                        [--pose-sigma-mm T] [--pose-sigma-deg R] [--generator sim|indep] [--verbose]
// --generator indep scores the families of the independent generator (tools/tabletop_indep,
// no code shared with tools/tabletop_sim) instead of tools/tabletop_families; --verbose lists
// its misses (stderr).
// --iterations defaults to the tabletop binary's own default (the kit's domain spec), so the
// table is what a user running `tabletop` with its defaults gets. --pose-sigma-* set the
// pose-estimate term of the likelihood (KitOptions::pose_sigma_t / _r, overriding the domain's keypoints.gaussian estimate_sigma_t / _r; 0 turns it off).
// --write-db writes training worlds for `ksmc learn` (training_db, from either generator) instead of scoring.
// Prints one row per family: false / hidden / support / contact P R F1 and the undecided
// share of the true positives (docs/tabletop_families.md), then the same pooled over the
// families, exact (pooled_line).
#include <charconv>
#include <chrono>
#include <cstdio>
#include <exception>
#include <iostream>
#include <sstream>
#include <string>

#include "tests/tabletop_kit/family_eval.h"
#include "tests/tabletop_kit/indep_eval.h"

using namespace ksmc::tests::tabletop_kit;

namespace {

long number(std::string_view flag, std::string_view text) {
  long v = 0;
  const auto* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (ec != std::errc() || ptr != end || v < 0) throw std::invalid_argument(fmt::format("{}: '{}' is not a count", flag, text));
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    FamilyRun run;
    std::string which = "all", binding_name = "ksm", db_dir, generator = "sim";
    bool kinds = false, iterations_given = false;
    const std::vector<std::string_view> args(argv + 1, argv + argc);
    for (std::size_t i = 0; i < args.size(); ++i) {
      const std::string_view flag = args[i];
      if (flag == "--kinds") {
        kinds = true;
        continue;
      }
      if (flag == "--verbose") {
        run.verbose = true;
        continue;
      }
      if (i + 1 >= args.size()) throw std::invalid_argument(fmt::format("{}: missing value", flag));
      const std::string_view v = args[++i];
      if (flag == "--families") which = v;
      else if (flag == "--scenes") run.scenes = number(flag, v);
      else if (flag == "--seed") run.seed = static_cast<std::uint64_t>(number(flag, v));
      else if (flag == "--iterations") {
        run.iterations = static_cast<std::uint64_t>(number(flag, v));
        iterations_given = true;
      }
      else if (flag == "--binding") binding_name = v;
      else if (flag == "--pose-sigma-mm") run.options.pose_sigma_t = 1e-3 * std::stod(std::string(v));
      else if (flag == "--pose-sigma-deg") run.options.pose_sigma_r = std::stod(std::string(v)) / 57.29577951308232;
      else if (flag == "--write-db") db_dir = v;
      else if (flag == "--generator") generator = v;
      else throw std::invalid_argument(fmt::format("unknown option '{}'", flag));
    }
    if (binding_name != "ksm" && binding_name != "seed") throw std::invalid_argument("--binding: ksm or seed");
    const blk::Binding& binding = binding_name == "ksm" ? ksm_binding() : seed_binding();
    if (generator != "sim" && generator != "indep") throw std::invalid_argument("--generator: sim or indep");
    if (run.verbose && generator != "indep") throw std::invalid_argument("--verbose: with --generator indep only");
    if (!iterations_given) run.iterations = kit::domain_spec(binding).default_iterations;
    std::vector<FamilyScore> rows;
    auto timed = [&](std::string_view name, auto evaluate) {
      const auto t0 = std::chrono::steady_clock::now();
      rows.push_back(evaluate());
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::cerr << fmt::format("{}: {} scenes in {:.1f} s\n", name, run.scenes, s);
    };
    std::vector<std::string> names;
    if (which != "all") {
      std::stringstream ss(which);
      for (std::string name; std::getline(ss, name, ',');) names.push_back(name);
    }
    if (generator == "indep") {
      std::vector<const ti::Family*> chosen;
      if (names.empty())
        for (const auto& f : ti::families()) chosen.push_back(&f);
      for (const auto& n : names) chosen.push_back(&ti::family(n));
      if (!db_dir.empty()) {
        long n = 0;
        for (const ti::Family* f : chosen) n += write_indep_training_dbs(*f, binding, run, db_dir);
        std::cout << fmt::format("{} training worlds written to {}\n", n, db_dir);
        return 0;
      }
      for (const ti::Family* f : chosen) timed(f->name, [&] { return evaluate_indep_family(*f, binding, run); });
    } else {
      std::vector<const tf::Family*> chosen;
      if (names.empty())
        for (const auto& f : tf::families()) chosen.push_back(&f);
      for (const auto& n : names) chosen.push_back(&tf::family(n));
      if (!db_dir.empty()) {
        long n = 0;
        for (const tf::Family* f : chosen) n += write_training_dbs(*f, binding, run, db_dir);
        std::cout << fmt::format("{} training worlds written to {}\n", n, db_dir);
        return 0;
      }
      for (const tf::Family* f : chosen) timed(f->name, [&] { return evaluate_family(*f, binding, run); });
    }
    std::cout << fmt::format("generator {}, binding {}, seed {}, {} scenes per family, {} iterations\n", generator,
                             binding_name, run.seed, run.scenes, run.iterations)
              << family_table(rows) << pooled_line(rows);
    if (kinds) std::cout << false_kind_lines(rows);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tabletop_family_eval: %s\n", e.what());
    return 2;
  }
}
