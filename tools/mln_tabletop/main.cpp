// ksmc-mln-tabletop: labelled worlds for weight learning from simulated table-top scenes,
// and the scores of weight sets on them (docs/mln.md, "Table-top weights learned from
// simulated scenes").
//   ksmc-mln-tabletop worlds --scenes DIR --out DIR2
//       DIR/scene_NNN.json + scene_NNN.truth.json (ksmc-scenegen) -> DIR2/scene_NNN.db
//   ksmc-mln-tabletop evaluate A.ksm [B.ksm ...] --data X.db [Y.db ...] [-I DIR]
//       per rule base: per query predicate the mean log P(true value) and the accuracy,
//       and the mean joint conditional log-likelihood per world.
// Exit codes: 0 ok, 1 bad input (named), 2 bad usage.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "compiler/driver/pipeline.h"
#include "runtime/io/atomic_file.h"
#include "runtime/mln/error.h"
#include "stdlib/tabletop/scene_io.h"
#include "tools/mln_tabletop/evaluate.h"
#include "tools/mln_tabletop/labelled_world.h"

namespace fs = std::filesystem;
namespace mt = ksmc::tools::mln_tabletop;

namespace {

constexpr const char* kUsage =
    "usage: ksmc-mln-tabletop worlds --scenes DIR --out DIR2\n"
    "       ksmc-mln-tabletop evaluate A.ksm [B.ksm ...] --data X.db [Y.db ...] [-I DIR]\n";

int worlds(const fs::path& scenes, const fs::path& out) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(scenes)) {
    const std::string name = entry.path().filename().string();
    if (name.ends_with(".json") && !name.ends_with(".truth.json")) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  if (files.empty()) {
    std::cerr << scenes.string() << ": error: no scene_NNN.json files\n";
    return 1;
  }
  fs::create_directories(out);
  for (const auto& f : files) {
    fs::path truth_path = f;
    truth_path.replace_extension(".truth.json");
    std::ifstream in(truth_path, std::ios::binary);
    if (!in) {
      std::cerr << truth_path.string() << ": error: cannot read the truth file\n";
      return 1;
    }
    const auto truth = nlohmann::json::parse(in);
    const auto load = ksmc::stdlib::tabletop::load_scene(f);
    fs::path db = out / f.filename();
    db.replace_extension(".db");
    ksmc::runtime::io::write_file_atomic(db, mt::labelled_world_db(load.scene, truth, f.filename().string()));
  }
  std::cout << "ksmc-mln-tabletop: wrote " << files.size() << " labelled worlds to " << out.string() << "\n";
  return 0;
}

int evaluate(const std::vector<std::string>& ksm, const std::vector<std::string>& data,
             const std::vector<std::string>& include_dirs) {
  using namespace ksmc::compiler;
  std::cout << fmt::format("{} worlds; per predicate: mean log P(true value) over its atoms / accuracy of P > 0.5 "
                           "(atoms decided wrong)\n",
                           data.size());
  for (const auto& path : ksm) {
    diag::SourceManager sources;
    diag::DiagEngine diags(sources);
    build::LoadOptions options;
    options.include_dirs = include_dirs;
    const auto r = driver::run_pipeline(path, options, sources, diags, driver::Goal::LowerMln);
    diags.flush(std::cerr);
    if (!r.ok) return 1;
    const mt::Evaluation e = mt::evaluate(r.mln.program, data);
    std::string line = fmt::format("{:<34}", path);
    long atoms = 0, correct = 0;
    double log_p = 0.0;
    for (const auto& s : e.predicates) {
      line += fmt::format(" {} {:.4f} / {:.3f} ({} wrong)", s.name, s.log_p / static_cast<double>(s.atoms),
                          static_cast<double>(s.correct) / static_cast<double>(s.atoms), s.atoms - s.correct);
      if (s.clamped > 0) line += fmt::format(" ({} at 1e-12)", s.clamped);
      atoms += s.atoms;
      correct += s.correct;
      log_p += s.log_p;
    }
    line += fmt::format(" | all {:.4f} / {:.3f} | joint CLL per world {:.4f}", log_p / static_cast<double>(atoms),
                        static_cast<double>(correct) / static_cast<double>(atoms),
                        e.joint_cll / static_cast<double>(e.worlds - e.infeasible));
    if (e.infeasible > 0) line += fmt::format(" ({} worlds against a hard rule left out)", e.infeasible);
    std::cout << line << "\n";
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || (args[0] != "worlds" && args[0] != "evaluate")) {
    std::cerr << kUsage;
    return 2;
  }
  std::string scenes, out;
  std::vector<std::string> ksm, data, include_dirs;
  bool in_data = false;
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    const bool valued = a == "--scenes" || a == "--out" || a == "-I";
    if (valued && i + 1 >= args.size()) {
      std::cerr << "ksmc-mln-tabletop: " << a << " needs a value\n" << kUsage;
      return 2;
    }
    if (a == "--scenes") scenes = args[++i];
    else if (a == "--out") out = args[++i];
    else if (a == "-I") include_dirs.push_back(args[++i]);
    else if (a == "--data") in_data = true;
    else if (a.starts_with("-")) {
      std::cerr << "ksmc-mln-tabletop: unknown option '" << a << "'\n" << kUsage;
      return 2;
    } else (in_data ? data : ksm).push_back(a);
  }
  try {
    if (args[0] == "worlds") {
      if (scenes.empty() || out.empty() || !ksm.empty()) {
        std::cerr << kUsage;
        return 2;
      }
      return worlds(scenes, out);
    }
    if (ksm.empty() || data.empty()) {
      std::cerr << kUsage;
      return 2;
    }
    return evaluate(ksm, data, include_dirs);
  } catch (const ksmc::runtime::mln::MlnError& e) {
    std::cerr << "ksmc-mln-tabletop: error: " << e.what() << "\n";
  } catch (const std::exception& e) {
    std::cerr << "ksmc-mln-tabletop: error: " << e.what() << "\n";
  }
  return 1;
}
