// Object database for the stereo front end (seed §4.6, Alg. 2): a folder per object holding
// object.json ({"size": [x, y, z]} in metres) and one texture per box face
// (face_px.png face_nx.png face_py.png face_ny.png face_pz.png face_nz.png). The 3D keypoint
// model of an object is SIFT on each face texture, every keypoint lifted onto its face in the
// object (box-centred) frame (texture resampled to several scales, ModelOptions). `ksmc-objdb` writes it as model.yml (cv::FileStorage) next to
// the textures; load_database reads model.yml or builds the model when it is absent.
#pragma once

#include <array>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace ksmc::stdlib::tabletop::perception::stereo {

class StereoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

inline constexpr std::array<const char*, 6> kFaceNames{"px", "nx", "py", "ny", "pz", "nz"};

// Face f (0..5) of a box: normal +-axis `normal` (sign `sign`); the texture's columns run
// along `u_axis`, its rows along `v_axis`, chosen so that the texture is seen unmirrored
// from outside the box (u x v points into the box).
struct FaceFrame {
  int normal = 0;
  double sign = 1.0;
  int u_axis = 1;
  int v_axis = 2;
};
FaceFrame face_frame(int face);

// The object-frame point of texture pixel (x, y) (OpenCV pixel coordinates, pixel centres at
// integers) on face `face` of a box of full extents `size`, the texture being w x h pixels.
Eigen::Vector3d face_point(int face, const Eigen::Vector3d& size, double x, double y, int w, int h);

struct ObjectModel {
  std::string name;                      // the folder name
  std::filesystem::path folder;
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> points;   // object frame, metres
  std::vector<int> faces;                // face of each point
  cv::Mat descriptors;                   // CV_32F, one SIFT descriptor (128) per point
};

struct ModelOptions {
  int max_features_per_face = 500;
  double contrast_threshold = 0.04;
  // SIFT runs on each texture at these scales too (INTER_AREA): a face seen from afar is
  // matched against keypoints detected at a similar resolution.
  std::vector<double> scales{1.0, 0.5};
};

// Reads object.json and the six face textures of `folder` (a missing face is skipped; none
// at all, an unreadable texture or a bad size is a StereoError naming the file) and builds
// the keypoint model. No SIFT feature on any face: StereoError naming the folder.
ObjectModel build_model(const std::filesystem::path& folder, const ModelOptions& options = {});

void save_model(const std::filesystem::path& file, const ObjectModel& model);
ObjectModel load_model(const std::filesystem::path& file);

// Every sub-folder of `dir` holding object.json, in name order; model.yml is used when it
// exists, otherwise the model is built. An empty database is a StereoError.
std::vector<ObjectModel> load_database(const std::filesystem::path& dir, const ModelOptions& options = {});

}  // namespace ksmc::stdlib::tabletop::perception::stereo
