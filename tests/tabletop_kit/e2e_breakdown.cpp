// Error breakdown of the kit on the generated scenes of test_kit_e2e: for every object whose
// false/hidden decision disagrees with the generator's truth (or is undecided), the truth
// (false kind, hidden, true stability), the query probabilities, and the evidence the
// decision came from (at the input poses and at the reported state).
//
//   tabletop_e2e_breakdown [iterations=300] [scenes=50] [prior=map|log_z] [current_competes=1|0] [sigma_t_mm sigma_r_deg]
//                          [pose_sigma_mm pose_sigma_deg]  (KitOptions::pose_sigma_t/_r over the domain's estimate_sigma_*; 0 0: no pose term)
// KSMC_TTKIT_FITS=1 prints each object's keypoint fit against the truth and the lowest point of
// its box at the truth, the input, the fit and the reported state; with KSMC_TTKIT_LL=1 also
// its likelihood at those poses and the prior with the object moved to its fit.
// KSMC_TTKIT_LEANING=1 counts the objects with obb.leaning evidence (r25) at the input poses, by truth;
// =2 also lists each real tilted box without it, with the bodies within 3 cm.
// KSMC_TTKIT_PAIRS=1 tallies the pairs of intersecting objects that both rest on a face at the
// input poses, by truth, and which of the two is snugger (obb.snugger, r26).
// With KSMC_TTKIT_FAMILY=<family> the scenes are that noise-model family's (tools/tabletop_families,
// batch seed 2027, as tabletop_family_eval draws them; KSMC_TTKIT_SEED=<seed> another batch).
//
// A development tool for docs/tabletop_kit.md "Results", not a test.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <string>

#include <fmt/format.h>

#include "stdlib/tabletop/extract_higher.h"
#include "stdlib/tabletop/extract_stable.h"
#include "stdlib/tabletop/gap_noise.h"
#include "stdlib/tabletop/keypoint_fit.h"
#include "stdlib/tabletop/pair_geometry.h"
#include "stdlib/tabletop/scene_io.h"
#include "tools/tabletop_sim/generator.h"
#include "tools/tabletop_sim/scene_writer.h"
#include "tests/tabletop_kit/e2e_support.h"
#include "tools/tabletop_families/families.h"

using namespace ksmc::tests::tabletop_kit;
namespace sim = ksmc::tools::tabletop_sim;

