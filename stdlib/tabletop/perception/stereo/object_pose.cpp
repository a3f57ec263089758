#include "stdlib/tabletop/perception/stereo/object_pose.h"

#include <algorithm>
#include <cmath>
#include <random>

#include <Eigen/Dense>
#include <opencv2/features2d.hpp>

namespace ksmc::stdlib::tabletop::perception::stereo {

namespace {

// Best model point of each query descriptor passing the ratio test, or -1. The second best
// is the nearest descriptor of a model point more than `same_point` away from the best's:
// SIFT gives one location several descriptors (orientations, texture scales), which must
// not veto each other.
std::vector<int> ratio_matches(const cv::Mat& query, const ObjectModel& model, double ratio, double same_point) {
  std::vector<int> out(static_cast<std::size_t>(query.rows), -1);
  if (query.empty() || model.descriptors.rows < 2) return out;
  cv::BFMatcher matcher(cv::NORM_L2);
  std::vector<std::vector<cv::DMatch>> knn;
  matcher.knnMatch(query, model.descriptors, knn, 6);
  for (const auto& m : knn) {
    if (m.size() < 2) continue;
    const Eigen::Vector3d& best = model.points[static_cast<std::size_t>(m[0].trainIdx)];
    float second = m.back().distance;
    for (std::size_t j = 1; j < m.size(); ++j)
      if ((model.points[static_cast<std::size_t>(m[j].trainIdx)] - best).norm() > same_point) {
        second = m[j].distance;
        break;
      }
    if (m[0].distance <= ratio * second) out[static_cast<std::size_t>(m[0].queryIdx)] = m[0].trainIdx;
  }
  return out;
}

Eigen::Isometry3d rigid_fit(const Eigen::Matrix3Xd& model, const Eigen::Matrix3Xd& scene) {
  return Eigen::Isometry3d(Eigen::umeyama(model, scene, false));
}

double rotation_angle(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  const double c = 0.5 * ((a.transpose() * b).trace() - 1.0);
  return std::acos(std::clamp(c, -1.0, 1.0));
}

// Indices (into `matches`) within tolerance of `pose`.
std::vector<int> inliers_of(const Eigen::Isometry3d& pose, const StereoPoints& pts, const ObjectModel& model,
                            const std::vector<Match3d>& matches, double tolerance) {
  std::vector<int> in;
  for (std::size_t i = 0; i < matches.size(); ++i) {
    const Eigen::Vector3d p = pose * model.points[static_cast<std::size_t>(matches[i].model)];
    if ((p - pts.point[static_cast<std::size_t>(matches[i].point)]).norm() <= tolerance) in.push_back(static_cast<int>(i));
  }
  return in;
}

Eigen::Isometry3d fit_on(const std::vector<int>& sel, const StereoPoints& pts, const ObjectModel& model,
                         const std::vector<Match3d>& matches) {
  Eigen::Matrix3Xd m(3, static_cast<Eigen::Index>(sel.size())), s(3, static_cast<Eigen::Index>(sel.size()));
  for (std::size_t k = 0; k < sel.size(); ++k) {
    const Match3d& mt = matches[static_cast<std::size_t>(sel[k])];
    m.col(static_cast<Eigen::Index>(k)) = model.points[static_cast<std::size_t>(mt.model)];
    s.col(static_cast<Eigen::Index>(k)) = pts.point[static_cast<std::size_t>(mt.point)];
  }
  return rigid_fit(m, s);
}

struct Hypothesis {
  Eigen::Isometry3d pose;
  int inliers = 0;
};

}  // namespace

std::vector<Match3d> match_to_model(const StereoPoints& points, const ObjectModel& model, double ratio) {
  constexpr double kSamePoint = 0.003;  // m
  const std::vector<int> l = ratio_matches(points.left_descriptors, model, ratio, kSamePoint);
  const std::vector<int> r = ratio_matches(points.right_descriptors, model, ratio, kSamePoint);
  std::vector<Match3d> out;
  for (std::size_t i = 0; i < l.size(); ++i)  // both images name the same model location
    if (l[i] >= 0 && r[i] >= 0 &&
        (model.points[static_cast<std::size_t>(l[i])] - model.points[static_cast<std::size_t>(r[i])]).norm() <= kSamePoint)
      out.push_back({static_cast<int>(i), l[i]});
  return out;
}

ObjectDetection estimate_pose(const StereoPoints& pts, const ObjectModel& model, const std::vector<Match3d>& matches,
                              const PoseOptions& o, std::uint64_t seed) {
  ObjectDetection d;
  d.matches = static_cast<int>(matches.size());
  if (d.matches < std::max(3, o.min_matches)) return d;
  std::mt19937_64 rng(seed);
  const auto n = static_cast<std::uint64_t>(matches.size());
  auto scene = [&](int k) { return pts.point[static_cast<std::size_t>(matches[static_cast<std::size_t>(k)].point)]; };
  auto mod = [&](int k) { return model.points[static_cast<std::size_t>(matches[static_cast<std::size_t>(k)].model)]; };

  std::vector<Hypothesis> hyps;
  for (int it = 0; it < o.hypotheses; ++it) {
    int idx[3];
    for (int& v : idx) v = static_cast<int>(rng() % n);  // modulo bias is negligible for n << 2^64
    if (idx[0] == idx[1] || idx[1] == idx[2] || idx[0] == idx[2]) continue;
    bool rigid = true;
    for (int a = 0; a < 3 && rigid; ++a) {
      const int p = idx[a], q = idx[(a + 1) % 3];
      const double dm = (mod(p) - mod(q)).norm(), ds = (scene(p) - scene(q)).norm();
      rigid = dm >= o.min_triple_side && std::abs(dm - ds) <= o.triple_tolerance;
    }
    if (!rigid) continue;
    const Eigen::Vector3d e1 = mod(idx[1]) - mod(idx[0]), e2 = mod(idx[2]) - mod(idx[0]);
    if (e1.cross(e2).norm() < o.min_triple_side * o.min_triple_side) continue;  // nearly collinear
    Eigen::Matrix3d m, s;
    for (int a = 0; a < 3; ++a) {
      m.col(a) = mod(idx[a]);
      s.col(a) = scene(idx[a]);
    }
    Hypothesis h;
    h.pose = rigid_fit(m, s);
    h.inliers = static_cast<int>(inliers_of(h.pose, pts, model, matches, o.inlier_tolerance).size());
    hyps.push_back(h);
  }
  d.hypotheses = static_cast<int>(hyps.size());
  if (hyps.empty()) return d;

  // Cluster: greedy, best-supported hypotheses first (stable sort keeps the draw order on ties).
  std::vector<int> order(hyps.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return hyps[static_cast<std::size_t>(a)].inliers > hyps[static_cast<std::size_t>(b)].inliers;
  });
  std::vector<int> centre, members;  // centre: hypothesis index (its best member)
  for (int h : order) {
    const Eigen::Isometry3d& p = hyps[static_cast<std::size_t>(h)].pose;
    std::size_t c = 0;
    for (; c < centre.size(); ++c) {
      const Eigen::Isometry3d& q = hyps[static_cast<std::size_t>(centre[c])].pose;
      if ((p.translation() - q.translation()).norm() <= o.cluster_translation &&
          rotation_angle(p.linear(), q.linear()) <= o.cluster_angle)
        break;
    }
    if (c == centre.size()) {
      centre.push_back(h);
      members.push_back(0);
    }
    ++members[c];
  }
  d.clusters = static_cast<int>(centre.size());
  std::size_t win = 0;
  for (std::size_t c = 1; c < centre.size(); ++c)
    if (members[c] > members[win]) win = c;
  d.cluster_size = members[win];

