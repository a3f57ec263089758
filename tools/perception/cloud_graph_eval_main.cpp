// ksmc-cloud-graph-eval --tabletop PATH [--scenes N] [--objects A..B] [--seed S] [--iterations N]
//                       [--chain-seed S] [--work DIR] [--min-f1 F] [--verbose]
// Cloud -> scene graph on simulated clouds: renders the depth cloud of each generated scene
// (the three families of ksmc-perception-sim, the same scenes for the same --seed), runs
// `PATH --cloud frame.ply` on it (the domain binary: the front end, then the inference), and
// scores its scene graph against the settled scene. Each box found is named after the true box
// nearest its centre (within 5 cm, camera frame). Printed per family: the support edges'
// precision / recall / F1 against the true support relation (an edge to a box not found is
// missed), and the boxes found that the binary marked false, hidden or left undecided (either
// probability within 0.4-0.6). The scenes have no false estimate and nothing hidden from the
// sensor, so every such mark is an error. Exit codes: 0 ok, 1 a run or a file failed, 2 bad
// arguments, 3 the pooled support-edge F1 is under --min-f1.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "stdlib/tabletop/perception/cloud_io.h"
#include "tools/perception/object_range.h"
#include "tools/perception_sim/sim_cloud.h"

namespace pc = ksmc::stdlib::tabletop::perception;
namespace ps = ksmc::tools::perception_sim;
namespace sim = ksmc::tools::tabletop_sim;
namespace fs = std::filesystem;

namespace {

struct Tally {
  int scenes = 0, boxes = 0, found = 0, edges_true = 0, edges_found = 0, edges_right = 0;
  int marked_false = 0, marked_hidden = 0, undecided = 0;

