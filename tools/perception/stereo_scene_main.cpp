// ksmc-stereo-scene LEFT RIGHT --calib stereo.yaml --db DIR [--out DIR] [--truth truth.json]
// Runs the stereo front end (seed Alg. 2), prints per database object the valid 3D-3D
// matches, rigid hypotheses, clusters, inliers and residual, and with --truth (written by
// ksmc-stereo-synth) the centre and rotation errors; --out writes DIR/scene.json.
// Exit codes: 0 ok, 1 bad input (the message names the file), 2 bad arguments.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <numbers>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "stdlib/tabletop/perception/scene_json.h"
#include "stdlib/tabletop/perception/stereo/scene_from_stereo.h"

namespace st = ksmc::stdlib::tabletop::perception::stereo;
namespace pc = ksmc::stdlib::tabletop::perception;
namespace fs = std::filesystem;

int main(int argc, char** argv) {
  std::vector<std::string> images;
  std::string calib, db, out, truth;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--calib" && i + 1 < argc) calib = argv[++i];
    else if (a == "--db" && i + 1 < argc) db = argv[++i];
    else if (a == "--out" && i + 1 < argc) out = argv[++i];
    else if (a == "--truth" && i + 1 < argc) truth = argv[++i];
    else if (!a.empty() && a[0] != '-') images.push_back(a);
    else images.assign(3, "");
  }
  if (images.size() != 2 || calib.empty() || db.empty()) {
    std::cerr << "usage: ksmc-stereo-scene LEFT RIGHT --calib stereo.yaml --db DIR [--out DIR] [--truth truth.json]\n";
    return 2;
  }
  try {
    const st::StereoCalib c = st::load_calib(calib);
    const auto models = st::load_database(db);
    const cv::Mat l = st::read_grey(images[0]), r = st::read_grey(images[1]);
    st::StereoSceneOptions options;
    const st::StereoScene s = st::scene_from_images(l, r, images[0], images[1], c, models, options);
    fmt::print("keypoints left {} right {}, stereo points {}\n", s.points.left_keypoints, s.points.right_keypoints,
               s.points.point.size());
    std::map<std::string, std::pair<Eigen::Vector3d, Eigen::Quaterniond>> gt;
    if (!truth.empty()) {
      std::ifstream in(truth);
      if (!in) throw st::StereoError(truth + ": cannot read");
      const auto doc = nlohmann::json::parse(in);
      for (const auto& o : doc.at("objects")) {
        const auto t = o.at("t"), q = o.at("q");
        gt[o.at("id").get<std::string>()] = {Eigen::Vector3d(t[0], t[1], t[2]),
                                             Eigen::Quaterniond(q[0], q[1], q[2], q[3])};
      }
    }
    for (std::size_t k = 0; k < models.size(); ++k) {
      const auto matches = st::match_to_model(s.points, models[k], options.pose.ratio);
      std::size_t found = s.detections.size();
      for (std::size_t d = 0; d < s.detections.size(); ++d)
        if (s.detections[d].object == static_cast<int>(k)) found = d;
      fmt::print("{:<10} matches {:>4}", models[k].name, matches.size());
      if (found == s.detections.size()) {
        fmt::print("  not found\n");
        continue;
      }
      const auto& det = s.detections[found];
      const auto& obj = s.scene.objects[found];
      fmt::print("  hypotheses {:>4} clusters {:>3} cluster {:>4} inliers {:>4} rms {:.1f} mm", det.hypotheses,
                 det.clusters, det.cluster_size, det.inliers.size(), 1000.0 * det.rms);
      if (const auto it = gt.find(obj.id); it != gt.end())
        fmt::print("  centre {:.2f} mm angle {:.2f} deg", 1000.0 * (obj.pose.t - it->second.first).norm(),
                   obj.pose.q.angularDistance(it->second.second) * 180.0 / std::numbers::pi);
      fmt::print("\n");
    }
    if (!out.empty()) {
      fs::create_directories(out);
      pc::write_scene_json(fs::path(out) / "scene.json", s.scene);
    }
  } catch (const std::exception& e) {
    std::cerr << "ksmc-stereo-scene: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
