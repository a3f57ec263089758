// ksmc-objdb DB_DIR [--max-features N]
// Builds the 3D keypoint model of every object folder of the stereo object database
// (stdlib/tabletop/perception/stereo/object_db.h): SIFT on each face texture, keypoints
// lifted onto the box face, written as <object>/model.yml (cv::FileStorage: name, size,
// points Nx3, faces N, descriptors Nx128). Prints one line per object.
// Exit codes: 0 ok, 1 bad input (the message names the folder or file), 2 bad arguments.
#include <filesystem>
#include <iostream>
#include <string>

#include <fmt/format.h>

#include "stdlib/tabletop/perception/stereo/object_db.h"

namespace st = ksmc::stdlib::tabletop::perception::stereo;
namespace fs = std::filesystem;

int main(int argc, char** argv) {
  std::string dir;
  st::ModelOptions options;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--max-features" && i + 1 < argc) {
      try {
        options.max_features_per_face = std::stoi(argv[++i]);
      } catch (const std::exception&) {
        std::cerr << "ksmc-objdb: --max-features: not an integer\n";
        return 2;
      }
    } else if (!a.empty() && a[0] != '-' && dir.empty()) {
      dir = a;
    } else {
      std::cerr << "ksmc-objdb: unexpected argument '" << a << "'\nusage: ksmc-objdb DB_DIR [--max-features N]\n";
      return 2;
    }
  }
  if (dir.empty()) {
    std::cerr << "usage: ksmc-objdb DB_DIR [--max-features N]\n";
    return 2;
  }
  try {
    if (!fs::is_directory(dir)) throw st::StereoError(dir + ": not a database folder");
    int objects = 0;
    std::vector<fs::path> folders;
    for (const auto& e : fs::directory_iterator(dir))
      if (e.is_directory() && fs::exists(e.path() / "object.json")) folders.push_back(e.path());
    std::sort(folders.begin(), folders.end());
    for (const fs::path& f : folders) {
      const st::ObjectModel m = st::build_model(f, options);
      st::save_model(f / "model.yml", m);
      int per_face[6] = {0, 0, 0, 0, 0, 0};
      for (int face : m.faces) ++per_face[face];
      fmt::print("{}: size {:.3f} x {:.3f} x {:.3f} m, {} keypoints (faces px {} nx {} py {} ny {} pz {} nz {})\n",
                 m.name, m.size.x(), m.size.y(), m.size.z(), m.points.size(), per_face[0], per_face[1], per_face[2],
                 per_face[3], per_face[4], per_face[5]);
      ++objects;
    }
    if (objects == 0) throw st::StereoError(dir + ": no object folder (a folder with object.json)");
  } catch (const st::StereoError& e) {
    std::cerr << "ksmc-objdb: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
