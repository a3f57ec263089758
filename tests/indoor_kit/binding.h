// The binding of domains/indoor.ksm written by hand as `ksmc emit` generates it
// (docs/binding.md §3), over the generated Markov logic part (indoor_factors.h): lets the kit
// tests build variants of the shipped domain (other kernels, schedules, lenient types).
#pragma once

#include <cstdint>

#include "indoor_factors.h"
#include "stdlib/indoor/blocks.h"

namespace ksmc::tests::indoor_kit {

namespace blk = ksmc::stdlib::indoor::blocks;
namespace dom = ksmc::runtime::domain;
namespace gen = ksmc_generated::indoor;

inline bool extract_RoLi(const blk::Scene& s, const std::int32_t* c) { return blk::geom::room_like(s, s.rect(c[0]), 10.0, 3.0); }
inline bool extract_CoLi(const blk::Scene& s, const std::int32_t* c) { return blk::geom::corridor_like(s, s.rect(c[0]), 10.0, 3.0); }
inline bool extract_HaLi(const blk::Scene& s, const std::int32_t* c) { return blk::geom::hall_like(s, s.rect(c[0]), 10.0, 3.0); }
inline bool extract_Adj(const blk::Scene& s, const std::int32_t* c) { return blk::geom::adjacent(s, s.rect(c[0]), s.rect(c[1]), 2.0); }
inline bool extract_MulDoor(const blk::Scene& s, const std::int32_t* c) { return blk::geom::multi_door(s, s.rect(c[0]), s.segments(), 2); }
inline double prior_SaLe_gaussian(const blk::Scene& s, const std::int32_t* c) {
  return blk::gaussian(s, blk::wall_length_diff(s, s.rect(c[0]), s.rect(c[1])), 0.3);
}

inline blk::Binding indoor_binding() {
  blk::Binding b;
  b.domain = "indoor";
  b.source = "domains/indoor.ksm";
  b.mln = {&gen::program, &gen::make_domain, &gen::ground};
  b.constant_type = gen::kType_unit;
  b.extractors.push_back({gen::kPred_RoLi, &extract_RoLi, "extract RoLi(u) = geom.room_like(unit[u], big_size = 10 m, big_ratio = 3.0);"});
  b.extractors.push_back({gen::kPred_CoLi, &extract_CoLi, "extract CoLi(u) = geom.corridor_like(unit[u], big_size = 10 m, big_ratio = 3.0);"});
  b.extractors.push_back({gen::kPred_HaLi, &extract_HaLi, "extract HaLi(u) = geom.hall_like(unit[u], big_size = 10 m, big_ratio = 3.0);"});
  b.extractors.push_back({gen::kPred_Adj, &extract_Adj, "extract Adj(a, b) = geom.adjacent(unit[a], unit[b], dilate = 2 cells);"});
  b.extractors.push_back({gen::kPred_MulDoor, &extract_MulDoor, "extract MulDoor(u) = geom.multi_door(unit[u], door, min_doors = 2);"});
  b.priors.push_back(blk::rect_penalty(1.0, 0.087266462599716474));
  b.priors.push_back(blk::overlap_penalty(1.0));
  b.conditional_priors.push_back({{gen::kType_unit, gen::kType_unit},
                                  {{true, gen::kPred_SaLe, {0, 1}, dom::Cmp::gt, 0.5, false}},
                                  &prior_SaLe_gaussian,
                                  "prior for a, b where P(SaLe(a, b)) > 0.5: gaussian(wall_length_diff(unit[a], unit[b]), sigma = 0.3 m);"});
  b.likelihood = blk::grid::occupancy({{0.8, 0.1, 0.1}, {0.1, 0.8, 0.1}, {0.1, 0.1, 0.8}}, {gen::kPred_Room, gen::kPred_Hall},
                                      {{0.6, 0.3, 0.1}, {0.2, 0.6, 0.2}, {0.1, 0.3, 0.6}});
  auto pair = [&b](const char* fwd, const char* rev, blk::Move f, blk::Move r, std::vector<blk::Source> src) {
    b.kernels.push_back({fwd, rev, f, src, std::string("kernel pair ") + fwd + " / " + rev});
    b.kernels.push_back({rev, fwd, r, std::move(src), std::string("kernel pair ") + fwd + " / " + rev});
  };
  pair("ADD", "REMOVE", blk::Move::birth, blk::Move::death,
       {blk::detect::wbu(1.5, 200), blk::detect::fsu(4000, 100), blk::detect::rpb(1.0)});
  pair("SPLIT", "MERGE", blk::Move::split, blk::Move::merge, {blk::detect::split_lines(20, 0.034906585039886591), blk::partner::inverse_distance()});
  pair("SHRINK", "DILATE", blk::Move::shrink, blk::Move::dilate, {blk::move::wall_shift(2.0)});
  pair("ALLOCATE", "DELETE", blk::Move::allocate, blk::Move::deallocate, {blk::detect::doors(0.6, 2.0)});
  b.kernels.push_back({"INTERCHANGE", "INTERCHANGE", blk::Move::interchange, {blk::move::interchange(), blk::partner::inverse_distance()},
                       "kernel INTERCHANGE reverse INTERCHANGE = move.interchange(), partner.inverse_distance();"});
  b.schedule.push_back({0, 1000, {{"ADD", 0.9}, {"REMOVE", 0.1}}});
  b.schedule.push_back({1000, 4000, {{"ADD", 0.05}, {"REMOVE", 0.15}, {"SPLIT", 0.15}, {"MERGE", 0.15},
                                     {"SHRINK", 0.2}, {"DILATE", 0.2}, {"INTERCHANGE", 0.1}}});
  b.schedule.push_back({4000, dom::ScheduleRow::kForever,
                        {{"ADD", 0.05}, {"REMOVE", 0.1}, {"SPLIT", 0.1}, {"MERGE", 0.1}, {"SHRINK", 0.15},
                         {"DILATE", 0.15}, {"INTERCHANGE", 0.1}, {"ALLOCATE", 0.125}, {"DELETE", 0.125}}});
  return b;
}

}  // namespace ksmc::tests::indoor_kit
