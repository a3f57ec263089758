#include "stdlib/tabletop/perception/planar_faces.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <Eigen/Eigenvalues>

namespace ksmc::stdlib::tabletop::perception {

namespace {

// Largest first, ties by first index (deterministic).
void sort_largest_first(std::vector<Face>& faces) {
  std::stable_sort(faces.begin(), faces.end(), [](const Face& a, const Face& b) {
    return a.points.size() > b.points.size() || (a.points.size() == b.points.size() && a.points.front() < b.points.front());
  });
}

// Whether faces a and b are parts of one face (join_coplanar_faces).
bool one_face(const Points& points, const Face& a, const Face& b, const FaceOptions& o) {
  if (std::abs(a.normal.dot(b.normal)) < std::cos(o.max_angle_deg * 3.14159265358979323846 / 180.0)) return false;
  if (std::abs((b.centroid - a.centroid).dot(a.normal)) > o.plane_tolerance ||
      std::abs((a.centroid - b.centroid).dot(b.normal)) > o.plane_tolerance)
    return false;
  Points of_b;
  of_b.reserve(b.points.size());
  for (int j : b.points) of_b.push_back(points[static_cast<std::size_t>(j)]);
  const PointGrid near_b(of_b, std::max(o.row_factor, 1.0) * o.grow_radius);
  std::vector<int> nb;
  return std::any_of(a.points.begin(), a.points.end(), [&](int i) {
    near_b.neighbours(points[static_cast<std::size_t>(i)], nb);
    return !nb.empty();
  });
}

}  // namespace

std::vector<Face> planar_faces(const Points& points, const FaceOptions& o) {
  const std::size_t n = points.size();
  std::vector<Eigen::Vector3d> normal(n, Eigen::Vector3d::UnitZ());
  std::vector<double> curvature(n, 1.0);
  std::vector<int> nb;
  {
    const PointGrid grid(points, o.normal_radius);
    for (std::size_t i = 0; i < n; ++i) {
      grid.neighbours(points[i], nb);
      if (nb.size() < 5) continue;
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      for (int j : nb) mean += points[static_cast<std::size_t>(j)];
      mean /= static_cast<double>(nb.size());
      Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
      for (int j : nb) {
        const Eigen::Vector3d d = points[static_cast<std::size_t>(j)] - mean;
        cov += d * d.transpose();
      }
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
      const double trace = es.eigenvalues().sum();
      if (trace <= 0.0) continue;
      curvature[i] = es.eigenvalues()(0) / trace;
      normal[i] = es.eigenvectors().col(0);
    }
  }
  // Seeds in order of increasing curvature (flattest first); stable for determinism.
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return curvature[static_cast<std::size_t>(a)] < curvature[static_cast<std::size_t>(b)]; });
  const double cos_max = std::cos(o.max_angle_deg * 3.14159265358979323846 / 180.0);
  const PointGrid grid(points, o.grow_radius);
  std::vector<char> taken(n, 0), tried(n, 0);
  std::vector<Face> faces;
  for (int seed : order) {
    const auto s = static_cast<std::size_t>(seed);
    if (taken[s] || tried[s] || curvature[s] > o.max_curvature) continue;
    taken[s] = 1;
    std::vector<int> region{seed};
    Eigen::Vector3d sum = normal[s];
    for (std::size_t k = 0; k < region.size(); ++k) {
      const Eigen::Vector3d axis = sum.normalized();
      grid.neighbours(points[static_cast<std::size_t>(region[k])], nb);
      for (int j : nb) {
        const auto u = static_cast<std::size_t>(j);
        if (taken[u] || curvature[u] > o.max_curvature) continue;
        const double c = normal[u].dot(axis);
        if (std::abs(c) < cos_max) continue;
        taken[u] = 1;
        region.push_back(j);
        sum += c < 0 ? -normal[u] : normal[u];
      }
    }
    if (region.size() < o.min_points) {
      // A small patch: its points stay free for other faces but seed none (no rework).
      for (int j : region) taken[static_cast<std::size_t>(j)] = 0, tried[static_cast<std::size_t>(j)] = 1;
      continue;
    }
    Face f;
    f.normal = sum.normalized();
    std::sort(region.begin(), region.end());
    for (int j : region) f.centroid += points[static_cast<std::size_t>(j)];
    f.centroid /= static_cast<double>(region.size());
    f.points = std::move(region);
    faces.push_back(std::move(f));
  }
  sort_largest_first(faces);
  for (std::size_t i = 0; i < n; ++i) taken[i] = 0;
  for (const Face& f : faces)
    for (int j : f.points) taken[static_cast<std::size_t>(j)] = 1;
  // Each face, largest first, takes the free points on its plane reached from its points
  // within `g`'s radius that pass `joins` (grown from the points it takes too).
  const auto extend = [&](const PointGrid& g, const auto& joins) {
    for (Face& f : faces) {
      for (std::size_t k = 0; k < f.points.size(); ++k) {
        g.neighbours(points[static_cast<std::size_t>(f.points[k])], nb);
        for (int j : nb) {
          const auto u = static_cast<std::size_t>(j);
          if (taken[u] || std::abs((points[u] - f.centroid).dot(f.normal)) > o.plane_tolerance || !joins(u, f)) continue;
          taken[u] = 1;
          f.points.push_back(j);
        }
      }
    }
  };
  // Rows of a face seen at a slant: flat points whose normals agree with the face's.
  if (o.row_factor > 1.0)
    extend(PointGrid(points, o.row_factor * o.grow_radius), [&](std::size_t u, const Face& f) {
      return curvature[u] <= o.max_curvature && std::abs(normal[u].dot(f.normal)) >= cos_max;
    });
  // Edges: points near an edge have mixed normals and join no face above; each face takes
  // the free points next to it that lie on its plane, so that faces reach the box's edges.
  extend(grid, [](std::size_t, const Face&) { return true; });
  for (Face& f : faces) std::sort(f.points.begin(), f.points.end());
  sort_largest_first(faces);
  return faces;
}

void join_coplanar_faces(const Points& points, std::vector<Face>& faces, const FaceOptions& o,
                         const std::function<bool(const Face&)>& may_join) {
  bool joined = false;
  for (std::size_t i = 0; i < faces.size(); ++i) {
    if (!may_join(faces[i])) continue;
    for (std::size_t j = i + 1; j < faces.size(); ++j) {
      if (!may_join(faces[j]) || !one_face(points, faces[i], faces[j], o)) continue;
      Face& a = faces[i];
      const Face& b = faces[j];
      const auto na = static_cast<double>(a.points.size()), nb = static_cast<double>(b.points.size());
      const Eigen::Vector3d bn = a.normal.dot(b.normal) < 0.0 ? Eigen::Vector3d(-b.normal) : b.normal;
      a.normal = (na * a.normal + nb * bn).normalized();
      a.centroid = (na * a.centroid + nb * b.centroid) / (na + nb);
      a.points.insert(a.points.end(), b.points.begin(), b.points.end());
      std::sort(a.points.begin(), a.points.end());
      faces.erase(faces.begin() + static_cast<std::ptrdiff_t>(j));
      j = i;  // the joined face may reach one it did not before
      joined = true;
    }
  }
  if (!joined) return;
  sort_largest_first(faces);
}

}  // namespace ksmc::stdlib::tabletop::perception
