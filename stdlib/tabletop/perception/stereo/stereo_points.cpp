#include "stdlib/tabletop/perception/stereo/stereo_points.h"

#include <cmath>
#include <limits>

#include <Eigen/Dense>
#include <opencv2/features2d.hpp>

namespace ksmc::stdlib::tabletop::perception::stereo {

namespace {

Eigen::Vector2d project(const Eigen::Matrix3d& k, const Eigen::Vector3d& p) {
  const Eigen::Vector3d q = k * p;
  return q.head<2>() / q.z();
}

float descriptor_distance(const cv::Mat& a, int i, const cv::Mat& b, int j) {
  const float* x = a.ptr<float>(i);
  const float* y = b.ptr<float>(j);
  float s = 0.0f;
  for (int k = 0; k < a.cols; ++k) {
    const float d = x[k] - y[k];
    s += d * d;
  }
  return std::sqrt(s);
}

struct Best {
  int index = -1;
  float first = std::numeric_limits<float>::infinity();
  float second = std::numeric_limits<float>::infinity();
  void offer(int i, float d) {
    if (d < first) {
      second = first;
      first = d;
      index = i;
    } else if (d < second) {
      second = d;
    }
  }
};

}  // namespace

Eigen::Vector3d triangulate(const StereoCalib& c, const Eigen::Vector2d& l, const Eigen::Vector2d& r) {
  Eigen::Matrix<double, 3, 4> pl = Eigen::Matrix<double, 3, 4>::Zero(), pr;
  pl.leftCols<3>() = c.k_left;
  pr.leftCols<3>() = c.k_right * c.r;
  pr.col(3) = c.k_right * c.t;
  Eigen::Matrix4d a;
  a.row(0) = l.x() * pl.row(2) - pl.row(0);
  a.row(1) = l.y() * pl.row(2) - pl.row(1);
  a.row(2) = r.x() * pr.row(2) - pr.row(0);
  a.row(3) = r.y() * pr.row(2) - pr.row(1);
  const Eigen::JacobiSVD<Eigen::Matrix4d> svd(a, Eigen::ComputeFullV);
  const Eigen::Vector4d x = svd.matrixV().col(3);
  return x.head<3>() / x.w();
}

StereoPoints stereo_points(const cv::Mat& left, const cv::Mat& right, const StereoCalib& calib,
                           const StereoOptions& options) {
  cv::Ptr<cv::SIFT> sift = cv::SIFT::create(options.max_features, 3, options.contrast_threshold);
  std::vector<cv::KeyPoint> kl, kr;
  cv::Mat dl, dr;
  sift->detectAndCompute(left, cv::noArray(), kl, dl);
  sift->detectAndCompute(right, cv::noArray(), kr, dr);
  StereoPoints out;
  out.left_keypoints = kl.size();
  out.right_keypoints = kr.size();
  if (kl.empty() || kr.empty()) return out;

  const Eigen::Matrix3d f = calib.fundamental();
  const int nl = static_cast<int>(kl.size()), nr = static_cast<int>(kr.size());
  std::vector<Eigen::Vector3d> hr(static_cast<std::size_t>(nr));
  for (int j = 0; j < nr; ++j) hr[static_cast<std::size_t>(j)] = Eigen::Vector3d(kr[j].pt.x, kr[j].pt.y, 1.0);
  std::vector<Best> best_left(static_cast<std::size_t>(nl)), best_right(static_cast<std::size_t>(nr));
  for (int i = 0; i < nl; ++i) {
    const Eigen::Vector3d line = f * Eigen::Vector3d(kl[i].pt.x, kl[i].pt.y, 1.0);
    const double norm = line.head<2>().norm();
    if (norm <= 0.0) continue;
    for (int j = 0; j < nr; ++j) {
      if (std::abs(line.dot(hr[static_cast<std::size_t>(j)])) > options.epipolar_tolerance * norm) continue;
      const float d = descriptor_distance(dl, i, dr, j);
      best_left[static_cast<std::size_t>(i)].offer(j, d);
      best_right[static_cast<std::size_t>(j)].offer(i, d);
    }
  }
  for (int i = 0; i < nl; ++i) {
    const Best& b = best_left[static_cast<std::size_t>(i)];
    if (b.index < 0 || b.first > options.ratio * b.second) continue;
    const Best& back = best_right[static_cast<std::size_t>(b.index)];
    if (back.index != i || back.first > options.ratio * back.second) continue;  // cross-check
    const Eigen::Vector2d pl(kl[i].pt.x, kl[i].pt.y), pr(kr[b.index].pt.x, kr[b.index].pt.y);
    const Eigen::Vector3d x = triangulate(calib, pl, pr);
    const Eigen::Vector3d xr = calib.r * x + calib.t;
    if (!x.allFinite() || x.z() < options.min_depth || x.z() > options.max_depth || xr.z() < options.min_depth) continue;
    if ((project(calib.k_left, x) - pl).norm() > options.reprojection_tolerance ||
        (project(calib.k_right, xr) - pr).norm() > options.reprojection_tolerance)
      continue;
    out.left.push_back(pl);
    out.right.push_back(pr);
    out.point.push_back(x);
    out.left_descriptors.push_back(dl.row(i));
    out.right_descriptors.push_back(dr.row(b.index));
  }
  return out;
}

}  // namespace ksmc::stdlib::tabletop::perception::stereo
