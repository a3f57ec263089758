#include "stdlib/tabletop/perception/registration.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/SVD>

namespace ksmc::stdlib::tabletop::perception {

Eigen::Isometry3d rigid_fit(const std::vector<Eigen::Vector3d>& src, const std::vector<Eigen::Vector3d>& dst) {
  const auto n = static_cast<Eigen::Index>(src.size());
  Eigen::Matrix3Xd a(3, n), b(3, n);
  for (Eigen::Index i = 0; i < n; ++i)
    a.col(i) = src[static_cast<std::size_t>(i)], b.col(i) = dst[static_cast<std::size_t>(i)];
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.matrix() = Eigen::umeyama(a, b, false);
  return t;
}

namespace {

struct Assignment {
  std::vector<int> match;
  int matched = 0;
  double sum_sq = 0.0;
};

// Greedy nearest-pair assignment under the transform, pairs closer than `gate` only.
Assignment assign(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target,
                  const Eigen::Isometry3d& t, double gate) {
  struct Pair {
    double d;
    int s, g;
  };
  std::vector<Pair> pairs;
  for (std::size_t s = 0; s < source.size(); ++s) {
    const Eigen::Vector3d p = t * source[s];
    for (std::size_t g = 0; g < target.size(); ++g) {
      const double d = (p - target[g]).norm();
      if (d < gate) pairs.push_back({d, static_cast<int>(s), static_cast<int>(g)});
    }
  }
  std::sort(pairs.begin(), pairs.end(), [](const Pair& x, const Pair& y) {
    return x.d < y.d || (x.d == y.d && (x.s < y.s || (x.s == y.s && x.g < y.g)));
  });
  Assignment a;
  a.match.assign(source.size(), -1);
  std::vector<bool> used(target.size(), false);
  for (const Pair& p : pairs) {
    if (a.match[static_cast<std::size_t>(p.s)] >= 0 || used[static_cast<std::size_t>(p.g)]) continue;
    a.match[static_cast<std::size_t>(p.s)] = p.g;
    used[static_cast<std::size_t>(p.g)] = true;
    ++a.matched;
    a.sum_sq += p.d * p.d;
  }
  return a;
}

void residuals(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target, Registration& r) {
  double sq = 0.0;
  r.max_residual = 0.0;
  for (std::size_t i = 0; i < source.size(); ++i) {
    if (r.match[i] < 0) continue;
    const double d = (r.source_to_target * source[i] - target[static_cast<std::size_t>(r.match[i])]).norm();
    sq += d * d;
    r.max_residual = std::max(r.max_residual, d);
  }
  r.rms = r.matched > 0 ? std::sqrt(sq / r.matched) : 0.0;
}

}  // namespace

Registration register_unmatched(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target,
                                double gate) {
  Registration best;
  best.match.assign(source.size(), -1);
  if (source.size() < 3 || target.size() < 3) return best;
  double best_sq = std::numeric_limits<double>::infinity();
  const std::size_t ns = source.size(), nt = target.size();
  auto dist = [](const Eigen::Vector3d& x, const Eigen::Vector3d& y) { return (x - y).norm(); };
  for (std::size_t i = 0; i < ns; ++i)
    for (std::size_t j = i + 1; j < ns; ++j)
      for (std::size_t k = j + 1; k < ns; ++k) {
        const Eigen::Vector3d &si = source[i], &sj = source[j], &sk = source[k];
        if ((sj - si).cross(sk - si).norm() < gate * gate) continue;  // nearly collinear
        for (std::size_t a = 0; a < nt; ++a)
          for (std::size_t b = 0; b < nt; ++b) {
            if (b == a || std::abs(dist(si, sj) - dist(target[a], target[b])) > gate) continue;
            for (std::size_t c = 0; c < nt; ++c) {
              if (c == a || c == b) continue;
              if (std::abs(dist(si, sk) - dist(target[a], target[c])) > gate ||
                  std::abs(dist(sj, sk) - dist(target[b], target[c])) > gate)
                continue;
              const Eigen::Isometry3d t = rigid_fit({si, sj, sk}, {target[a], target[b], target[c]});
              Assignment as = assign(source, target, t, gate);
              if (as.matched > best.matched || (as.matched == best.matched && as.sum_sq < best_sq)) {
                best.matched = as.matched;
                best.match = std::move(as.match);
                best.source_to_target = t;
                best_sq = as.sum_sq;
              }
            }
          }
      }
  if (best.matched < 3) return best;
  // Refine on all matches; re-assign once with the refined transform.
  for (int round = 0; round < 2; ++round) {
    std::vector<Eigen::Vector3d> s, d;
    for (std::size_t i = 0; i < ns; ++i)
      if (best.match[i] >= 0) s.push_back(source[i]), d.push_back(target[static_cast<std::size_t>(best.match[i])]);
    best.source_to_target = rigid_fit(s, d);
    if (round == 0) {
      Assignment as = assign(source, target, best.source_to_target, gate);
      if (as.matched >= best.matched) best.match = std::move(as.match), best.matched = as.matched;
    }
  }
  residuals(source, target, best);
  return best;
}

Registration match_nearest(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target,
                           const Eigen::Isometry3d& t, double gate) {
  Registration r;
  r.source_to_target = t;
  Assignment as = assign(source, target, t, gate);
  r.match = std::move(as.match);
  r.matched = as.matched;
  residuals(source, target, r);
  return r;
}

}  // namespace ksmc::stdlib::tabletop::perception
