// ksmc-perception-sim [--scenes N] [--objects A..B] [--seed S] [--sigma M] [--missing R] [--stride K] [--upright]
//                     [--footprint-only] [--fixed-tolerance] [--isotropic] [--no-shadow-merge] [--whole-faces]
//                     [--no-side-steps] [--no-hidden-bottom] [--no-hidden-reach] [--no-tilted-foot] [--no-lean-seat]
//                     [--no-seen-under] [--no-occluded-gap]
//                     [--whole-tops] [--no-centre-support] [--no-shadow-rest] [--no-close-gap] [--keep-strips] [--visible V] [--verbose] [--dump DIR]
// Renders depth clouds of generated scenes (three families), runs the point-cloud front end
// and prints, per family, how well the boxes are recovered (camera frame, nearest-centre
// matching within 5 cm). "in tol" is over all boxes; "vis>=V" repeats it over the boxes
// whose visible share (visibility.h) is at least V (--visible, default 0.5), and "shown" over
// the boxes whose seen surface spans all three of their extents to within 1 cm (visibility.h:
// the others' extents are not in the cloud, whatever the front end does). --dump DIR writes, per
// scene, DIR/<family>_<scene>.json: the true and the estimated boxes and each estimate's own
// points, all in the table frame (for looking at the misses). Exit codes: 0 ok, 1 generation
// failure or an unwritable dump, 2 bad arguments.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <iostream>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "runtime/io/atomic_file.h"

#include "tools/perception/object_range.h"
#include "tools/perception/visibility.h"
#include "tools/perception_sim/sim_cloud.h"

namespace pc = ksmc::stdlib::tabletop::perception;
namespace ps = ksmc::tools::perception_sim;

namespace {

double median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}
double p90(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, v.size() * 9 / 10)];
}

nlohmann::json box_json(const std::string& name, const Eigen::Isometry3d& to_table, const Eigen::Vector3d& centre,
                        const Eigen::Matrix3d& axes, const Eigen::Vector3d& size) {
  const Eigen::Vector3d c = to_table * centre;
  const Eigen::Matrix3d r = to_table.linear() * axes;
  nlohmann::json j{{"name", name}, {"centre", {c.x(), c.y(), c.z()}}, {"size", {size.x(), size.y(), size.z()}}};
  for (int k = 0; k < 3; ++k) j["axes"].push_back({r(0, k), r(1, k), r(2, k)});
  return j;
}

// DIR/<family>_<scene>.json, table frame: truth, estimates and the estimates' points (rounded to
// 10 um: close enough to the cloud's that a box fit replayed on them takes the same branches).
void dump_scene(const std::string& dir, const std::string& family, int scene, const ps::SimFrame& f,
                const pc::CloudScene& cs) {
  const Eigen::Isometry3d to_table = cs.table.table_in_cloud.isometry().inverse();
  nlohmann::json j;
  for (const auto& t : f.truth) j["truth"].push_back(box_json(t.name, to_table, t.centre, t.axes, t.size));
  const std::vector<pc::TruthBox> est = pc::camera_frame_boxes(cs.scene);
  for (std::size_t e = 0; e < est.size(); ++e) {
    nlohmann::json b = box_json(est[e].name, to_table, est[e].centre, est[e].axes, est[e].size);
    b["cluster"] = cs.cluster_of[e];
    for (const auto& p : cs.object_points[e])
      b["points"].push_back({std::round(p.x() * 1e5) / 1e5, std::round(p.y() * 1e5) / 1e5, std::round(p.z() * 1e5) / 1e5});
    j["estimates"].push_back(std::move(b));
  }
  ksmc::runtime::io::write_file_atomic(fmt::format("{}/{}_{}.json", dir, family, scene), j.dump() + "\n");
}

}  // namespace

