// Bindings of domains/tabletop.ksm for the tests: the generated one (tabletop_model.cpp, what
// bin/tabletop runs) and a copy written as `ksmc emit` writes it (docs/binding.md §3) with the
// extract tolerances and likelihood settings as a type parameter, so the tests can also run
// the seed's literal values (the calibration in docs/tabletop_kit.md) and variants.
#pragma once

#include <cstdint>

#include "stdlib/tabletop/blocks.h"
#include "tabletop_factors.h"
#include "tabletop_model.h"

namespace ksmc::tests::tabletop_kit {

namespace blk = ksmc::stdlib::tabletop::blocks;
namespace gen = ksmc_generated::tabletop;

// domains/tabletop.ksm (10 deg, 4 mm, 5 mm, 4 mm; robust Gaussian, 5 px; overlap 0.5 of the
// smaller box, flatter by 0.5 deg; overhang within 4 mm, beyond 5 mm; leaning beyond 10 deg,
// within 4 mm; snugger within 4 mm, by one sigma of gap noise; blocks by a 6 mm margin, 3
// keypoints and a tenth of them; hides by a 6 mm margin, 3 keypoints expected; tilted beyond
// 3 sigma of the scene's tilt noise and 2 deg; sunk beyond 1.5 sigma of its gap noise and 4 mm; the pose
// estimate as a measurement, 3 mm / 1.5 deg).
struct KsmValues {
  static constexpr double stable_tol = 0.17453292519943295;
  static constexpr double contact_eps = 0.004;
  static constexpr double intersect_eps = 0.005;
  static constexpr double hover_eps = 0.004;
  static constexpr bool robust = true;
  static constexpr double outlier_px = 5.0;
  static constexpr double overlap_fraction = 0.5;
  static constexpr double flatter_margin = 0.008726646259971648;
  static constexpr double overhang_eps = 0.004;
  static constexpr double overhang_margin = 0.005;
  static constexpr double leaning_tol = 0.17453292519943295;  // 10 deg
  static constexpr double leaning_eps = 0.004;
  static constexpr double snugger_eps = 0.004;
  static constexpr double snugger_margin = 1.0;  // sigmas of the scene's gap noise
  static constexpr double blocks_margin = 0.006;
  static constexpr int blocks_min_keypoints = 3;
  static constexpr double blocks_min_fraction = 0.1;
  static constexpr double hides_margin = 0.006;
  static constexpr double hides_min_expected = 3.0;
  static constexpr double tilted_k = 3.0;
  static constexpr double tilted_min = 0.03490658503988659;  // 2 deg
  static constexpr double sunk_k = 1.5;
  static constexpr double sunk_min = 0.004;
  static constexpr double estimate_sigma_t = 0.003;                   // 3 mm
  static constexpr double estimate_sigma_r = 0.026179938779914945;    // 1.5 deg
  static constexpr bool sigma_from_scene = true;
  // kernel fit = pose.fit(scale = 1, estimate_scale = 2), scheduled with this probability.
  static constexpr double fit_share = 0.2;
  static constexpr double fit_scale = 1.0;
  static constexpr double fit_estimate_scale = 2.0;
};

// A literal reading of the seed: 3 deg, 4 mm, 4 mm, plain Gaussian (sigma 1 px). The seed has
// no overlap / flatter / overhang / leaning / snugger / blocks / hides / tilted evidence; the
// domain file's values serve its rules r23-r26 and r28-r31.
struct SeedValues {
  static constexpr double stable_tol = 0.05235987755982988;
  static constexpr double contact_eps = 0.004;
  static constexpr double intersect_eps = 0.004;
  static constexpr double hover_eps = 0.004;
  static constexpr bool robust = false;
  static constexpr double outlier_px = 20.0;
  static constexpr double overlap_fraction = KsmValues::overlap_fraction;
  static constexpr double flatter_margin = KsmValues::flatter_margin;
  static constexpr double overhang_eps = KsmValues::overhang_eps;
  static constexpr double overhang_margin = KsmValues::overhang_margin;
  static constexpr double leaning_tol = KsmValues::leaning_tol;
  static constexpr double leaning_eps = KsmValues::leaning_eps;
  static constexpr double snugger_eps = KsmValues::snugger_eps;
  static constexpr double snugger_margin = KsmValues::snugger_margin;
  static constexpr double blocks_margin = KsmValues::blocks_margin;
  static constexpr int blocks_min_keypoints = KsmValues::blocks_min_keypoints;
  static constexpr double blocks_min_fraction = KsmValues::blocks_min_fraction;
  static constexpr double hides_margin = KsmValues::hides_margin;
  static constexpr double hides_min_expected = KsmValues::hides_min_expected;
  static constexpr double tilted_k = KsmValues::tilted_k;
  static constexpr double tilted_min = KsmValues::tilted_min;
  static constexpr double sunk_k = KsmValues::sunk_k;
  static constexpr double sunk_min = KsmValues::sunk_min;
  static constexpr double estimate_sigma_t = KsmValues::estimate_sigma_t;  // not in the seed either
  static constexpr double estimate_sigma_r = KsmValues::estimate_sigma_r;
  static constexpr bool sigma_from_scene = false;  // the seed's fixed 1 px
  static constexpr double fit_share = 0.0;  // the seed's refine move alone
  static constexpr double fit_scale = KsmValues::fit_scale;
  static constexpr double fit_estimate_scale = KsmValues::fit_estimate_scale;
};

// The generated program's predicate named `name`, or -1.
inline std::int32_t predicate_named(const char* name) {
  const auto& predicates = gen::program().predicates;
  for (std::size_t i = 0; i < predicates.size(); ++i)
    if (predicates[i].name == name) return static_cast<std::int32_t>(i);
  return -1;
}

template <class V>
struct Fixture {
  static bool stable(const blk::Scene& s, const std::int32_t* c) {
    return blk::obb::stable(s, s.se3(c[0]), s.vec3(c[0]), V::stable_tol);
  }
  static bool contact(const blk::Scene& s, const std::int32_t* c) {
    return blk::obb::contact(s, s.se3(c[0]), s.vec3(c[0]), s.se3(c[1]), s.vec3(c[1]), V::contact_eps);
  }
  static bool intersect(const blk::Scene& s, const std::int32_t* c) {
    return blk::obb::intersect(s, s.se3(c[0]), s.vec3(c[0]), s.se3(c[1]), s.vec3(c[1]), V::intersect_eps);
  }
  static bool higher(const blk::Scene& s, const std::int32_t* c) {
    return blk::obb::higher(s, s.se3(c[0]), s.vec3(c[0]), s.se3(c[1]), s.vec3(c[1]));
  }
  static bool hover(const blk::Scene& s, const std::int32_t* c) { return blk::obb::hover(s, c[0], V::hover_eps); }
  static bool overlap(const blk::Scene& s, const std::int32_t* c) {
    return blk::obb::overlap(s, s.se3(c[0]), s.vec3(c[0]), s.se3(c[1]), s.vec3(c[1]), V::overlap_fraction);
  }
  static bool flatter(const blk::Scene& s, const std::int32_t* c) {
    return blk::obb::flatter(s, s.se3(c[0]), s.vec3(c[0]), s.se3(c[1]), s.vec3(c[1]), V::flatter_margin);
  }
  static bool overhang(const blk::Scene& s, const std::int32_t* c) {
    return blk::obb::overhang(s, c[0], V::overhang_eps, V::overhang_margin);
  }
  static bool leaning(const blk::Scene& s, const std::int32_t* c) {
    return blk::obb::leaning(s, c[0], V::leaning_tol, V::leaning_eps);
  }
  static bool snugger(const blk::Scene& s, const std::int32_t* c) {
    return blk::obb::snugger(s, c[0], c[1], V::snugger_eps, V::snugger_margin);
  }
  static bool blocks(const blk::Scene& s, const std::int32_t* c) {
    return blk::obb::blocks(s, s.se3(c[0]), s.vec3(c[0]), s.se3(c[1]), s.vec3(c[1]), V::blocks_margin,
                            V::blocks_min_keypoints, V::blocks_min_fraction);
  }
  static bool hides(const blk::Scene& s, const std::int32_t* c) {
    return blk::obb::hides(s, s.se3(c[0]), s.vec3(c[0]), s.se3(c[1]), s.vec3(c[1]), V::hides_margin,
                           V::hides_min_expected);
  }
  static bool tilted(const blk::Scene& s, const std::int32_t* c) {
    return blk::obb::tilted(s, s.se3(c[0]), s.vec3(c[0]), V::tilted_k, V::tilted_min);
  }
  static bool sunk(const blk::Scene& s, const std::int32_t* c) {
    return blk::obb::sunk(s, s.se3(c[0]), s.vec3(c[0]), V::sunk_k, V::sunk_min);
  }
  static bool table(const blk::Scene& s, const std::int32_t* c) { return blk::scene::is_table(s, c[0]); }