namespace {

std::string flag(std::optional<bool> d) { return d ? (*d ? "T" : "f") : "?"; }

// Evidence summary of body b.
std::string describe(const tt::Evidence& ev, std::size_t b) {
  std::string s = fmt::format("st={} hov={}", ev.stable[b] ? 1 : 0, ev.hover[b] ? 1 : 0);
  if (b > 0)
    s += fmt::format(" gap={:.1f}mm", 1e3 * tt::rest_gap(std::span<const tt::Obb>(ev.boxes).subspan(1), b - 1, 10.0 / 57.29577951308232));
  std::string sup_by, sups, con, inter;
  for (std::size_t o = 0; o < ev.size(); ++o) {
    if (o == b) continue;
    const bool r10 = ev.contact[b][o] && ev.stable[b] && ev.stable[o];
    if (r10 && ev.higher[b][o]) sup_by += " " + ev.ids[o];
    else if (r10 && ev.higher[o][b]) sups += " " + ev.ids[o];
    else if (ev.contact[b][o]) {
      con += " " + ev.ids[o] + (ev.stable[o] ? "(st)" : "");
      if (ev.stable[b] && ev.stable[o] && ev.boxes[b].center.z() > ev.boxes[o].center.z())  // why not `higher`
        con += fmt::format("{{min_z {:.1f} mm, top of {} {:.1f} mm}}", 1e3 * ev.boxes[b].min_z(), ev.ids[o],
                           1e3 * ev.boxes[o].max_z());
    }
    if (ev.intersect[b][o]) {
      const tt::PairGeometry g = tt::pair_geometry(ev.boxes[b], ev.boxes[o]);
      inter += " " + ev.ids[o] + (ev.stable[o] ? "(st)" : "") +
               fmt::format("{{depth {:.1f} mm, dir_z {:.2f}{}}}", 1e3 * g.depth, std::abs(g.direction.z()),
                           g.stacked ? ", stacked" : "");
    }
  }
  s += " on[" + sup_by + " ] carries[" + sups + " ] touch[" + con + " ] cut[" + inter + " ]";
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  const std::uint64_t iters = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 300;
  const int n_scenes = argc > 2 ? std::atoi(argv[2]) : 50;
  kit::KitOptions options;
  if (argc > 3) options.prior_quantity = std::string(argv[3]) == "log_z" ? kit::PriorQuantity::log_z : kit::PriorQuantity::map;
  if (argc > 4) options.current_competes = std::atoi(argv[4]) != 0;
  if (argc > 8) {
    options.pose_sigma_t = 1e-3 * std::atof(argv[7]);
    options.pose_sigma_r = std::atof(argv[8]) / 57.29577951308232;
  }
  static blk::Binding binding = ksm_binding();
  if (argc > 6)  // sigma_t [mm], sigma_r [deg]
    for (auto& k : binding.kernels)
      for (auto& src : k.sources)
        if (auto* p = std::get_if<blk::PosePerturb>(&src)) {
          p->sigma_t = 1e-3 * std::atof(argv[5]);
          p->sigma_r = std::atof(argv[6]) / 57.29577951308232;
        }
  sim::GeneratorOptions opt;
  Score total;
  struct PoseError {
    double t = 0, z = 0, r = 0;
  } err[2];
  long err_count = 0;
  std::map<std::string, int> categories;
  std::map<std::string, std::pair<int, int>> leaning;  // truth class -> (objects, leaning at the input)
  std::map<std::string, int> pairs;                    // "truth: snugger verdict" -> pairs
  for (int i = 0; i < n_scenes; ++i) {
    const char* family = std::getenv("KSMC_TTKIT_FAMILY");
    namespace tf = ksmc::tools::tabletop_families;
    const char* batch = std::getenv("KSMC_TTKIT_SEED");
    const std::uint64_t batch_seed = batch ? std::strtoull(batch, nullptr, 10) : 2027;
    const auto g = family ? tf::generate(tf::family(family), tf::family_scene_seed(tf::family(family), batch_seed, static_cast<std::uint64_t>(i)))
                          : sim::generate_scene(sim::scene_seed(2026, static_cast<std::uint64_t>(i)), opt);
    auto load = tt::parse_scene(nlohmann::json::parse(sim::scene_json(g)), "scene", ".");
    const auto scene = std::make_shared<const tt::Scene>(std::move(load.scene));
    const auto truth = nlohmann::json::parse(sim::truth_json(g));
    const tt::TabletopResult r0 = run_kit(binding, scene, 0, 1 + static_cast<std::uint64_t>(i), options);
    const tt::TabletopResult r = iters == 0 ? r0 : run_kit(binding, scene, iters, 1 + static_cast<std::uint64_t>(i), options);
    score(r, truth, total);
    std::cout << fmt::format("s{:02} vertical tolerance {:.1f} mm\n", i, 1e3 * blk::Scene(*scene).vertical_tolerance());
    if (std::getenv("KSMC_TTKIT_FITS"))  // keypoint fits (keypoint_fit.h) against the true poses
      for (const auto& o : g.objects) {
        const int idx = r.scene.find(o.id);
        const auto fit = tt::fit_keypoints(*scene, scene->objects[static_cast<std::size_t>(idx)]);
        if (!fit.ok) continue;
        const Eigen::Vector3d d = fit.mean.t - o.clean_pose.t;
        const auto& so = scene->objects[static_cast<std::size_t>(idx)];
        const auto& reported = r.scene.objects[static_cast<std::size_t>(idx)].pose;
        auto lowest = [&so](const auto& p) { return 1e3 * tt::Obb::from_pose(tt::Pose{p.t, p.q}, so.size).min_z(); };
        std::cout << fmt::format("fit {} kp {} inl {}: |dt| {:.2f} mm dz {:.2f} mm rot {:.2f} deg; sd t {:.2f} {:.2f} {:.2f} mm bottom {:.2f} mm; "
                                 "lowest z true {:.1f} input {:.1f} fit {:.1f} reported {:.1f} mm\n",
                                 o.id, so.keypoints_model.size(), fit.inliers,
                                 1e3 * d.norm(), 1e3 * d.z(), 57.29578 * Eigen::AngleAxisd(fit.mean.q * o.clean_pose.q.conjugate()).angle(),
                                 1e3 * std::sqrt(fit.covariance(0, 0)), 1e3 * std::sqrt(fit.covariance(1, 1)),
                                 1e3 * std::sqrt(fit.covariance(2, 2)), 1e3 * fit.bottom_sigma, lowest(o.clean_pose), lowest(so.pose),
                                 lowest(fit.mean), lowest(reported));
        if (std::getenv("KSMC_TTKIT_LL")) {
          kit::TabletopModel m(scene, binding, options);  // at the reported state
          const auto i_obj = static_cast<std::size_t>(idx);
          for (std::size_t j = 0; j < r.scene.objects.size(); ++j) {
            m.begin_move(j, r.scene.objects[j].pose, std::nan(""));
            m.accept();
          }
          const double prior_rep = m.log_prior();
          m.begin_move(i_obj, fit.mean, std::nan(""));
          const double prior_fit = m.log_prior();
          m.reject();
          std::cout << fmt::format("    likelihood input {:.1f} fit {:.1f} reported {:.1f}; prior at reported {:.2f}, "
                                   "with this object at its fit {:.2f}\n",
                                   m.object_log_likelihood_at(i_obj, so.pose), m.object_log_likelihood_at(i_obj, fit.mean),
                                   m.object_log_likelihood_at(i_obj, reported), prior_rep, prior_fit);
        }
      }
    if (std::getenv("KSMC_TTKIT_LEANING")) {  // obb.leaning (r25) at the input poses, by truth
      const blk::Scene bs(*scene);
      for (const auto& o : g.objects) {
        const auto body = blk::Scene::body_of_object(static_cast<std::size_t>(r.scene.find(o.id)));
        const std::string cls = o.false_kind != sim::FalseKind::none ? "false " + std::string(sim::to_string(o.false_kind))
                                : o.stable                          ? "real, resting on a face"
                                                                    : "real, tilted";
        auto& [n, lean] = leaning[cls];
        ++n;
        const bool leans = blk::obb::leaning(bs, body, 10.0 / 57.29577951308232, 0.004);
        lean += leans ? 1 : 0;
        if (!leans && cls == "real, tilted" && std::string(std::getenv("KSMC_TTKIT_LEANING")) == "2") {
          // Why not: every body within 3 cm, its gap (negative: cut depth), tilt, above/below.
          const tt::Obb& box = bs.box(body);
          std::string near;
          for (std::size_t j = 0; j < bs.bodies(); ++j) {
            const auto b = static_cast<std::int32_t>(j);
            if (b == body) continue;
            const auto geo = tt::pair_geometry(box, bs.box(b), 0.05);
            if (geo.distance > 0.03) continue;
            const auto corners = box.vertices();
            const Eigen::Vector3d low = *std::min_element(corners.begin(), corners.end(), [](const auto& x, const auto& y) { return x.z() < y.z(); });
            const Eigen::Vector2d falls = (box.center - low).head<2>();
            const double side = (bs.box(b).closest_point(box.center) - box.center).head<2>().dot(falls.normalized());
            near += fmt::format(" [{} {} {:.1f}mm tilt {:.0f}{} side {:.0f}mm]", bs.is_table(b) ? std::string("table") : r.scene.objects[static_cast<std::size_t>(b - 1)].id,
                                geo.overlapping ? "cut" : "gap", 1e3 * (geo.overlapping ? -geo.depth : geo.distance),
                                57.29578 * tt::tilt_angle(bs.box(b)), tt::extract_higher(box, bs.box(b), tt::EvidenceParams{}) ? " under" : "", 1e3 * side);
          }
          std::string truth_touch;  // the true contacts of its physical box, undetected ones marked
          for (const auto& [a, b] : g.relations.contact) {
            if (a != o.physical && b != o.physical) continue;
            const int other = a == o.physical ? b : a;
            truth_touch += other < 0 ? " table" : fmt::format(" p{}{}", other, g.physical[static_cast<std::size_t>(other)].undetected ? "(undetected)" : "");
          }
          near += "; true contacts:" + truth_touch;
          std::cout << fmt::format("not leaning s{:02} {}: tilt {:.1f} (true {:.1f}) deg;{}\n", i, o.id, 57.29578 * tt::tilt_angle(box),
                                   57.29578 * tt::tilt_angle(tt::Obb::from_pose(tt::Pose{o.clean_pose.t, o.clean_pose.q}, 2.0 * box.half)), near);
        }
      }
    }
    if (std::getenv("KSMC_TTKIT_PAIRS")) {  // obb.snugger (r26) at the input poses, by truth
      const blk::Scene bs(*scene);
      const tt::Evidence& ev = r0.evidence;
      for (std::size_t ka = 0; ka < g.objects.size(); ++ka)
        for (std::size_t kb = ka + 1; kb < g.objects.size(); ++kb) {
          const auto ia = static_cast<std::size_t>(r.scene.find(g.objects[ka].id));
          const auto ib = static_cast<std::size_t>(r.scene.find(g.objects[kb].id));
          const auto a = tt::Evidence::body(ia), b = tt::Evidence::body(ib);
          if (!ev.intersect[a][b] || !ev.stable[a] || !ev.stable[b]) continue;
          const bool fa = g.objects[ka].false_kind != sim::FalseKind::none;
          const bool fb = g.objects[kb].false_kind != sim::FalseKind::none;
          const auto ba = static_cast<std::int32_t>(a), bb = static_cast<std::int32_t>(b);
          const bool ab = blk::obb::snugger(bs, ba, bb, 0.004, 1.0), ba_ = blk::obb::snugger(bs, bb, ba, 0.004, 1.0);
          std::string cls, verdict = ab || ba_ ? "one is snugger" : "neither is snugger";
          if (fa != fb) {
            cls = "one real, one false";
            if (ab || ba_) verdict = (ab ? !fa : !fb) ? "the real one is snugger" : "the false one is snugger";
          } else {
            cls = fa ? "both false" : "both real";
          }
          ++pairs[cls + ": " + verdict];
        }
    }
    for (const auto& o : g.objects) {  // pose errors of real objects, input and reported state
      if (o.false_kind != sim::FalseKind::none) continue;
      const int idx = r.scene.find(o.id);
      for (int which = 0; which < 2; ++which) {
        const auto& est = (which == 0 ? r0 : r).scene.objects[static_cast<std::size_t>(idx)].pose;
        const Eigen::Vector3d d = est.t - o.clean_pose.t;
        err[which].t += d.norm();
        err[which].z += std::abs(d.z());
        err[which].r += Eigen::AngleAxisd(est.q * o.clean_pose.q.conjugate()).angle();
      }
      ++err_count;
    }
    for (std::size_t k = 0; k < g.objects.size(); ++k) {
      const auto& o = g.objects[k];
      const int idx = r.scene.find(o.id);
      const auto& p = r.probabilities[static_cast<std::size_t>(idx)];
      const auto& p0 = r0.probabilities[static_cast<std::size_t>(idx)];
      const auto f = tt::decide(p.false_prob), h = tt::decide(p.hidden_prob);
      const bool is_false = o.false_kind != sim::FalseKind::none;
      const bool f_ok = f && *f == is_false, h_ok = h && *h == o.hidden;
      if (f_ok && h_ok) continue;
      std::string cat;
      if (!f_ok) cat += is_false ? fmt::format("false-FN:{}", sim::to_string(o.false_kind)) : (f ? "false-FP" : "false-undecided");
      if (!h_ok) cat += std::string(cat.empty() ? "" : "+") + (o.hidden ? "hidden-FN" : (h ? "hidden-FP" : "hidden-undecided"));
      ++categories[cat];
      const std::size_t b = tt::Evidence::body(static_cast<std::size_t>(idx));
      std::cout << fmt::format("s{:02} {:7} {:<40} truth F={} H={} st={} | f={:.2f}{} h={:.2f}{} (input f={:.2f} h={:.2f})\n",
                               i, o.id, cat, is_false ? 1 : 0, o.hidden ? 1 : 0, o.stable ? 1 : 0, p.false_prob,
                               flag(f), p.hidden_prob, flag(h), p0.false_prob, p0.hidden_prob);
      std::cout << "      input: " << describe(r0.evidence, b) << "\n";
      if (iters > 0) std::cout << "      final: " << describe(r.evidence, b) << "\n";
    }
  }
  for (int which = 0; which < 2; ++which)
    std::cout << fmt::format("{} poses of real objects: mean |dt| {:.2f} mm, |dz| {:.2f} mm, rotation {:.2f} deg\n",
                             which == 0 ? "input" : "reported", 1e3 * err[which].t / err_count,
                             1e3 * err[which].z / err_count, 57.29578 * err[which].r / err_count);
  std::cout << "\n" << table(total) << "\ncategories:\n";
  for (const auto& [c, n] : categories) std::cout << fmt::format("  {:4} {}\n", n, c);
  if (!leaning.empty()) std::cout << "\nleaning at the input poses (KSMC_TTKIT_LEANING):\n";
  for (const auto& [c, v] : leaning) std::cout << fmt::format("  {:4} of {:4} {}\n", v.second, v.first, c);
  if (!pairs.empty()) std::cout << "\nintersecting pairs resting on a face, at the input poses (KSMC_TTKIT_PAIRS):\n";
  for (const auto& [c, n] : pairs) std::cout << fmt::format("  {:4} {}\n", n, c);
  return 0;
}
