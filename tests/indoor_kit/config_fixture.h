// Hand-built DomainConfig mirroring domains/indoor.ksm exactly (base units: 10 m = 10.0,
// 5 deg = 0.08726646259971647 rad, 2 deg = 0.03490658503988659 rad, cells as written),
// defaults of stdlib/indoor.ksm filled in; stands in for the generated indoor_model.cpp.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "runtime/domain/config.h"

namespace ksmc::tests::indoor_kit {

namespace rd = ksmc::runtime::domain;

inline rd::Arg arg(std::string name, rd::Value v) { return rd::Arg{std::move(name), std::move(v)}; }
inline rd::Value unit_of(const std::string& var) { return rd::Value::index("unit", {rd::Value::name(var)}); }
inline rd::Call call(std::string name, std::vector<rd::Arg> args, int line) {
  return rd::Call{std::move(name), std::move(args), "domains/indoor.ksm:" + std::to_string(line)};
}
inline rd::Value table(std::vector<std::vector<double>> rows) {
  std::vector<rd::Value> out;
  for (const auto& r : rows) {
    std::vector<rd::Value> items;
    for (double x : r) items.push_back(rd::Value::num(x));
    out.push_back(rd::Value::list(std::move(items)));
  }
  return rd::Value::list(std::move(out));
}

inline rd::DomainConfig indoor_config() {
  rd::DomainConfig c;
  c.domain = "indoor";
  c.source = "domains/indoor.ksm";
  c.model = {{"unit", true, "", "rect", true}, {"door", true, "", "segment", true}};
  auto cls = [](const std::string& fn, int line) {
    return call(fn, {arg("u", unit_of("u")), arg("big_size", rd::Value::num(10.0)), arg("big_ratio", rd::Value::num(3.0))}, line);
  };
  c.extract.push_back({"RoLi", {"u"}, cls("geom.room_like", 33)});
  c.extract.push_back({"CoLi", {"u"}, cls("geom.corridor_like", 34)});
  c.extract.push_back({"HaLi", {"u"}, cls("geom.hall_like", 35)});
  c.extract.push_back({"Adj", {"a", "b"},
                       call("geom.adjacent", {arg("a", unit_of("a")), arg("b", unit_of("b")), arg("dilate", rd::Value::num(2.0))}, 37)});
  c.extract.push_back({"MulDoor", {"u"},
                       call("geom.multi_door", {arg("u", unit_of("u")), arg("doors", rd::Value::name("door")),
                                                arg("min_doors", rd::Value::num(2.0))}, 38)});

  c.prior.push_back({{}, {}, call("rect_penalty", {arg("psi1", rd::Value::num(1.0)), arg("tol", rd::Value::num(0.08726646259971647))}, 41)});
  c.prior.push_back({{}, {}, call("overlap_penalty", {arg("psi2", rd::Value::num(1.0))}, 42)});
  {
    rd::Condition cond;
    cond.probability = true;
    cond.predicate = "SaLe";
    cond.args = {"a", "b"};
    cond.op = ">";
    cond.threshold = 0.5;
    rd::Value x = rd::Value::call("wall_length_diff", {unit_of("a"), unit_of("b")});
    c.prior.push_back({{"a", "b"}, {cond}, call("gaussian", {arg("x", x), arg("sigma", rd::Value::num(0.3))}, 43)});
  }

  c.likelihood.push_back(call("grid.occupancy",
                              {arg("lut", table({{0.8, 0.1, 0.1}, {0.1, 0.8, 0.1}, {0.1, 0.1, 0.8}})),
                               arg("lenient_types", rd::Value::set({rd::Value::name("Room"), rd::Value::name("Hall")})),
                               arg("lenient_lut", table({{0.6, 0.3, 0.1}, {0.2, 0.6, 0.2}, {0.1, 0.3, 0.6}}))},
                              47));

  const std::vector<rd::Call> add_src = {
      call("detect.wbu", {arg("min_size", rd::Value::num(1.5)), arg("max_units", rd::Value::num(200))}, 51),
      call("detect.fsu", {arg("after", rd::Value::num(4000)), arg("min_area_cells", rd::Value::num(100))}, 52),
      call("detect.rpb", {arg("min_size", rd::Value::num(1.0))}, 53)};
  const std::vector<rd::Call> split_src = {
      call("detect.split_lines", {arg("min_votes", rd::Value::num(20)), arg("angle_tol", rd::Value::num(0.03490658503988659))}, 55),
      call("partner.inverse_distance", {}, 56)};
  const std::vector<rd::Call> shrink_src = {call("move.wall_shift", {arg("sigma", rd::Value::num(2.0))}, 57)};
  const std::vector<rd::Call> door_src = {
      call("detect.doors", {arg("min_width", rd::Value::num(0.6)), arg("max_width", rd::Value::num(2.0))}, 58)};
  const std::vector<rd::Call> inter_src = {call("partner.inverse_distance", {}, 59)};
  auto pair = [&](const std::string& a, const std::string& b, const std::vector<rd::Call>& src, int line) {
    const std::string where = "domains/indoor.ksm:" + std::to_string(line);
    c.kernels.push_back({a, b, {}, src, where});
    c.kernels.push_back({b, a, {}, src, where});
  };
  pair("ADD", "REMOVE", add_src, 50);
  pair("SPLIT", "MERGE", split_src, 54);
  pair("SHRINK", "DILATE", shrink_src, 57);
  pair("ALLOCATE", "DELETE", door_src, 58);
  c.kernels.push_back({"INTERCHANGE", "INTERCHANGE", {}, inter_src, "domains/indoor.ksm:59"});

  c.schedule.push_back({0, 1000, {{"ADD", 0.9}, {"REMOVE", 0.1}}});
  c.schedule.push_back({1000, 4000, {{"ADD", 0.05}, {"REMOVE", 0.15}, {"SPLIT", 0.15}, {"MERGE", 0.15},
                                     {"SHRINK", 0.2}, {"DILATE", 0.2}, {"INTERCHANGE", 0.1}}});
  c.schedule.push_back({4000, rd::ScheduleRow::kForever,
                        {{"ADD", 0.05}, {"REMOVE", 0.1}, {"SPLIT", 0.1}, {"MERGE", 0.1}, {"SHRINK", 0.15},
                         {"DILATE", 0.15}, {"INTERCHANGE", 0.1}, {"ALLOCATE", 0.125}, {"DELETE", 0.125}}});
  return c;
}

}  // namespace ksmc::tests::indoor_kit