  // RANSAC consensus of the winning cluster, refined on its inliers (tighter gate) until stable.
  Eigen::Isometry3d pose = hyps[static_cast<std::size_t>(centre[win])].pose;
  std::vector<int> in = inliers_of(pose, pts, model, matches, o.inlier_tolerance);
  for (int round = 0; round < 5 && static_cast<int>(in.size()) >= 3; ++round) {
    pose = fit_on(in, pts, model, matches);
    std::vector<int> next = inliers_of(pose, pts, model, matches, o.refine_tolerance);
    if (next == in) break;
    in = std::move(next);
  }
  const int count = static_cast<int>(in.size());
  if (count < std::min(o.min_inliers, o.min_verified_inliers) || count < 3) return d;
  double ss = 0.0;
  for (int k : in) ss += (pose * mod(k) - scene(k)).squaredNorm();
  const double rms = std::sqrt(ss / static_cast<double>(count));
  if (count < o.min_inliers && (rms > o.verified_rms || d.cluster_size < o.verified_cluster)) return d;
  d.pose = pose;
  d.rms = rms;
  for (int k : in) {
    d.inliers.push_back(matches[static_cast<std::size_t>(k)].point);
    d.model.push_back(mod(k));
  }
  return d;
}

std::vector<ObjectDetection> detect_objects(const StereoPoints& points, const std::vector<ObjectModel>& db,
                                            const PoseOptions& options) {
  std::vector<ObjectDetection> out;
  for (std::size_t k = 0; k < db.size(); ++k) {
    const ObjectModel& model = db[k];
    std::vector<Match3d> matches = match_to_model(points, model, options.ratio);
    std::vector<Eigen::Vector3d> centres;  // of the instances found
    for (int instance = 0; instance < options.max_instances; ++instance) {
      const std::uint64_t seed = options.seed * 0x9E3779B97F4A7C15ULL + k + 0x5851F42D4C957F2DULL * static_cast<std::uint64_t>(instance);
      ObjectDetection d = estimate_pose(points, model, matches, options, seed);
      if (d.inliers.empty()) break;
      const Eigen::Vector3d centre = d.pose.translation();
      const bool same_box = std::any_of(centres.begin(), centres.end(), [&](const Eigen::Vector3d& c) {
        return (c - centre).norm() < 0.9 * model.size.minCoeff();
      });
      if (same_box) break;
      // The matches this pose explains belong to this instance; the next one is sought in the rest.
      const std::vector<int> explained = inliers_of(d.pose, points, model, matches, options.inlier_tolerance);
      std::vector<bool> drop(matches.size(), false);
      for (int i : explained) drop[static_cast<std::size_t>(i)] = true;
      std::vector<Match3d> rest;
      for (std::size_t i = 0; i < matches.size(); ++i)
        if (!drop[i]) rest.push_back(matches[i]);
      matches = std::move(rest);
      centres.push_back(centre);
      d.object = static_cast<int>(k);
      d.instance = instance;
      out.push_back(std::move(d));
    }
  }
  return out;
}

}  // namespace ksmc::stdlib::tabletop::perception::stereo
