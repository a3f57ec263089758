// The end-to-end scene of the stereo and cloud front ends (docs/perception_stereo.md, "End to end"):
//   crate   on the table; its camera-facing side carries a glossy printed picture of the
//           product `poster` (a database object that is not in the scene);
//   base    on the table, with `top` stacked on it (a stack);
//   black   a plain black box (no texture, not in the database, no depth returns),
//           with `lid` resting on it: the supporter neither front end can see;
//   poster  only the picture on the crate's side.
// How the decisions legitimately arise:
//   stereo: `black` has no features and no model -> not detected -> `lid` hovers -> hidden;
//           the picture matches `poster`'s model -> a box inside the crate, in the air -> false.
//   cloud:  `black` returns no depth (absorbing) -> `lid`'s cluster starts 8 cm up -> hidden;
//           the glossy picture returns multipath depth 3 cm too long -> a ghost cluster inside
//           the crate, in the air -> false.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "stdlib/tabletop/perception/stereo/object_db.h"
#include "tools/stereo_synth/synth_stereo.h"

namespace ksmc::tests::stereo {

namespace sy = ksmc::tools::stereo_synth;
namespace st = ksmc::stdlib::tabletop::perception::stereo;

struct E2eScene {
  std::vector<sy::TexturedBox> present;   // rendered (both front ends)
  std::vector<sy::TexturedBox> database;  // object database (crate, base, top, lid, poster)
  Eigen::Vector3d picture_min, picture_max;  // the picture's extent in the crate frame
  int crate = 0, black = 3;                  // indices into `present`
};

inline E2eScene e2e_scene() {
  E2eScene s;
  auto crate = sy::textured_box("crate", {0.22, 0.12, 0.13}, sy::upright(-0.12, 0.02, 0.065, 0.0), 11);
  const auto base = sy::textured_box("base", {0.16, 0.12, 0.06}, sy::upright(0.11, -0.07, 0.03, 0.3), 12);
  const auto top = sy::textured_box("top", {0.10, 0.08, 0.07}, sy::upright(0.11, -0.07, 0.095, 0.2), 13);
  auto black = sy::textured_box("black", {0.12, 0.10, 0.08}, sy::upright(0.07, 0.15, 0.04, 0.0), 14);
  for (auto& f : black.faces) f = cv::Mat();
  black.plain_grey = 25;
  const auto lid = sy::textured_box("lid", {0.09, 0.07, 0.05}, sy::upright(0.07, 0.15, 0.105, -0.2), 15);
  // The poster product: its ny face (u along z, v along x) is printed 1:1 on the crate's ny
  // face, centred in x and 2.5 cm above the crate's mid-height.
  const auto poster = sy::textured_box("poster", {0.12, 0.04, 0.07}, sy::upright(0, 0, 0, 0), 16);
  const int ny = 3;
  const st::FaceFrame ff = st::face_frame(ny);
  const cv::Mat& pic = poster.faces[ny];
  cv::Mat& side = crate.faces[ny];
  const double z_centre = 0.025;
  const int col0 = static_cast<int>(std::lround((z_centre - 0.5 * poster.size[ff.u_axis]) / crate.size[ff.u_axis] * side.cols + 0.5 * side.cols));
  const int row0 = static_cast<int>(std::lround((0.0 - 0.5 * poster.size[ff.v_axis]) / crate.size[ff.v_axis] * side.rows + 0.5 * side.rows));
  pic.copyTo(side(cv::Rect(col0, row0, pic.cols, pic.rows)));
  s.picture_min = Eigen::Vector3d(-0.06, -0.06, z_centre - 0.035);
  s.picture_max = Eigen::Vector3d(0.06, -0.06, z_centre + 0.035);
  s.present = {crate, base, top, black, lid};
  s.database = {crate, base, top, lid, poster};
  return s;
}

}  // namespace ksmc::tests::stereo