  static blk::Binding make(bool decisions = true) {
    blk::Binding b;
    b.domain = "tabletop";
    b.source = "domains/tabletop.ksm";
    b.mln = {&gen::program, &gen::make_domain, &gen::ground};
    b.constant_type = gen::kType_object;
    b.extractors.push_back({gen::kPred_stable, &stable, "extract stable(o) = obb.stable(...)"});
    b.extractors.push_back({gen::kPred_contact, &contact, "extract contact(a, b) = obb.contact(...)"});
    b.extractors.push_back({gen::kPred_intersect, &intersect, "extract intersect(a, b) = obb.intersect(...)"});
    b.extractors.push_back({gen::kPred_higher, &higher, "extract higher(a, b) = obb.higher(...)"});
    b.extractors.push_back({gen::kPred_hover, &hover, "extract hover(o) = obb.hover(o, ...)"});
    // By name: the learned copy of an older domain file (bench/tabletop/tabletop_learned.ksm,
    // tabletop_family_eval_learned) declares none of them.
    if (const std::int32_t p = predicate_named("overlap"); p >= 0)
      b.extractors.push_back({p, &overlap, "extract overlap(a, b) = obb.overlap(...)"});
    if (const std::int32_t p = predicate_named("flatter"); p >= 0)
      b.extractors.push_back({p, &flatter, "extract flatter(a, b) = obb.flatter(...)"});
    if (const std::int32_t p = predicate_named("overhang"); p >= 0)
      b.extractors.push_back({p, &overhang, "extract overhang(o) = obb.overhang(o, ...)"});
    if (const std::int32_t p = predicate_named("leaning"); p >= 0)
      b.extractors.push_back({p, &leaning, "extract leaning(o) = obb.leaning(o, ...)"});
    if (const std::int32_t p = predicate_named("snugger"); p >= 0)
      b.extractors.push_back({p, &snugger, "extract snugger(a, b) = obb.snugger(a, b, ...)"});
    if (const std::int32_t p = predicate_named("blocks"); p >= 0)
      b.extractors.push_back({p, &blocks, "extract blocks(a, b) = obb.blocks(...)"});
    if (const std::int32_t p = predicate_named("hides"); p >= 0)
      b.extractors.push_back({p, &hides, "extract hides(a, b) = obb.hides(...)"});
    if (const std::int32_t p = predicate_named("tilted"); p >= 0)
      b.extractors.push_back({p, &tilted, "extract tilted(o) = obb.tilted(...)"});
    if (const std::int32_t p = predicate_named("sunk"); p >= 0)
      b.extractors.push_back({p, &sunk, "extract sunk(o) = obb.sunk(...)"});
    b.extractors.push_back({gen::kPred_table, &table, "extract table(o) = scene.is_table(o)"});
    b.priors.push_back(blk::mln());
    b.likelihood = blk::keypoints::gaussian(1.0, V::robust, V::outlier_px, V::estimate_sigma_t, V::estimate_sigma_r,
                                            V::sigma_from_scene);
    b.likelihood *= blk::cloud::surface(0.004, true, 0.02, 0.0, 0.02, 0.005);
    if (decisions) b.outputs.push_back(blk::scene::decisions(gen::kPred_falseEst, gen::kPred_hidden));
    b.kernels.push_back({"refine", "refine", blk::Move::perturb, {blk::pose::perturb(0.001, 0.008726646259971648, 20)},
                         "kernel refine(o: object) reverse refine = pose.perturb(...)"});
    if (V::fit_share > 0.0) {
      b.kernels.push_back({"fit", "fit", blk::Move::fit, {blk::pose::fit(V::fit_scale, V::fit_estimate_scale)},
                           "kernel fit(o: object) reverse fit = pose.fit(...)"});
      b.schedule.push_back({0, ksmc::runtime::domain::ScheduleRow::kForever,
                            {{"refine", 1.0 - V::fit_share}, {"fit", V::fit_share}}});
    } else {
      b.schedule.push_back({0, ksmc::runtime::domain::ScheduleRow::kForever, {{"refine", 1.0}}});
    }
    return b;
  }
};

// Long-lived bindings (a model keeps a reference). ksm_binding() is the generated one.
inline const blk::Binding& ksm_binding() { return ksmc_generated::tabletop::binding(); }
inline const blk::Binding& ksm_fixture_binding() {
  static const blk::Binding b = Fixture<KsmValues>::make();
  return b;
}
inline const blk::Binding& seed_binding() {
  static const blk::Binding b = Fixture<SeedValues>::make();
  return b;
}
inline const blk::Binding& no_decisions_binding() {
  static const blk::Binding b = Fixture<KsmValues>::make(false);
  return b;
}

}  // namespace ksmc::tests::tabletop_kit
