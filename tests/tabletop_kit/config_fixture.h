// Hand-built DomainConfig mirroring domains/tabletop.ksm exactly (base units: 10 deg =
// 0.17453292519943295 rad, 4 mm = 0.004 m), standing in for the generated
// tabletop_model.cpp. `tolerances` lets tests try other extract tolerances and likelihood
// settings (the calibration in docs/tabletop_kit.md); the defaults are the .ksm's.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "runtime/domain/config.h"

namespace ksmc::tests::tabletop_kit {

namespace rd = ksmc::runtime::domain;

// Defaults: domains/tabletop.ksm, calibrated on the generated scenes and the HOPE frame
// (docs/tabletop_kit.md).
struct Tolerances {
  double stable_tol = 0.17453292519943295;  // 10 deg
  double contact_eps = 0.004;               // 4 mm
  double intersect_eps = 0.005;             // 5 mm
  double hover_eps = 0.004;                 // 4 mm
  double vertical_eps = 0.0;                // > 0: add the optional vertical_eps to contact/intersect
  bool robust = true;                       // keypoints.gaussian(robust, outlier_px)
  double outlier_px = 5.0;
};

// The same as the .ksm (kept as a name for the tests that compare settings).
inline Tolerances recommended_tolerances() { return Tolerances{}; }

// A literal reading of the seed: 3 deg, 4 mm, 4 mm, plain Gaussian (sigma 1 px).
inline Tolerances seed_tolerances() {
  Tolerances t;
  t.stable_tol = 0.05235987755982988;  // 3 deg
  t.intersect_eps = 0.004;
  t.robust = false;
  t.outlier_px = 20.0;
  return t;
}

inline rd::Arg arg(std::string name, rd::Value v) { return rd::Arg{std::move(name), std::move(v)}; }
inline rd::Value idx(const std::string& coll, const std::string& var) {
  return rd::Value::index(coll, {rd::Value::name(var)});
}
inline rd::Call call(std::string name, std::vector<rd::Arg> args, int line) {
  return rd::Call{std::move(name), std::move(args), "domains/tabletop.ksm:" + std::to_string(line)};
}

inline rd::DomainConfig tabletop_config(const Tolerances& tol = {}) {
  rd::DomainConfig c;
  c.domain = "tabletop";
  c.source = "domains/tabletop.ksm";
  c.model = {{"pose", true, "object", "se3", true}, {"size", true, "object", "vec3", false}};
  auto pair_args = [](const std::string& a, const std::string& b) {
    return std::vector<rd::Arg>{arg("pose_a", idx("pose", a)), arg("size_a", idx("size", a)),
                                arg("pose_b", idx("pose", b)), arg("size_b", idx("size", b))};
  };
  c.extract.push_back({"stable", {"o"},
                       call("obb.stable", {arg("pose", idx("pose", "o")), arg("size", idx("size", "o")),
                                           arg("tol", rd::Value::num(tol.stable_tol))}, 65)});
  auto contact = pair_args("a", "b");
  contact.push_back(arg("eps", rd::Value::num(tol.contact_eps)));
  if (tol.vertical_eps > 0) contact.push_back(arg("vertical_eps", rd::Value::num(tol.vertical_eps)));
  c.extract.push_back({"contact", {"a", "b"}, call("obb.contact", contact, 66)});
  auto inter = pair_args("a", "b");
  inter.push_back(arg("eps", rd::Value::num(tol.intersect_eps)));
  if (tol.vertical_eps > 0) inter.push_back(arg("vertical_eps", rd::Value::num(tol.vertical_eps)));
  c.extract.push_back({"intersect", {"a", "b"}, call("obb.intersect", inter, 67)});
  c.extract.push_back({"higher", {"a", "b"}, call("obb.higher", pair_args("a", "b"), 68)});
  c.extract.push_back({"hover", {"o"},
                       call("obb.hover", {arg("o", rd::Value::name("o")), arg("eps", rd::Value::num(tol.hover_eps))}, 69)});
  c.extract.push_back({"table", {"o"}, call("scene.is_table", {arg("o", rd::Value::name("o"))}, 70)});
  c.prior.push_back({{}, {}, call("mln", {}, 72)});
  c.likelihood.push_back(call("keypoints.gaussian",
                              {arg("sigma", rd::Value::num(1.0)), arg("robust", rd::Value::flag(tol.robust)),
                               arg("outlier_px", rd::Value::num(tol.outlier_px))}, 73));
  rd::Kernel k;
  k.name = "refine";
  k.reverse = "refine";
  k.params = {{"o", "object"}};
  k.sources = {call("pose.perturb", {arg("pose", idx("pose", "o")), arg("sigma_t", rd::Value::num(0.001)),
                                     arg("sigma_r", rd::Value::num(0.008726646259971648)),
                                     arg("candidates", rd::Value::num(20))}, 76)};
  k.where = "domains/tabletop.ksm:76";
  c.kernels.push_back(k);
  rd::ScheduleRow row;
  row.probabilities = {{"refine", 1.0}};
  c.schedule.push_back(row);
  return c;
}

}  // namespace ksmc::tests::tabletop_kit
