// ksmc-cloud-graph-eval --tabletop PATH [--scenes N] [--objects A..B] [--seed S] [--iterations N]
//                       [--chain-seed S] [--work DIR] [--min-f1 F] [--centre-only] [--verbose]
// Cloud -> scene graph on simulated clouds: renders the depth cloud of each generated scene
// (the three families of ksmc-perception-sim, the same scenes for the same --seed), runs
// `PATH --cloud frame.ply` on it (the domain binary: the front end, then the inference), and
// scores its scene graph against the settled scene. Each scene's folder under --work keeps the
// frame (frame.ply), the settled boxes (truth.json, obb_world.json's format, camera frame), the
// binary's log and its output. Each box found is named after the true box nearest its centre
// (within 5 cm, camera frame: "found"); a box left over, after the unclaimed true box holding
// at least half its volume ("partial": a real object seen in part, its centre far from the
// true one; --centre-only leaves these unmatched, the measure before stop 40). Printed per
// family:
// - the support edges' precision / recall / F1 against the true support relation (an edge to
//   a box not found is missed);
// - hidden: a box found is truly "hidden" when a box it rests on was not found (the sensor
//   did not see it, or the front end missed it); the binary's hidden marks against that
//   (right / wrong / left out);
// - false: a box is truly "false" when it matches no true box (a second box in a true box, a
//   ghost); the binary's false marks against that;
// - undecided: boxes with either probability within 0.4-0.6.
// Exit codes: 0 ok, 1 a run or a file failed, 2 bad arguments, 3 the pooled support-edge F1
// is under --min-f1.
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

#include "runtime/io/atomic_file.h"
#include "stdlib/tabletop/perception/cloud_io.h"
#include "tools/perception/object_range.h"
#include "tools/perception_sim/sim_cloud.h"

namespace pc = ksmc::stdlib::tabletop::perception;
namespace ps = ksmc::tools::perception_sim;
namespace sim = ksmc::tools::tabletop_sim;
namespace fs = std::filesystem;

namespace {

struct Tally {
  int scenes = 0, boxes = 0, found = 0, partial = 0, edges_true = 0, edges_found = 0, edges_right = 0;
  int hidden_right = 0, hidden_wrong = 0, hidden_left = 0;  // marks on truly hidden / other boxes, hidden not marked
  int false_right = 0, false_wrong = 0, false_left = 0;
  int undecided = 0;

