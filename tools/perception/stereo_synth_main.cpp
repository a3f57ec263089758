// ksmc-stereo-synth --out DIR [--objects N] [--seed S]
// Writes a synthesised stereo frame (stdlib/tabletop/perception/stereo/synth): N textured
// boxes on a 4-column grid seen by a rig 0.75 m from the table: DIR/left.png, right.png,
// stereo.yaml, db/<box>/ (object.json + face textures) and truth.json (true box poses,
// table frame). Exit codes: 0 ok, 2 bad arguments.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include <fmt/format.h>
#include <opencv2/imgcodecs.hpp>

#include "tools/stereo_synth/synth_stereo.h"

namespace sy = ksmc::tools::stereo_synth;
namespace st = ksmc::stdlib::tabletop::perception::stereo;
namespace fs = std::filesystem;
using ksmc::stdlib::tabletop::Pose;

int main(int argc, char** argv) {
  std::string out;
  int objects = 5;
  std::uint64_t seed = 1;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      if (a == "--out" && i + 1 < argc) out = argv[++i];
      else if (a == "--objects" && i + 1 < argc) objects = std::stoi(argv[++i]);
      else if (a == "--seed" && i + 1 < argc) seed = std::stoull(argv[++i]);
      else throw std::invalid_argument("unexpected argument '" + a + "'");
    }
    if (out.empty() || objects < 1 || objects > 16) throw std::invalid_argument("--out DIR and 1..16 --objects needed");
  } catch (const std::exception& e) {
    std::cerr << "ksmc-stereo-synth: " << e.what() << "\nusage: ksmc-stereo-synth --out DIR [--objects N] [--seed S]\n";
    return 2;
  }
  sy::Rig rig;
  rig.table_from_left = sy::look_at_table(0.75, 0.85, 0.15);
  const auto boxes = sy::grid_boxes(objects, seed);
  fs::create_directories(out);
  const sy::StereoPair pair = sy::render_pair(rig, boxes, seed);
  cv::imwrite((fs::path(out) / "left.png").string(), pair.left);
  cv::imwrite((fs::path(out) / "right.png").string(), pair.right);
  st::save_calib(fs::path(out) / "stereo.yaml", sy::rig_calib(rig));
  std::ofstream truth(fs::path(out) / "truth.json");
  truth << "{\"objects\": [";
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const auto& b = boxes[i];
    sy::write_object_folder(fs::path(out) / "db", b);
    const Eigen::Quaterniond q = b.pose.q;
    truth << (i ? ",\n  " : "\n  ")
          << fmt::format(R"({{"id": "{}", "size": [{:.6f}, {:.6f}, {:.6f}], "t": [{:.6f}, {:.6f}, {:.6f}], "q": [{:.9f}, {:.9f}, {:.9f}, {:.9f}]}})",
                         b.name, b.size.x(), b.size.y(), b.size.z(), b.pose.t.x(), b.pose.t.y(), b.pose.t.z(), q.w(),
                         q.x(), q.y(), q.z());
  }
  truth << "\n]}\n";
  fmt::print("{}: {} boxes, {}x{} pair, baseline {:.3f} m\n", out, boxes.size(), rig.width, rig.height, rig.baseline);
  return 0;
}