  void add(const Tally& t) {
    scenes += t.scenes, boxes += t.boxes, found += t.found, edges_true += t.edges_true;
    edges_found += t.edges_found, edges_right += t.edges_right, marked_false += t.marked_false;
    marked_hidden += t.marked_hidden, undecided += t.undecided;
  }
  [[nodiscard]] double precision() const { return edges_found ? double(edges_right) / edges_found : 1.0; }
  [[nodiscard]] double recall() const { return edges_true ? double(edges_right) / edges_true : 1.0; }
  [[nodiscard]] double f1() const {
    const double p = precision(), r = recall();
    return p + r > 0.0 ? 2.0 * p * r / (p + r) : 0.0;
  }
};

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

// Runs the binary on one frame and scores its scene graph; throws with the reason.
Tally score_frame(const std::string& tabletop, const ps::SimFrame& f, const fs::path& dir, int iterations,
                  int chain_seed, bool verbose, const std::string& label) {
  fs::create_directories(dir);
  pc::save_ply(dir / "frame.ply", f.cloud);
  const fs::path out = dir / "out";
  const std::string cmd = fmt::format("{} --cloud {} --out {} --iterations {} --seed {} > {} 2>&1", tabletop,
                                      quoted(dir / "frame.ply"), quoted(out), iterations, chain_seed,
                                      quoted(dir / "log.txt"));
  if (std::system(cmd.c_str()) != 0)
    throw std::runtime_error(fmt::format("{}: {} failed (see {})", label, tabletop, (dir / "log.txt").string()));
  std::ifstream in(out / "scene_graph.json");
  if (!in) throw std::runtime_error(fmt::format("{}: no {}", label, (out / "scene_graph.json").string()));
  const nlohmann::json g = nlohmann::json::parse(in);

  // Each box found, named after the nearest unclaimed true box within 5 cm (closest pairs first).
  std::vector<std::tuple<double, std::size_t, std::size_t>> pairs;
  const auto& objects = g.at("objects");
  for (std::size_t e = 0; e < objects.size(); ++e) {
    const auto& t = objects[e].at("pose").at("t");
    const Eigen::Vector3d c(t[0].get<double>(), t[1].get<double>(), t[2].get<double>());
    for (std::size_t k = 0; k < f.truth.size(); ++k) {
      const double d = (f.truth[k].centre - c).norm();
      if (d <= 0.05) pairs.emplace_back(d, e, k);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  std::map<std::string, int> truth_of;  // estimate id -> true box index
  std::set<std::size_t> claimed;
  for (const auto& [d, e, k] : pairs) {
    const std::string id = objects[e].at("id").get<std::string>();
    if (truth_of.count(id) || claimed.count(k)) continue;
    truth_of[id] = static_cast<int>(k);
    claimed.insert(k);
  }

  Tally t;
  t.scenes = 1;
  t.boxes = static_cast<int>(f.truth.size());
  t.found = static_cast<int>(truth_of.size());
  std::set<std::pair<int, int>> truth_edges;
  for (const auto& [upper, lower] : f.scene.relations.support)
    truth_edges.emplace(upper, lower == sim::kTableIndex ? -1 : lower);
  t.edges_true = static_cast<int>(truth_edges.size());
  for (const auto& e : g.at("support")) {
    const std::string up = e[0].get<std::string>(), low = e[1].get<std::string>();
    ++t.edges_found;
    const auto u = truth_of.find(up);
    const auto l = truth_of.find(low);
    if (u == truth_of.end() || (low != "table" && l == truth_of.end())) continue;
    const bool right = truth_edges.count({u->second, low == "table" ? -1 : l->second}) > 0;
    t.edges_right += right;
    if (verbose && !right) fmt::print("  {}: extra support {} on {}\n", label, up, low);
  }
  for (const auto& o : objects) {
    const double pf = o.at("false_prob").get<double>(), ph = o.at("hidden_prob").get<double>();
    const auto marked = [&](const char* key) {  // true, false, or null (undecided: within 0.4-0.6)
      const auto& v = o.at(key);
      return v.is_boolean() && v.get<bool>();
    };
    const bool f_mark = marked("false"), h_mark = marked("hidden");
    t.marked_false += f_mark;
    t.marked_hidden += h_mark;
    const bool open = (pf >= 0.4 && pf <= 0.6) || (ph >= 0.4 && ph <= 0.6);
    t.undecided += open;
    if (verbose && (f_mark || h_mark || open))
      fmt::print("  {}: {} false {:.2f} hidden {:.2f}\n", label, o.at("id").get<std::string>(), pf, ph);
  }
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  std::string tabletop, work;
  int scenes = 10, lo = 5, hi = 10, iterations = 2000, chain_seed = 1;
  std::uint64_t seed = 1;
  bool verbose = false;
  double min_f1 = 0.0;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      if (a == "--verbose") {
        verbose = true;
        continue;
      }
      if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
      const std::string v = argv[++i];
      if (a == "--tabletop") tabletop = v;
      else if (a == "--scenes") scenes = std::stoi(v);
      else if (a == "--seed") seed = std::stoull(v);
      else if (a == "--iterations") iterations = std::stoi(v);
      else if (a == "--chain-seed") chain_seed = std::stoi(v);
      else if (a == "--work") work = v;
      else if (a == "--min-f1") min_f1 = std::stod(v);
      else if (a == "--objects") std::tie(lo, hi) = ksmc::tools::perception::parse_object_range(v);
      else throw std::invalid_argument("unknown option " + a);
    }
    if (tabletop.empty()) throw std::invalid_argument("--tabletop PATH (the domain binary) is required");
    if (scenes < 1 || lo < 1 || hi < lo || iterations < 1) throw std::invalid_argument("values out of range");
  } catch (const std::exception& e) {
    std::cerr << "ksmc-cloud-graph-eval: " << e.what() << "\n";
    return 2;
  }
  const fs::path root = work.empty() ? fs::temp_directory_path() / fmt::format("ksmc_cloud_graph_{}", seed) : fs::path(work);
  fmt::print("{} scenes per family, {}..{} boxes, seed {}, {} iterations (chain seed {}), binary {}\n", scenes, lo, hi,
             seed, iterations, chain_seed, tabletop);
  fmt::print("{:<8} {:>5} {:>5} | {:>5} {:>6} {:>6} {:>6} | {:>6} {:>6} {:>9}\n", "family", "boxes", "found", "edges",
             "P", "R", "F1", "false", "hidden", "undecided");
  Tally all;
  const auto row = [](const std::string& name, const Tally& t) {
    fmt::print("{:<8} {:>5} {:>5} | {:>5} {:>6.3f} {:>6.3f} {:>6.3f} | {:>6} {:>6} {:>9}\n", name, t.boxes, t.found,
               t.edges_true, t.precision(), t.recall(), t.f1(), t.marked_false, t.marked_hidden, t.undecided);
  };
  for (const ps::SimFamily& fam : ps::sim_families(lo, hi)) {
    Tally family;
    for (int s = 0; s < scenes; ++s) {
      const std::string label = fmt::format("{} scene {}", fam.name, s);
      try {
        const ps::SimFrame f = ps::simulate_frame(sim::scene_seed(seed, static_cast<std::uint64_t>(s)), fam);
        family.add(score_frame(tabletop, f, root / fmt::format("{}_{}", fam.name, s), iterations, chain_seed, verbose,
                               label));
      } catch (const std::exception& e) {
        std::cerr << "ksmc-cloud-graph-eval: " << e.what() << "\n";
        return 1;
      }
    }
    row(fam.name, family);
    all.add(family);
  }
  row("all", all);
  if (all.f1() < min_f1) {
    std::cerr << fmt::format("ksmc-cloud-graph-eval: support-edge F1 {:.3f} is under --min-f1 {:.3f}\n", all.f1(), min_f1);
    return 3;
  }
  return 0;
}
