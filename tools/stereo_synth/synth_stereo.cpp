#include "tools/stereo_synth/synth_stereo.h"

#include <cmath>
#include <fstream>
#include <limits>

#include <fmt/format.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "stdlib/tabletop/camera_geometry.h"
#include "stdlib/tabletop/perception/stereo/object_db.h"

namespace ksmc::tools::stereo_synth {

using stdlib::tabletop::look_along;
using stdlib::tabletop::ray_enter_box;
using stdlib::tabletop::perception::stereo::face_frame;
using stdlib::tabletop::perception::stereo::FaceFrame;
using stdlib::tabletop::perception::stereo::kFaceNames;

namespace fs = std::filesystem;

cv::Mat procedural_texture(int w, int h, std::uint64_t seed) {
  cv::RNG rng(seed);
  // Low-frequency grey background (a coarse random grid, cubic-upsampled) under dense shapes.
  cv::Mat coarse(std::max(2, h / 24), std::max(2, w / 24), CV_8U);
  rng.fill(coarse, cv::RNG::UNIFORM, 40, 220);
  cv::Mat t;
  cv::resize(coarse, t, cv::Size(w, h), 0, 0, cv::INTER_CUBIC);
  const int shapes = std::max(12, w * h / 300);
  const int scale = std::max(8, std::min(w, h) / 5);
  for (int i = 0; i < shapes; ++i) {
    const cv::Point c(rng.uniform(0, w), rng.uniform(0, h));
    const cv::Scalar grey(rng.uniform(0, 256));
    const int r = rng.uniform(4, scale);
    switch (rng.uniform(0, 4)) {
      case 0: cv::circle(t, c, r, grey, cv::FILLED, cv::LINE_AA); break;
      case 1: cv::rectangle(t, c, c + cv::Point(rng.uniform(3, scale), rng.uniform(3, scale)), grey, cv::FILLED); break;
      case 2:
        cv::line(t, c, c + cv::Point(rng.uniform(-scale, scale), rng.uniform(-scale, scale)), grey, rng.uniform(1, 5),
                 cv::LINE_AA);
        break;
      default: {
        std::vector<cv::Point> tri{c, c + cv::Point(rng.uniform(-r, r), rng.uniform(-r, r)),
                                   c + cv::Point(rng.uniform(-r, r), rng.uniform(-r, r))};
        cv::fillConvexPoly(t, tri, grey, cv::LINE_AA);
      }
    }
  }
  return t;
}

TexturedBox textured_box(const std::string& name, const Eigen::Vector3d& size, const Pose& pose, std::uint64_t seed) {
  TexturedBox b;
  b.name = name;
  b.size = size;
  b.pose = pose;
  for (int f = 0; f < 6; ++f) {
    const FaceFrame ff = face_frame(f);
    const int w = std::max(16, static_cast<int>(std::lround(size[ff.u_axis] * kTexturePixelsPerMetre)));
    const int h = std::max(16, static_cast<int>(std::lround(size[ff.v_axis] * kTexturePixelsPerMetre)));
    b.faces[static_cast<std::size_t>(f)] = procedural_texture(w, h, seed * 7919 + static_cast<std::uint64_t>(f) + 1);
  }
  return b;
}

Pose look_at_table(double distance, double elevation, double azimuth) {
  const Eigen::Vector3d eye(distance * std::cos(elevation) * std::sin(azimuth),
                            -distance * std::cos(elevation) * std::cos(azimuth), distance * std::sin(elevation));
  Pose p;
  p.t = eye;
  p.q = look_along(-eye);
  return p;
}

StereoCalib rig_calib(const Rig& rig) {
  StereoCalib c;
  c.width = rig.width;
  c.height = rig.height;
  c.k_left << rig.f, 0, 0.5 * rig.width - 0.5, 0, rig.f, 0.5 * rig.height - 0.5, 0, 0, 1;
  c.k_right = c.k_left;
  c.t = Eigen::Vector3d(-rig.baseline, 0, 0);
  c.table_in_left = rig.table_from_left.inverse();
  c.table_size = Eigen::Vector3d(2.0 * rig.table_half.x(), 2.0 * rig.table_half.y(), 0.05);
  return c;
}

namespace {

struct Prepared {
  Eigen::Matrix3d r;  // box axes in the table frame
  Eigen::Vector3d t, half;
  std::array<cv::Mat, 6> faces;  // CV_32F, slightly blurred against aliasing
};

float bilinear(const cv::Mat& t, double x, double y) {
  x = std::clamp(x, 0.0, t.cols - 1.0);
  y = std::clamp(y, 0.0, t.rows - 1.0);
  const int x0 = std::min(static_cast<int>(x), std::max(0, t.cols - 2));
  const int y0 = std::min(static_cast<int>(y), std::max(0, t.rows - 2));
  const int x1 = std::min(x0 + 1, t.cols - 1), y1 = std::min(y0 + 1, t.rows - 1);
  const auto fx = static_cast<float>(x - x0), fy = static_cast<float>(y - y0);
  const float a = t.at<float>(y0, x0) * (1 - fx) + t.at<float>(y0, x1) * fx;
  const float b = t.at<float>(y1, x0) * (1 - fx) + t.at<float>(y1, x1) * fx;
  return a * (1 - fy) + b * fy;
}

cv::Mat render_view(const Rig& rig, const Pose& table_from_cam, const std::vector<Prepared>& boxes,
                    const cv::Mat& table_tex, const TexturedBox* const* plain, cv::RNG& rng) {
  const Eigen::Matrix3d rc = table_from_cam.rotation();
  const Eigen::Vector3d eye = table_from_cam.t;
  const Eigen::Vector3d light = Eigen::Vector3d(0.3, -0.4, 1.0).normalized();
  const double cx = 0.5 * rig.width - 0.5, cy = 0.5 * rig.height - 0.5;
  cv::Mat img(rig.height, rig.width, CV_8U);
  constexpr int kSub = 2;
  for (int v = 0; v < rig.height; ++v) {
    for (int u = 0; u < rig.width; ++u) {
      double sum = 0.0;
      for (int sv = 0; sv < kSub; ++sv)
        for (int su = 0; su < kSub; ++su) {
          const double pu = u - 0.5 + (su + 0.5) / kSub, pv = v - 0.5 + (sv + 0.5) / kSub;
          const Eigen::Vector3d dir = rc * Eigen::Vector3d((pu - cx) / rig.f, (pv - cy) / rig.f, 1.0);
          double best = std::numeric_limits<double>::infinity(), shade = 1.0, value = 90.0;
          if (dir.z() < 0.0 && eye.z() > 0.0) {
            const double s = -eye.z() / dir.z();
            const Eigen::Vector3d hit = eye + s * dir;
            if (std::abs(hit.x()) <= rig.table_half.x() && std::abs(hit.y()) <= rig.table_half.y()) {
              best = s;
              value = bilinear(table_tex, (hit.x() + rig.table_half.x()) * 500.0, (hit.y() + rig.table_half.y()) * 500.0);
              shade = light.z();
            }
          }
          for (std::size_t b = 0; b < boxes.size(); ++b) {
            const Prepared& p = boxes[b];
            const Eigen::Vector3d o = p.r.transpose() * (eye - p.t), d = p.r.transpose() * dir;
            int face = 0;
            const double s = ray_enter_box(o, d, p.half, &face);
            if (s <= 0.0 || s >= best) continue;
            best = s;
            const FaceFrame ff = face_frame(face);
            const Eigen::Vector3d q = o + s * d;
            const cv::Mat& tex = p.faces[static_cast<std::size_t>(face)];
            if (tex.empty()) {
              value = plain[b]->plain_grey;
            } else {
              const double x = (q[ff.u_axis] / (2.0 * p.half[ff.u_axis]) + 0.5) * tex.cols - 0.5;
              const double y = (q[ff.v_axis] / (2.0 * p.half[ff.v_axis]) + 0.5) * tex.rows - 0.5;
              value = bilinear(tex, x, y);
            }
            Eigen::Vector3d n = Eigen::Vector3d::Zero();
            n[ff.normal] = ff.sign;
            shade = std::max(0.0, (p.r * n).dot(light));
          }
          sum += value * (0.45 + 0.55 * shade);
        }
      const double g = sum / (kSub * kSub) + rng.gaussian(rig.noise);
      img.at<std::uint8_t>(v, u) = cv::saturate_cast<std::uint8_t>(g);
    }
  }
  return img;
}

}  // namespace

StereoPair render_pair(const Rig& rig, const std::vector<TexturedBox>& boxes, std::uint64_t seed) {
  std::vector<Prepared> prep;
  std::vector<const TexturedBox*> plain;
  for (const TexturedBox& b : boxes) {
    Prepared p;
    p.r = b.pose.rotation();
    p.t = b.pose.t;
    p.half = 0.5 * b.size;
    for (int f = 0; f < 6; ++f) {
      const cv::Mat& src = b.faces[static_cast<std::size_t>(f)];
      if (src.empty()) continue;
      cv::Mat g;
      src.convertTo(g, CV_32F);
      cv::GaussianBlur(g, p.faces[static_cast<std::size_t>(f)], cv::Size(0, 0), 0.8);
    }
    prep.push_back(std::move(p));
    plain.push_back(&b);
  }
  cv::Mat table;
  procedural_texture(static_cast<int>(rig.table_half.x() * 1000.0), static_cast<int>(rig.table_half.y() * 1000.0),
                     seed ^ 0x7AB1EULL)
      .convertTo(table, CV_32F, 0.5, 70.0);  // a less contrasted table top
  cv::GaussianBlur(table, table, cv::Size(0, 0), 1.0);
  cv::RNG rng(seed);
  StereoPair out;
  out.left = render_view(rig, rig.table_from_left, prep, table, plain.data(), rng);
  Pose right_in_left;
  right_in_left.t = Eigen::Vector3d(rig.baseline, 0, 0);
  out.right = render_view(rig, rig.table_from_left.compose(right_in_left), prep, table, plain.data(), rng);
  return out;
}

Pose upright(double x, double y, double z, double yaw) {
  Pose p;
  p.t = Eigen::Vector3d(x, y, z);
  p.q = Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
  return p;
}

std::vector<TexturedBox> grid_boxes(int n, std::uint64_t seed) {
  cv::RNG rng(seed);
  std::vector<TexturedBox> out;
  const int cols = 4, rows = (n + cols - 1) / cols;
  for (int i = 0; i < n; ++i) {
    const int c = i % cols, r = i / cols;
    const Eigen::Vector3d size(rng.uniform(0.07, 0.11), rng.uniform(0.05, 0.09), rng.uniform(0.04, 0.10));
    const double x = (c - 0.5 * (cols - 1)) * 0.15, y = (r - 0.5 * (rows - 1)) * 0.13;
    out.push_back(textured_box("box" + std::to_string(i), size, upright(x, y, 0.5 * size.z(), rng.uniform(-0.6, 0.6)),
                               seed * 101 + static_cast<std::uint64_t>(i)));
  }
  return out;
}

void write_object_folder(const fs::path& dir, const TexturedBox& box) {
  const fs::path folder = dir / box.name;
  fs::create_directories(folder);
  std::ofstream(folder / "object.json") << fmt::format("{{\"size\": [{:.6f}, {:.6f}, {:.6f}]}}\n", box.size.x(),
                                                       box.size.y(), box.size.z());
  for (int f = 0; f < 6; ++f) {
    const cv::Mat& t = box.faces[static_cast<std::size_t>(f)];
    if (!t.empty()) cv::imwrite((folder / fmt::format("face_{}.png", kFaceNames[f])).string(), t);
  }
}

}  // namespace ksmc::tools::stereo_synth
