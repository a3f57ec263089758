// ksmc-cloud-scene CLOUD --out DIR [--cloud-units cm|mm|m] [--truth obb_world.json] [--gate M]
//                  [--clusters FILE] [--min-height M] [--tolerance M] [--spacing-factor F] [--slant-factor S]
//                  [--min-points N]
// --tolerance is the clustering tolerance's floor; a sparser cloud gets F (default 2) times
// its object point spacing (--spacing-factor 0: the tolerance as given). Along the rows of a
// flat top seen at a slant, points up to S (default 2) row spacings apart are joined
// (--slant-factor 0: the tolerance in every direction).
// Runs the point-cloud front end, writes DIR/scene.json and prints one line per box; with
// --truth, registers the boxes to the true ones and prints the errors.
// Exit codes: 0 ok, 1 bad input (message names the file), 2 bad arguments.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "stdlib/tabletop/perception/scene_from_cloud.h"
#include "stdlib/tabletop/perception/scene_json.h"
#include "stdlib/tabletop/perception/cloud_truth.h"
#include "stdlib/tabletop/perception/truth_eval.h"

namespace pc = ksmc::stdlib::tabletop::perception;

namespace {

int usage(const std::string& why) {
  std::cerr << "ksmc-cloud-scene: " << why
            << "\nusage: ksmc-cloud-scene CLOUD.(ply|pcd) --out DIR [--cloud-units cm|mm|m] [--truth obb_world.json] "
               "[--gate M]\n";
  return 2;
}

void print_report(const pc::CloudScene& cs, const std::vector<pc::TruthBox>& truth, const pc::TruthReport& rep) {
  fmt::print("{:<18} {:>6} {:>9} {:>9} {:>26} {:>26}\n", "object", "est", "centre mm", "angle deg",
             "true size mm", "size error mm");
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const auto& o = rep.objects[i];
    const auto& t = truth[i];
    if (o.estimate < 0) {
      fmt::print("{:<18} {:>6}\n", t.name, "missed");
      continue;
    }
    const auto& e = o.error;
    fmt::print("{:<18} {:>6} {:>9.1f} {:>9.1f} {:>8.1f}{:>9.1f}{:>9.1f} {:>+8.1f}{:>+9.1f}{:>+9.1f}\n", t.name,
               cs.scene.objects[static_cast<std::size_t>(o.estimate)].id, 1000.0 * e.centre,
               e.angle * 180.0 / std::numbers::pi, 1000.0 * t.size.x(), 1000.0 * t.size.y(), 1000.0 * t.size.z(),
               1000.0 * e.size.x(), 1000.0 * e.size.y(), 1000.0 * e.size.z());
  }
  fmt::print("missed {}, spurious {}\n", rep.missed, rep.spurious);
}

void print_truth(const pc::CloudScene& cs, const std::filesystem::path& truth_path, double gate) {
  const auto truth = pc::read_obb_world(truth_path);
  const pc::CloudTruth ct = pc::evaluate_cloud_scene(cs, truth, gate);
  const auto& reg = ct.by_centres.registration;
  fmt::print("registration of the box centres: {} of {} matched, residual rms {:.1f} mm, max {:.1f} mm\n", reg.matched,
             truth.size(), 1000.0 * reg.rms, 1000.0 * reg.max_residual);
  print_report(cs, truth, ct.by_centres);
  fmt::print("refined on the box surfaces (ICP, 2 cm gate): {} object points kept, point-to-surface rms {:.1f} mm; "
             "boxes matched by their points: {}\n",
             ct.surfaces.kept, 1000.0 * ct.surfaces.rms, ct.by_points.registration.matched);
  print_report(cs, truth, ct.by_points);
  const Eigen::Matrix4d m = ct.surfaces.points_to_boxes.matrix();
  fmt::print("cloud -> truth frame [m]: [{:.6f} {:.6f} {:.6f} {:.5f}; {:.6f} {:.6f} {:.6f} {:.5f}; {:.6f} {:.6f} {:.6f} {:.5f}]\n",
             m(0, 0), m(0, 1), m(0, 2), m(0, 3), m(1, 0), m(1, 1), m(1, 2), m(1, 3), m(2, 0), m(2, 1), m(2, 2), m(2, 3));
  fmt::print("table top in the truth frame: z = {:.4f} m, normal tilt {:.2f} deg\n", ct.table_in_truth.translation().z(),
             std::acos(std::min(1.0, ct.table_in_truth.linear().col(2).z())) * 180.0 / std::numbers::pi);
}

}  // namespace