  void add(const Tally& t) {
    scenes += t.scenes, boxes += t.boxes, found += t.found, partial += t.partial, edges_true += t.edges_true;
    edges_found += t.edges_found, edges_right += t.edges_right;
    hidden_right += t.hidden_right, hidden_wrong += t.hidden_wrong, hidden_left += t.hidden_left;
    false_right += t.false_right, false_wrong += t.false_wrong, false_left += t.false_left;
    undecided += t.undecided;
  }
  [[nodiscard]] double precision() const { return edges_found ? double(edges_right) / edges_found : 1.0; }
  [[nodiscard]] double recall() const { return edges_true ? double(edges_right) / edges_true : 1.0; }
  [[nodiscard]] double f1() const {
    const double p = precision(), r = recall();
    return p + r > 0.0 ? 2.0 * p * r / (p + r) : 0.0;
  }
};

// A true box's inside test.
struct TruthBoxView {
  const pc::TruthBox& box;
  [[nodiscard]] bool contains(const Eigen::Vector3d& p, double margin) const {
    const Eigen::Vector3d l = box.axes.transpose() * (p - box.centre);
    return (l.cwiseAbs() - 0.5 * box.size).maxCoeff() <= margin;
  }
};

// A path for the shell, in single quotes (a quote inside is closed, escaped and reopened).
std::string shell_quoted(const fs::path& p) {
  std::string out = "'";
  for (const char c : p.string()) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// Runs the binary on one frame and scores its scene graph; throws with the reason.
Tally score_frame(const std::string& tabletop, const ps::SimFrame& f, const fs::path& dir, int iterations,
                  int chain_seed, bool verbose, bool partial_views, const std::string& label) {
  fs::create_directories(dir);
  pc::save_ply(dir / "frame.ply", f.cloud);
  {  // the settled boxes beside the frame, camera frame, in obb_world.json's format
    nlohmann::json truth = {{"frame", "camera (the cloud's frame)"}, {"objects", nlohmann::json::array()}};
    for (const auto& b : f.truth) {
      std::vector<double> r;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r.push_back(b.axes(i, j));
      truth["objects"].push_back({{"class", b.name},
                                  {"center_m", {b.centre.x(), b.centre.y(), b.centre.z()}},
                                  {"R_rowmajor", r},
                                  {"size_m", {b.size.x(), b.size.y(), b.size.z()}}});
    }
    ksmc::runtime::io::write_file_atomic(dir / "truth.json", truth.dump(1) + "\n");
  }
  const fs::path out = dir / "out";
  const std::string cmd =
      fmt::format("{} --cloud {} --out {} --iterations {} --seed {} > {} 2>&1", shell_quoted(fs::path(tabletop)),
                  shell_quoted(dir / "frame.ply"), shell_quoted(out), iterations, chain_seed, shell_quoted(dir / "log.txt"));
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
  // A box left over is a partial view of the unclaimed true box holding at least half of it (a
  // 5 x 5 x 5 grid over the box, the true box grown by 3 mm), the fullest first: a real object
  // seen in part is not a false estimate.
  std::size_t partial = 0;
  if (partial_views) {
    std::ifstream sin(out / "scene.json");
    if (!sin) throw std::runtime_error(fmt::format("{}: no {}", label, (out / "scene.json").string()));
    std::map<std::string, Eigen::Vector3d> size_of;
    const nlohmann::json scene = nlohmann::json::parse(sin);
    for (const auto& o : scene.at("objects")) {
      const auto& z = o.at("size");
      size_of[o.at("id").get<std::string>()] = Eigen::Vector3d(z[0].get<double>(), z[1].get<double>(), z[2].get<double>());
    }
    std::vector<std::tuple<double, std::size_t, std::size_t>> inside;  // -share, estimate, true box
    for (std::size_t e = 0; e < objects.size(); ++e) {
      const std::string id = objects[e].at("id").get<std::string>();
      if (truth_of.count(id) || !size_of.count(id)) continue;
      const auto& t = objects[e].at("pose").at("t");
      const auto& q = objects[e].at("pose").at("q");
      const Eigen::Vector3d c(t[0].get<double>(), t[1].get<double>(), t[2].get<double>());
      const Eigen::Matrix3d r =
          Eigen::Quaterniond(q[0].get<double>(), q[1].get<double>(), q[2].get<double>(), q[3].get<double>())
              .normalized()
              .toRotationMatrix();
      for (std::size_t k = 0; k < f.truth.size(); ++k) {
        if (claimed.count(k)) continue;
        const TruthBoxView b{f.truth[k]};
        int in = 0;
        for (int i = 0; i < 5; ++i)
          for (int j = 0; j < 5; ++j)
            for (int l = 0; l < 5; ++l) {
              const Eigen::Vector3d u((i - 2) / 5.0, (j - 2) / 5.0, (l - 2) / 5.0);
              in += b.contains(c + r * u.cwiseProduct(size_of[id]), 0.003);
            }
        if (in >= 63) inside.emplace_back(-in / 125.0, e, k);
      }
    }
    std::sort(inside.begin(), inside.end());
    for (const auto& [share, e, k] : inside) {
      const std::string id = objects[e].at("id").get<std::string>();
      if (truth_of.count(id) || claimed.count(k)) continue;
      truth_of[id] = static_cast<int>(k);
      claimed.insert(k);
      ++partial;
    }
  }

  Tally t;
  t.scenes = 1;
  t.boxes = static_cast<int>(f.truth.size());
  t.found = static_cast<int>(truth_of.size() - partial);
  t.partial = static_cast<int>(partial);
  std::set<std::pair<int, int>> truth_edges;
  for (const auto& [upper, lower] : f.scene.relations.support)
    truth_edges.emplace(upper, lower == sim::kTableIndex ? -1 : lower);
  t.edges_true = static_cast<int>(truth_edges.size());
  std::set<std::pair<int, int>> drawn;  // the binary's edges, as true box indices
  for (const auto& e : g.at("support")) {
    const std::string up = e[0].get<std::string>(), low = e[1].get<std::string>();
    ++t.edges_found;
    const auto u = truth_of.find(up);
    const auto l = truth_of.find(low);
    if (u == truth_of.end() || (low != "table" && l == truth_of.end())) {
      if (verbose)
        fmt::print("  {}: extra support {} on {} ({} matches no true box)\n", label, up, low,
                   u == truth_of.end() ? up : low);
      continue;
    }
    const std::pair<int, int> edge{u->second, low == "table" ? -1 : l->second};
    drawn.insert(edge);
    const bool right = truth_edges.count(edge) > 0;
    t.edges_right += right;
    if (verbose && !right) fmt::print("  {}: extra support {} on {}\n", label, up, low);
  }
  if (verbose) {
    std::map<int, std::string> id_of;
    for (const auto& [id, k] : truth_of) id_of[k] = id;
    const auto name = [&](int k) {
      if (k < 0) return std::string("table");
      const auto it = id_of.find(k);
      return f.truth[static_cast<std::size_t>(k)].name + (it == id_of.end() ? " (not found)" : " = " + it->second);
    };
    for (const auto& edge : truth_edges)
      if (!drawn.count(edge)) fmt::print("  {}: missed support {} on {}\n", label, name(edge.first), name(edge.second));
  }
  for (const auto& o : objects) {
    const double pf = o.at("false_prob").get<double>(), ph = o.at("hidden_prob").get<double>();
    const auto marked = [&](const char* key) {  // true, false, or null (undecided: within 0.4-0.6)
      const auto& v = o.at(key);
      return v.is_boolean() && v.get<bool>();
    };
    const bool f_mark = marked("false"), h_mark = marked("hidden");
    const std::string id = o.at("id").get<std::string>();
    const auto match = truth_of.find(id);
    const bool is_false = match == truth_of.end();
    bool is_hidden = false;  // a box it rests on was not found
    if (!is_false)
      for (const auto& [upper, lower] : truth_edges)
        is_hidden = is_hidden || (upper == match->second && lower >= 0 && !claimed.count(static_cast<std::size_t>(lower)));
    if (f_mark) ++(is_false ? t.false_right : t.false_wrong);
    else if (is_false) ++t.false_left;
    if (h_mark) ++(is_hidden ? t.hidden_right : t.hidden_wrong);
    else if (is_hidden) ++t.hidden_left;
    const bool open = (pf >= 0.4 && pf <= 0.6) || (ph >= 0.4 && ph <= 0.6);
    t.undecided += open;
    if (verbose && (f_mark || h_mark || open)) {
      std::string truth = "no true box";  // what the box is, and what it truly rests on
      if (!is_false) {
        const std::size_t k = static_cast<std::size_t>(match->second);
        std::string on;
        for (const auto& [upper, lower] : truth_edges)
          if (upper == match->second)
            on += (on.empty() ? "" : ", ") +
                  (lower < 0 ? std::string("table")
                             : f.truth[static_cast<std::size_t>(lower)].name +
                                   (claimed.count(static_cast<std::size_t>(lower)) ? "" : " (not found)"));
        truth = f.truth[k].name + " on " + (on.empty() ? "nothing" : on);
      }
      fmt::print("  {}: {} false {:.2f} hidden {:.2f} ({})\n", label, id, pf, ph, truth);
    }
  }
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  std::string tabletop, work;
  int scenes = 10, lo = 5, hi = 10, iterations = 2000, chain_seed = 1;
  std::uint64_t seed = 1;
  bool verbose = false, partial_views = true;
  double min_f1 = 0.0;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      if (a == "--verbose") {
        verbose = true;
        continue;
      }
      if (a == "--centre-only") {
        partial_views = false;
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
  fmt::print("{} scenes per family, {}..{} boxes, seed {}, {} iterations (chain seed {}), binary {}; boxes matched by {}\n",
             scenes, lo, hi, seed, iterations, chain_seed, tabletop,
             partial_views ? "centre, then as partial views" : "centre only");
  fmt::print("{:<8} {:>5} {:>5} {:>7} | {:>5} {:>6} {:>6} {:>6} | {:>23} | {:>22} | {:>9}\n", "family", "boxes", "found", "partial",
             "edges", "P", "R", "F1", "hidden right/wrong/left", "false right/wrong/left", "undecided");
  Tally all;
  const auto row = [](const std::string& name, const Tally& t) {
    fmt::print("{:<8} {:>5} {:>5} {:>7} | {:>5} {:>6.3f} {:>6.3f} {:>6.3f} | {:>23} | {:>22} | {:>9}\n", name, t.boxes, t.found, t.partial,
               t.edges_true, t.precision(), t.recall(), t.f1(),
               fmt::format("{} / {} / {}", t.hidden_right, t.hidden_wrong, t.hidden_left),
               fmt::format("{} / {} / {}", t.false_right, t.false_wrong, t.false_left), t.undecided);
  };
  for (const ps::SimFamily& fam : ps::sim_families(lo, hi)) {
    Tally family;
    for (int s = 0; s < scenes; ++s) {
      const std::string label = fmt::format("{} scene {}", fam.name, s);
      try {
        const ps::SimFrame f = ps::simulate_frame(sim::scene_seed(seed, static_cast<std::uint64_t>(s)), fam);
        family.add(score_frame(tabletop, f, root / fmt::format("{}_{}", fam.name, s), iterations, chain_seed, verbose,
                               partial_views, label));
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
