// Rigid registration of two point sets with unknown correspondences (e.g. detected box
// centres against ground-truth centres in another frame): every triple of source points
// against every ordered triple of target points with the same side lengths (within
// `gate`) gives a Umeyama/Kabsch hypothesis; the remaining points are matched to their
// nearest target within `gate`; the hypothesis with most matches (then least RMS) wins and
// is refined by Umeyama on all its matches.
#pragma once

#include <vector>

#include <Eigen/Geometry>

namespace ksmc::stdlib::tabletop::perception {

struct Registration {
  Eigen::Isometry3d source_to_target = Eigen::Isometry3d::Identity();
  std::vector<int> match;  // per source point: target index, or -1
  int matched = 0;
  double rms = 0.0;        // over the matched pairs, after refinement [input units]
  double max_residual = 0.0;
};

// Least-squares rigid transform (no scale, det +1) taking src[i] to dst[i] (Umeyama 1991).
Eigen::Isometry3d rigid_fit(const std::vector<Eigen::Vector3d>& src, const std::vector<Eigen::Vector3d>& dst);

// Nearest-pair matching of `source` mapped by `t` to `target`, pairs closer than `gate`
// only, closest pairs first (each point used once). Fills match, matched, rms, max_residual.
Registration match_nearest(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target,
                           const Eigen::Isometry3d& t, double gate);

// Needs at least three points on each side; returns matched = 0 when no hypothesis fits.
Registration register_unmatched(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target,
                                double gate);

}  // namespace ksmc::stdlib::tabletop::perception