int main(int argc, char** argv) {
  int scenes = 10, lo = 5, hi = 10;
  std::uint64_t seed = 1;
  double sigma = 0.001, missing = 0.0, min_visible = 0.5;
  int stride = 2;
  bool verbose = false;
  std::string dump;  // --dump DIR
  bool upright = false;  // the upright fit only (no tilted boxes): the figures before tilted_box.h
  bool footprint_only = false;  // stacks without the free-space test: the figures before it
  bool fixed_tolerance = false;  // the 8 mm clustering tolerance whatever the sampling: the figures before it
  bool no_shadow_merge = false;  // clusters split by a resting box's shadow stay apart: the figures before it
  bool isotropic = false;  // clusters joined by the tolerance alone, not along grazing tops' rows: the figures before it
  bool whole_faces = false;  // tilted boxes from whole faces, a neighbour's face near by taken in: the figures before
                             // the edge and filled-rows tests (tilted_box.h)
  bool no_side_steps = false;  // boxes not split where their side faces step: the figures before side_steps.h
  bool no_hidden_bottom = false;  // boxes starting above the table stay there: the figures before hidden_bottom.h
  bool no_tilted_foot = false;    // a tilted box whose foot is hidden keeps its fit: the figures before tilted_foot.h
  bool no_hidden_reach = false;   // a box under one that overhangs it keeps its fit: the figures before hidden_reach.h
  bool no_lean_seat = false;      // a tilted box cutting into an upright one keeps its fit: the figures before lean_seat.h
  bool keep_strips = false;  // thin boxes on larger ones stay: before face_strip.h
  bool no_close_gap = false;  // a box over another within 15 mm keeps its gap: before HiddenBottomOptions::close_gap
  bool no_centre_support = false;  // a top rests on the rest only by the share it covers: before stop 44
  bool no_shadow_rest = false;  // a top whose faces stop at the plateau, in its own shadow, stands: before stop 44
  bool whole_tops = false;   // the tops above a plateau peeled as one box: before top_parts.h
  bool no_occluded_gap = false;  // the two ends of a box something lies across stay two: before occluded_gap.h
  bool no_seen_under = false;  // boxes from the table stay whole where the sensor saw under them: before seen_under.h
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      // Switches (no value).
      bool* const flag = a == "--verbose"           ? &verbose
                         : a == "--upright"         ? &upright
                         : a == "--footprint-only"  ? &footprint_only
                         : a == "--fixed-tolerance" ? &fixed_tolerance
                         : a == "--isotropic"       ? &isotropic
                         : a == "--no-shadow-merge" ? &no_shadow_merge
                         : a == "--whole-faces"     ? &whole_faces
                         : a == "--no-side-steps"   ? &no_side_steps
                         : a == "--no-hidden-bottom" ? &no_hidden_bottom
                         : a == "--no-hidden-reach" ? &no_hidden_reach
                         : a == "--no-tilted-foot" ? &no_tilted_foot
                         : a == "--no-lean-seat"    ? &no_lean_seat
                         : a == "--no-seen-under"   ? &no_seen_under
                         : a == "--no-occluded-gap" ? &no_occluded_gap
                         : a == "--keep-strips"     ? &keep_strips
                         : a == "--whole-tops"      ? &whole_tops
                         : a == "--no-centre-support" ? &no_centre_support
                         : a == "--no-shadow-rest"  ? &no_shadow_rest
                         : a == "--no-close-gap"    ? &no_close_gap
                                                    : nullptr;
      if (flag != nullptr) {
        *flag = true;
        continue;
      }
      if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
      const std::string v = argv[++i];
      if (a == "--scenes") scenes = std::stoi(v);
      else if (a == "--seed") seed = std::stoull(v);
      else if (a == "--sigma") sigma = std::stod(v);
      else if (a == "--missing") missing = std::stod(v);
      else if (a == "--stride") stride = std::stoi(v);
      else if (a == "--visible") min_visible = std::stod(v);
      else if (a == "--dump") dump = v;
      else if (a == "--objects") std::tie(lo, hi) = ksmc::tools::perception::parse_object_range(v);
      else throw std::invalid_argument("unknown option " + a);
    }
    if (scenes < 1 || lo < 1 || hi < lo || stride < 1 || sigma < 0 || missing < 0 || missing >= 1)
      throw std::invalid_argument("values out of range");
  } catch (const std::exception& e) {
    std::cerr << "ksmc-perception-sim: " << e.what() << "\n";
    return 2;
  }
  if (!dump.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(dump, ec);
    if (ec) {
      std::cerr << "ksmc-perception-sim: " << dump << ": cannot create the dump folder: " << ec.message() << "\n";
      return 1;
    }
  }
  fmt::print("{} scenes per family, {}..{} boxes, depth sigma {} mm at 1 m (x z^2), missing {:.0f} %, stride {}\n",
             scenes, lo, hi, 1000.0 * sigma, 100.0 * missing, stride);
  fmt::print("{:<8} {:>5} {:>6} {:>7} {:>6} | {:>10} {:>10} {:>9} {:>9} {:>11} {:>11} | {:>8} | {:>16} | {:>16}\n",
             "family", "boxes", "found", "missed", "extra", "centre med", "centre p90", "angle med", "angle p90",
             "size med", "size p90", "in tol", fmt::format("vis>={:.0f}%: in tol", 100.0 * min_visible),
             "shown: in tol");
  for (ps::SimFamily fam : ps::sim_families(lo, hi)) {
    fam.depth.sigma_at_1m = sigma;
    fam.depth.missing_rate = missing;
    fam.depth.stride = stride;
    int boxes = 0, found = 0, missed = 0, extra = 0, within = 0, visible = 0, visible_within = 0, shown = 0,
        shown_within = 0;
    std::vector<double> centre, angle, size;
    for (int s = 0; s < scenes; ++s) {
      try {
        const ps::SimFrame f = ps::simulate_frame(ksmc::tools::tabletop_sim::scene_seed(seed, static_cast<std::uint64_t>(s)), fam);
        pc::CloudOptions opt;
        opt.camera = ps::scene_camera(f.scene.camera);
        opt.fit.tilted = !upright;
        opt.fit.stacks.free_space = !footprint_only;
        if (fixed_tolerance) opt.clusters.spacing_factor = 0.0;
        if (isotropic) opt.clusters.slant_factor = 0.0;
        if (no_shadow_merge) opt.shadow.enabled = false;
        if (no_side_steps) opt.fit.stacks.sides.enabled = false;
        if (no_hidden_bottom) opt.hidden_bottom.enabled = false;
        if (no_hidden_reach) opt.hidden_reach.enabled = false;
        if (no_tilted_foot) opt.tilted_foot.enabled = false;
        if (no_lean_seat) opt.lean_seat.enabled = false;
        if (no_seen_under) opt.seen_under.enabled = false;
        if (no_occluded_gap) opt.occluded_gap.enabled = false;
        if (keep_strips) opt.face_strip.thin = -1.0;
        if (whole_tops) opt.fit.stacks.separate_tops = false;
        if (no_centre_support) opt.fit.stacks.centre_inset = -1.0;
        if (no_shadow_rest) opt.fit.stacks.max_points_below = 0;
        if (no_close_gap) opt.hidden_bottom.close_gap = std::numeric_limits<double>::infinity();
        if (whole_faces) {
          opt.fit.tilt.edge_gap = std::numeric_limits<double>::infinity();
          opt.fit.tilt.fill_ratio = 0.0;
        }
        const pc::CloudScene cs = pc::scene_from_points(f.cloud, fmt::format("{} scene {}", fam.name, s), opt);
        if (!dump.empty()) dump_scene(dump, fam.name, s, f, cs);
        const pc::TruthReport rep = pc::evaluate_same_frame(pc::camera_frame_boxes(cs.scene), f.truth, 0.05);
        std::vector<ksmc::tools::tabletop_sim::Box> truth_boxes;
        for (const auto& p : f.scene.physical) truth_boxes.push_back(p.body.box);
        const std::vector<ksmc::tools::perception::BoxView> view =
            ksmc::tools::perception::box_views(f.scene.camera, f.scene.table_from_camera, truth_boxes, stride);
        for (const auto& v : view) {
          visible += v.visible >= min_visible;
          shown += v.extents_shown;
        }
        boxes += static_cast<int>(f.truth.size());
        missed += rep.missed;
        extra += rep.spurious;
        for (const auto& o : rep.objects) {
          if (o.estimate < 0) continue;
          ++found;
          centre.push_back(1000.0 * o.error.centre);
          angle.push_back(o.error.angle * 180.0 / std::numbers::pi);
          size.push_back(1000.0 * o.error.max_size());
          const bool ok = o.error.centre <= 0.01 && o.error.angle <= 3.0 * std::numbers::pi / 180.0 &&
                          o.error.max_size() <= 0.01;
          within += ok;
          const std::size_t t_index = static_cast<std::size_t>(&o - rep.objects.data());
          visible_within += ok && view[t_index].visible >= min_visible;
          shown_within += ok && view[t_index].extents_shown;
          if (verbose && !ok) {
            const auto& t = f.truth[t_index];
            const auto& e = cs.scene.objects[static_cast<std::size_t>(o.estimate)];
            fmt::print("  {} scene {} {}: true {:.0f}x{:.0f}x{:.0f} mm, estimate {:.0f}x{:.0f}x{:.0f} mm ({} points), "
                       "centre {:.1f} mm, angle {:.1f} deg, size error {:.1f} mm, {:.0f} % visible{}\n",
                       fam.name, s, t.name, 1000 * t.size.x(), 1000 * t.size.y(), 1000 * t.size.z(), 1000 * e.size.x(),
                       1000 * e.size.y(), 1000 * e.size.z(), cs.object_points[static_cast<std::size_t>(o.estimate)].size(),
                       1000 * o.error.centre, o.error.angle * 180.0 / std::numbers::pi, 1000 * o.error.max_size(),
                       100.0 * view[t_index].visible, view[t_index].extents_shown ? ", extents shown" : "");
          }
        }
        if (verbose)
          for (std::size_t t = 0; t < rep.objects.size(); ++t)
            if (rep.objects[t].estimate < 0)
              fmt::print("  {} scene {} {}: missed, {:.0f} % visible{}\n", fam.name, s, f.truth[t].name,
                         100.0 * view[t].visible, view[t].extents_shown ? ", extents shown" : "");
      } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
      }
    }
    fmt::print("{:<8} {:>5} {:>6} {:>7} {:>6} | {:>7.1f} mm {:>7.1f} mm {:>7.2f} ° {:>7.2f} ° {:>8.1f} mm {:>8.1f} mm | {:>5.0f} % | {:>3} boxes {:>3.0f} % | {:>3} boxes {:>3.0f} %\n",
               fam.name, boxes, found, missed, extra, median(centre), p90(centre), median(angle), p90(angle),
               median(size), p90(size), 100.0 * within / std::max(1, boxes), visible,
               100.0 * visible_within / std::max(1, visible), shown, 100.0 * shown_within / std::max(1, shown));
  }
  return 0;
}
