// Checked access to JSON documents for the table-top importers: every failure
// throws SceneError "<source>: <json.path>: <message>".
#pragma once

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "stdlib/tabletop/pose.h"
#include "stdlib/tabletop/scene_io.h"

namespace ksmc::stdlib::tabletop::detail {

using nlohmann::json;

class Reader {
 public:
  Reader(std::string source, std::vector<std::string>& warnings)
      : source_(std::move(source)), warnings_(warnings) {}

  [[noreturn]] void fail(const std::string& path, const std::string& msg) const {
    throw SceneError(fmt::format("{}: {}: {}", source_, path, msg));
  }
  void warn(const std::string& path, const std::string& msg) const {
    warnings_.push_back(fmt::format("{}: {}: {}", source_, path, msg));
  }

  const json& member(const json& obj, const std::string& path, const char* key) const {
    if (!obj.is_object()) fail(path, "expected an object");
    auto it = obj.find(key);
    if (it == obj.end()) fail(join(path, key), "missing field");
    return *it;
  }
  const json* optional_member(const json& obj, const std::string& path, const char* key) const {
    if (!obj.is_object()) fail(path, "expected an object");
    auto it = obj.find(key);
    return it == obj.end() ? nullptr : &*it;
  }

  double number(const json& j, const std::string& path) const {
    if (!j.is_number()) fail(path, fmt::format("expected a number, got {}", j.type_name()));
    const double v = j.get<double>();
    if (!std::isfinite(v)) fail(path, "not a finite number");
    return v;
  }
  double positive(const json& j, const std::string& path) const {
    const double v = number(j, path);
    if (!(v > 0.0)) fail(path, fmt::format("must be > 0, got {}", v));
    return v;
  }
  int positive_int(const json& j, const std::string& path) const {
    if (!j.is_number_integer()) fail(path, fmt::format("expected an integer, got {}", j.type_name()));
    const auto v = j.get<long long>();
    if (v <= 0 || v > 1000000) fail(path, fmt::format("must be a positive image dimension, got {}", v));
    return static_cast<int>(v);
  }
  std::string string(const json& j, const std::string& path) const {
    if (!j.is_string()) fail(path, fmt::format("expected a string, got {}", j.type_name()));
    return j.get<std::string>();
  }
  const json& array(const json& j, const std::string& path) const {
    if (!j.is_array()) fail(path, fmt::format("expected an array, got {}", j.type_name()));
    return j;
  }
  template <int N>
  Eigen::Matrix<double, N, 1> vec(const json& j, const std::string& path) const {
    array(j, path);
    if (j.size() != static_cast<std::size_t>(N))
      fail(path, fmt::format("expected {} numbers, got {}", N, j.size()));
    Eigen::Matrix<double, N, 1> v;
    for (int i = 0; i < N; ++i) v[i] = number(j[static_cast<std::size_t>(i)], index(path, static_cast<std::size_t>(i)));
    return v;
  }

  Pose pose(const json& j, const std::string& path, double tol) const {
    Pose p;
    p.t = bounded<3>(member(j, path, "t"), join(path, "t"));
    const std::string qpath = join(path, "q");
    const Eigen::Vector4d q = vec<4>(member(j, path, "q"), qpath);  // w, x, y, z
    // Scale by the largest component first so that huge entries cannot overflow the norm.
    const double m = q.cwiseAbs().maxCoeff();
    if (!(m > 1e-12)) fail(qpath, "zero quaternion");
    const Eigen::Vector4d qs = q / m;
    const double ns = qs.norm();
    const double n = ns * m;
    if (!(std::abs(n - 1.0) <= tol)) warn(qpath, fmt::format("non-unit quaternion (norm {:.6g}), normalised", n));
    p.q = Eigen::Quaterniond(qs[0] / ns, qs[1] / ns, qs[2] / ns, qs[3] / ns);
    p.q.normalize();
    return p;
  }

  // Like vec<N>, but every entry must lie within ±limit (default 1e6): larger values
  // are not plausible metres or pixels and would overflow later arithmetic.
  template <int N>
  Eigen::Matrix<double, N, 1> bounded(const json& j, const std::string& path, double limit = 1e6) const {
    const Eigen::Matrix<double, N, 1> v = vec<N>(j, path);
    for (int i = 0; i < N; ++i)
      if (std::abs(v[i]) > limit)
        fail(index(path, static_cast<std::size_t>(i)), fmt::format("value {} out of range (|v| > {})", v[i], limit));
    return v;
  }

  static std::string join(const std::string& path, const char* key) {
    return path.empty() ? std::string(key) : path + "." + key;
  }
  static std::string index(const std::string& path, std::size_t i) { return fmt::format("{}[{}]", path, i); }

 private:
  std::string source_;
  std::vector<std::string>& warnings_;
};

}  // namespace ksmc::stdlib::tabletop::detail