int main(int argc, char** argv) {
  std::filesystem::path cloud, out, truth, clusters_out;
  pc::CloudOptions options;
  double gate = 0.05;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](const char* name) -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(fmt::format("{} needs a value", name));
      return argv[++i];
    };
    try {
      if (a == "--out") out = value("--out");
      else if (a == "--cloud-units") options.units = pc::parse_units(value("--cloud-units"));
      else if (a == "--truth") truth = value("--truth");
      else if (a == "--gate") gate = std::stod(value("--gate"));
      else if (a == "--clusters") clusters_out = value("--clusters");
      else if (a == "--min-height") options.clusters.min_height = std::stod(value("--min-height"));
      else if (a == "--tolerance") options.clusters.tolerance = std::stod(value("--tolerance"));
      else if (a == "--spacing-factor") options.clusters.spacing_factor = std::stod(value("--spacing-factor"));
      else if (a == "--slant-factor") options.clusters.slant_factor = std::stod(value("--slant-factor"));
      else if (a == "--min-points") options.clusters.min_points = std::stoul(value("--min-points"));
      else if (!a.empty() && a[0] == '-') return usage("unknown option " + a);
      else if (cloud.empty()) cloud = a;
      else return usage("more than one cloud given");
    } catch (const std::exception& e) {
      return usage(e.what());
    }
  }
  if (cloud.empty()) return usage("no cloud given");
  if (out.empty()) return usage("--out DIR is required");
  try {
    const pc::CloudScene cs = pc::scene_from_cloud(cloud, options);
    std::filesystem::create_directories(out);
    pc::write_scene_json(out / "scene.json", cs.scene);
    fmt::print("{}: {} points, table {} inliers (rms {:.1f} mm, depth noise {:.1f} mm, {:.2f} x {:.2f} m), {} objects\n",
               cloud.string(), cs.cloud_points, cs.table.inliers, 1000.0 * cs.table.rms, 1000.0 * cs.table.noise,
               cs.table.extent.x(), cs.table.extent.y(), cs.scene.objects.size());
    fmt::print("object point spacing {:.1f} mm, clustering tolerance {:.1f} mm\n", 1000.0 * cs.point_spacing,
               1000.0 * cs.cluster_tolerance);
    for (std::size_t i = 0; i < cs.scene.objects.size(); ++i) {
      const auto& o = cs.scene.objects[i];
      fmt::print("  {:<8} {:>6} points, size {:.1f} x {:.1f} x {:.1f} mm, centre ({:.3f}, {:.3f}, {:.3f}) m\n", o.id,
                 cs.object_points[i].size(), 1000.0 * o.size.x(), 1000.0 * o.size.y(), 1000.0 * o.size.z(),
                 o.pose.t.x(), o.pose.t.y(), o.pose.t.z());
    }
    if (!truth.empty()) print_truth(cs, truth, gate);
    if (!clusters_out.empty()) {  // table-frame points "x y z cluster" for inspection
      std::string text;
      for (std::size_t i = 0; i < cs.object_points.size(); ++i)
        for (const auto& p : cs.object_points[i]) text += fmt::format("{:.5f} {:.5f} {:.5f} {}\n", p.x(), p.y(), p.z(), i);
      std::ofstream(clusters_out) << text;
    }
  } catch (const pc::CloudError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
