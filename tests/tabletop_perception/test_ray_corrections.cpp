// The box fits corrected by the cloud's rays: a box whose foot is hidden behind a nearer box
// stands on the table (hidden_bottom.h), and a box resting on a narrower one whose top it
// hides is two boxes when the sensor saw under its overhang (seen_under.h); a box the sensor
// sees under, one resting on another, and boxes standing on the table keep their fits; the two
// ends of a box with a box across it are one box, two boxes with a seen gap stay two
// (occluded_gap.h); a lower box seen only from its front grows under the box on it, a thin
// board seen beside stays thin (hidden_reach.h).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "stdlib/tabletop/perception/hidden_bottom.h"
#include "stdlib/tabletop/perception/hidden_reach.h"
#include "stdlib/tabletop/perception/occluded_gap.h"
#include "stdlib/tabletop/perception/scene_from_cloud.h"
#include "stdlib/tabletop/perception/seen_under.h"
#include "synthetic_cloud.h"

using namespace ksmc::stdlib::tabletop::perception;
using ksmc::stdlib::tabletop::FreeSpace;
using ksmc::stdlib::tabletop::Obb;
using ksmc::stdlib::tabletop::RayIndex;
using ksmc::stdlib::tabletop::SceneObject;
namespace tp = ksmc::tests::perception;

namespace {

const Eigen::Vector3d kFront(0.0, -0.9, 0.55);  // in front of the scene
const Eigen::Vector3d kAside(0.35, -0.7, 0.6);  // in front and to the side

struct Heights {
  double bottom, top;
};

// The scene with the hidden-foot and seen-under steps on or off.
CloudScene run(const Points& cloud, bool hidden_bottom, bool seen_under) {
  CloudOptions options;
  options.hidden_bottom.enabled = hidden_bottom;
  options.seen_under.enabled = seen_under;
  return scene_from_points(cloud, "synthetic", options);
}

// The scene object nearest (x, y) on the table, its bottom and top heights.
Heights nearest(const CloudScene& cs, double x, double y) {
  const SceneObject* best = nullptr;
  for (const auto& o : cs.scene.objects)
    if (best == nullptr || (o.pose.t.head<2>() - Eigen::Vector2d(x, y)).norm() <
                               (best->pose.t.head<2>() - Eigen::Vector2d(x, y)).norm())
      best = &o;
  REQUIRE(best != nullptr);
  return {best->obb().min_z(), best->obb().max_z()};
}


std::vector<Heights> heights(const CloudScene& cs) {  // lowest top first
  std::vector<Heights> h;
  for (const auto& o : cs.scene.objects) h.push_back({o.obb().min_z(), o.obb().max_z()});
  std::sort(h.begin(), h.end(), [](const Heights& a, const Heights& b) { return a.top < b.top; });
  return h;
}


// An upright box, axes along the table's, centred at x = 0 and `y`, from `bottom` up.
UprightBox upright_at(double y, double bottom, const Eigen::Vector3d& size) {
  UprightBox b;
  b.size = size;
  b.pose.t = Eigen::Vector3d(0.0, y, bottom + 0.5 * size.z());
  return b;
}

// A book lying on a narrower box, flush with it at the front and 3 cm over it on either side:
// the book hides the lower box's top, and the front faces make one cluster of the two.
const std::vector<tp::CastBox> kBookOnBox{tp::upright_box(0.0, 0.03, 0.0, Eigen::Vector3d(0.13, 0.21, 0.06)),
                                          tp::upright_box(0.0, 0.05, 0.06, Eigen::Vector3d(0.19, 0.25, 0.04))};

}  // namespace

TEST_CASE("hidden bottom: a carton behind a lower box stands on the table", "[perception][hidden_bottom]") {
  // The front box (12 cm) hides the carton's foot: the sensor sees it from about 8.6 cm up.
  const Points cloud = tp::sensor_view(kFront, {tp::upright_box(0.0, -0.05, 0.0, Eigen::Vector3d(0.2, 0.08, 0.12)),
                             tp::upright_box(0.0, 0.10, 0.0, Eigen::Vector3d(0.08, 0.08, 0.25))});
  const Heights before = nearest(run(cloud, false, true), 0.0, 0.10);
  CHECK(before.bottom > 0.05);  // the fit alone starts the carton where its points start
  const CloudScene cs = run(cloud, true, true);
  REQUIRE(cs.scene.objects.size() == 2);
  const Heights after = nearest(cs, 0.0, 0.10);
  CHECK(after.bottom == Approx(0.0).margin(0.003));
  CHECK(after.top == Approx(0.25).margin(0.005));
  const Heights front = nearest(cs, 0.0, -0.05);  // the front box is untouched
  CHECK(front.bottom == Approx(0.0).margin(0.003));
  CHECK(front.top == Approx(0.12).margin(0.005));
}

TEST_CASE("hidden bottom: a box the sensor sees under keeps its bottom", "[perception][hidden_bottom]") {
  // Nothing in front: the rays under the box reach the table behind it.
  const CloudScene cs = run(tp::sensor_view(kFront, {tp::upright_box(0.0, 0.10, 0.09, Eigen::Vector3d(0.08, 0.08, 0.16))}), true, true);
  REQUIRE(cs.scene.objects.size() == 1);
  CHECK(nearest(cs, 0.0, 0.10).bottom == Approx(0.09).margin(0.006));
}

TEST_CASE("hidden bottom: a box resting on another keeps its bottom", "[perception][hidden_bottom]") {
  // The lower box hides the space under the upper one, which rests on it.
  const CloudScene cs = run(tp::sensor_view(kFront, {tp::upright_box(0.0, 0.10, 0.0, Eigen::Vector3d(0.14, 0.14, 0.08)),
                                  tp::upright_box(0.0, 0.10, 0.08, Eigen::Vector3d(0.08, 0.08, 0.10))}),
                            true, true);
  REQUIRE(cs.scene.objects.size() == 2);
  const std::vector<Heights> h = heights(cs);
  CHECK(h[0].top == Approx(0.08).margin(0.005));
  CHECK(h[1].bottom == Approx(0.08).margin(0.006));
}

TEST_CASE("hidden bottom: a box lying on one it overhangs makes the lower box grow up to it", "[perception][hidden_bottom]") {
  // A 28 x 23 cm box on a 10 x 10 x 14 cm one, centred: from the front, the sensor sees the lower
  // box's front face only up to about 10.6 cm (the upper box's overhang hides the rest) and
  // sees under the overhang beside the lower box, so the upper box is not grown down.
  const std::vector<tp::CastBox> stack{tp::upright_box(0.0, 0.0, 0.0, Eigen::Vector3d(0.10, 0.10, 0.14)),
                                       tp::upright_box(0.0, 0.0, 0.14, Eigen::Vector3d(0.28, 0.23, 0.06))};
  const Points cloud = tp::sensor_view(kFront, stack);
  const std::vector<Heights> before = heights(run(cloud, false, true));
  REQUIRE(before.size() == 2);
  CHECK(before[0].top < 0.115);  // the lower box, cut where the overhang hides it
  const CloudScene cs = run(cloud, true, true);
  const std::vector<Heights> h = heights(cs);
  REQUIRE(h.size() == 2);
  CHECK(h[0].bottom == Approx(0.0).margin(0.003));
  CHECK(h[0].top == Approx(0.14).margin(0.005));
  CHECK(h[1].bottom == Approx(0.14).margin(0.005));  // the upper box keeps its bottom
  CHECK(h[1].top == Approx(0.20).margin(0.005));

  // A 4 cm gap between the two (something hidden holds the upper box), seen from low at the
  // side, through the gap: the lower box keeps its top.
  const std::vector<tp::CastBox> gap{tp::upright_box(0.0, 0.0, 0.0, Eigen::Vector3d(0.10, 0.10, 0.10)), stack[1]};
  const std::vector<Heights> seen = heights(run(tp::sensor_view(Eigen::Vector3d(0.9, 0.0, 0.16), gap), true, true));
  REQUIRE(seen.size() == 2);
  CHECK(seen[0].top == Approx(0.10).margin(0.005));
  CHECK(seen[1].bottom == Approx(0.14).margin(0.005));
}

TEST_CASE("hidden reach: a lower box seen only from its front grows under the box on it", "[perception][hidden_reach]") {
  // A 26 x 26 cm box on a 20 x 16 x 5 cm one, flush at the front: from the front the sensor sees
  // only the lower box's front face (its top and sides are hidden or edge-on), and the front end
  // fits a 5 mm strip that the upper box's centre lies 13 cm behind.
  const std::vector<tp::CastBox> stack{tp::upright_box(0.0, 0.02, 0.0, Eigen::Vector3d(0.20, 0.16, 0.05)),
                                       tp::upright_box(0.0, 0.07, 0.05, Eigen::Vector3d(0.26, 0.26, 0.04))};
  const Points cloud = tp::sensor_view(kFront, stack);
  CloudOptions options;
  options.hidden_reach.enabled = false;
  const CloudScene strip = scene_from_points(cloud, "synthetic", options);
  REQUIRE(strip.scene.objects.size() == 2);
  const auto depth = [](const CloudScene& cs) {  // the lower box's extent along y, and its back
    const auto& o = cs.scene.objects[0].obb().min_z() < cs.scene.objects[1].obb().min_z() ? cs.scene.objects[0]
                                                                                           : cs.scene.objects[1];
    const Obb b = o.obb();
    double lo = 1e9, hi = -1e9;
    for (const auto& v : b.vertices()) lo = std::min(lo, v.y()), hi = std::max(hi, v.y());
    return std::make_pair(hi - lo, hi);
  };
  CHECK(depth(strip).first < 0.02);
  options.hidden_reach.enabled = true;
  const CloudScene grown = scene_from_points(cloud, "synthetic", options);
  REQUIRE(grown.scene.objects.size() == 2);
  const auto [extent, back] = depth(grown);
  CHECK(extent > 0.12);           // true 16 cm; it grows until the upper centre (7 cm) is 1 cm inside
  CHECK(back == Approx(0.08).margin(0.006));
  CHECK(depth(grown).first <= 0.16 + 0.005);

  // A 2 cm thin board under the same box, seen from low at the side: the sensor saw under the
  // box beside the board (rays reach the table there), so the board keeps its fit.
  const std::vector<tp::CastBox> board{tp::upright_box(0.0, -0.05, 0.0, Eigen::Vector3d(0.20, 0.02, 0.05)), stack[1]};
  const CloudScene side = scene_from_points(tp::sensor_view(Eigen::Vector3d(0.7, -0.6, 0.12), board), "synthetic", {});
  REQUIRE(side.scene.objects.size() == 2);
  const auto& low = side.scene.objects[0].obb().max_z() < side.scene.objects[1].obb().max_z() ? side.scene.objects[0]
                                                                                              : side.scene.objects[1];
  CHECK(std::min(low.size.x(), low.size.y()) < 0.03);
  CHECK(std::max(low.size.x(), low.size.y()) == Approx(0.20).margin(0.01));
}

TEST_CASE("hidden bottom: the counts of rays under a box, and boxes left alone", "[perception][hidden_bottom]") {
  FreeSpace seen;
  seen.sensor = kFront;
  seen.points = tp::table_view(kFront, {tp::upright_box(0.0, -0.05, 0.0, Eigen::Vector3d(0.2, 0.08, 0.12)),
                                        tp::upright_box(0.0, 0.10, 0.0, Eigen::Vector3d(0.08, 0.08, 0.25))});
  UprightBox box;  // the carton's visible part, from 9 cm up
  box.size = Eigen::Vector3d(0.08, 0.08, 0.16);
  box.pose.t = Eigen::Vector3d(0.0, 0.10, 0.09 + 0.08);
  const RayIndex rays(seen);
  const SpaceUnder s = rays_under(box, rays);
  CHECK(s.before > 100);  // the front box hides the space under it ...
  CHECK(s.before > 9 * (s.inside + s.through));
  std::vector<UprightBox> boxes{box};
  CHECK(grow_hidden_bottoms(boxes, rays, 0.03) == 1);
  CHECK(boxes[0].size.z() == Approx(0.25));
  CHECK(boxes[0].pose.t.z() == Approx(0.125));

  UprightBox tilted = box;  // not upright: left alone
  tilted.pose.q = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()));
  UprightBox low = box;  // starting within the float gap: left alone
  low.pose.t.z() = 0.02 + 0.08;
  std::vector<UprightBox> others{tilted, low};
  CHECK(grow_hidden_bottoms(others, rays, 0.03) == 0);
  HiddenBottomOptions off;
  off.enabled = false;
  std::vector<UprightBox> disabled{box};
  CHECK(grow_hidden_bottoms(disabled, rays, 0.03, off) == 0);
}

TEST_CASE("hidden bottom: a box leaning on one seen from its shoulder up holds nothing", "[perception][hidden_bottom]") {
  // The carton of the cases above, seen from 9 cm up behind the front box, and a board (2 x 6 x
  // 10 cm, tilted 20 degrees) leaning on its side: the board's upper edge reaches 2 mm under
  // the edge of the carton's footprint, 1.2 cm below its bottom. The carton does not rest on
  // it: it still grows down to the table (it stayed at 9 cm, and was called hidden).
  FreeSpace seen;
  seen.sensor = kFront;
  seen.points = tp::table_view(kFront, {tp::upright_box(0.0, -0.05, 0.0, Eigen::Vector3d(0.2, 0.08, 0.12)),
                                        tp::upright_box(0.0, 0.10, 0.0, Eigen::Vector3d(0.08, 0.08, 0.25))});
  const RayIndex rays(seen);
  UprightBox carton;
  carton.size = Eigen::Vector3d(0.08, 0.08, 0.16);
  carton.pose.t = Eigen::Vector3d(0.0, 0.10, 0.09 + 0.08);
  const double a = 20.0 * 3.14159265358979323846 / 180.0;
  UprightBox board;
  board.size = Eigen::Vector3d(0.02, 0.06, 0.10);
  board.pose.q = Eigen::Quaterniond(Eigen::AngleAxisd(a, Eigen::Vector3d::UnitY()));
  const Eigen::Vector3d corner(0.01 * std::cos(a) + 0.05 * std::sin(a), 0.0, -0.01 * std::sin(a) + 0.05 * std::cos(a));
  board.pose.t = Eigen::Vector3d(-0.038, 0.10, 0.078) - corner;  // its upper +x edge there
  REQUIRE_FALSE(is_upright(board));
  REQUIRE(Obb::from_pose(board.pose, board.size).contains(Eigen::Vector3d(-0.04, 0.10, 0.075), 0.0075));
  std::vector<UprightBox> boxes{carton, board};
  CHECK(grow_hidden_bottoms(boxes, rays, 0.03) == 1);
  CHECK(bottom_height(boxes[0]) == Approx(0.0).margin(1e-9));
  CHECK(boxes[0].size.z() == Approx(0.25));
  // An upright box there instead holds it: the carton rests on it and keeps its bottom.
  UprightBox block;
  block.size = Eigen::Vector3d(0.02, 0.06, 0.078);
  block.pose.t = Eigen::Vector3d(-0.048, 0.10, 0.039);
  std::vector<UprightBox> held{carton, block};
  CHECK(grow_hidden_bottoms(held, rays, 0.03) == 0);
  CHECK(bottom_height(held[0]) == Approx(0.09));
}

TEST_CASE("hidden bottom: a box over another grows down to that box's top, not to the table",
          "[perception][hidden_bottom]") {
  // A box (8 x 8 x 12 cm) resting on a wider low one (14 x 14 x 8 cm), both behind a 17 cm
  // front box: the sensor sees the upper box from about 14 cm up, and the space under that,
  // down to the low box's top, is hidden. The upper box grows down to 8 cm, where it rests.
  FreeSpace seen;
  seen.sensor = kFront;
  seen.points = tp::table_view(kFront, {tp::upright_box(0.0, -0.05, 0.0, Eigen::Vector3d(0.2, 0.08, 0.17)),
                                        tp::upright_box(0.0, 0.10, 0.0, Eigen::Vector3d(0.14, 0.14, 0.08)),
                                        tp::upright_box(0.0, 0.10, 0.08, Eigen::Vector3d(0.08, 0.08, 0.12))});
  const RayIndex rays(seen);
  std::vector<UprightBox> boxes{upright_at(-0.05, 0.0, Eigen::Vector3d(0.2, 0.08, 0.17)),
                                upright_at(0.10, 0.0, Eigen::Vector3d(0.14, 0.14, 0.08)),
                                upright_at(0.10, 0.14, Eigen::Vector3d(0.08, 0.08, 0.06))};  // the part seen
  CHECK(grow_hidden_bottoms(boxes, rays, 0.03) == 1);
  CHECK(bottom_height(boxes[2]) == Approx(0.08));
  CHECK(boxes[2].size.z() == Approx(0.12));
  CHECK(bottom_height(boxes[1]) == 0.0);  // the others as they were
  CHECK(boxes[1].size.z() == Approx(0.08));
}

TEST_CASE("hidden bottom: a box under a larger one, fitted short by its overhang, grows up to it",
          "[perception][hidden_bottom]") {
  // A 28 x 14 x 4 cm box on a 10 x 10 x 4 cm one: from the front, the upper box's 2 cm overhang
  // hides the lower box's front face above about 2.7 cm. Fitted from what is seen, the lower box
  // ends 13 mm under the upper one: within rest_depth, and the box over it hovered.
  const std::vector<tp::CastBox> stack{tp::upright_box(0.0, 0.0, 0.0, Eigen::Vector3d(0.10, 0.10, 0.04)),
                                       tp::upright_box(0.0, 0.0, 0.04, Eigen::Vector3d(0.28, 0.14, 0.04))};
  const auto fitted = [&] {
    return std::vector<UprightBox>{upright_at(0.0, 0.0, Eigen::Vector3d(0.10, 0.10, 0.027)),
                                   upright_at(0.0, 0.04, Eigen::Vector3d(0.28, 0.14, 0.04))};
  };
  FreeSpace front;
  front.sensor = kFront;
  front.points = tp::table_view(kFront, stack);
  const RayIndex front_rays(front);
  std::vector<UprightBox> boxes = fitted();
  CHECK(grow_hidden_bottoms(boxes, front_rays, 0.03) == 1);
  CHECK(bottom_height(boxes[0]) == Approx(0.0));
  CHECK(boxes[0].size.z() == Approx(0.04));
  CHECK(bottom_height(boxes[1]) == Approx(0.04));  // the upper box as it was
  CHECK(boxes[1].size.z() == Approx(0.04));
  HiddenBottomOptions before;  // the gap kept, as before close_gap
  before.close_gap = std::numeric_limits<double>::infinity();
  boxes = fitted();
  CHECK(grow_hidden_bottoms(boxes, front_rays, 0.03, before) == 0);
  CHECK(boxes[0].size.z() == Approx(0.027));

  // The same 13 mm gap, truly there (something hidden holds the upper box) and seen through
  // from low at the side, onto a board behind: the lower box keeps its top.
  const std::vector<tp::CastBox> gap{tp::upright_box(0.0, 0.0, 0.0, Eigen::Vector3d(0.10, 0.10, 0.027)), stack[1],
                                     tp::upright_box(-0.3, 0.0, 0.0, Eigen::Vector3d(0.02, 0.6, 0.2))};
  FreeSpace side;
  side.sensor = Eigen::Vector3d(0.9, 0.0, 0.034);
  side.points = tp::table_view(side.sensor, gap);
  const RayIndex side_rays(side);
  boxes = fitted();
  CHECK(grow_hidden_bottoms(boxes, side_rays, 0.03) == 0);
  CHECK(boxes[0].size.z() == Approx(0.027));
}

TEST_CASE("hidden bottom: a box seen only as a strip under a book grows up to it", "[perception][hidden_bottom]") {
  // A 20 x 22 cm book on a 15 x 6 x 6.5 cm box, seen from the front: the book's 8 cm overhang
  // hides all of the lower box but the foot of its front face, fitted as a 5 mm strip 1.6 cm
  // high. No point of the book's footprint grid lies over the strip; the strip's top lies under
  // the book, so the book is over it and the strip grows up to the book.
  FreeSpace seen;
  seen.sensor = kFront;
  seen.points = tp::table_view(kFront, {tp::upright_box(0.0, 0.0, 0.0, Eigen::Vector3d(0.15, 0.06, 0.065)),
                                        tp::upright_box(0.0, 0.0, 0.065, Eigen::Vector3d(0.20, 0.22, 0.04))});
  const RayIndex rays(seen);
  std::vector<UprightBox> boxes{upright_at(-0.0325, 0.0, Eigen::Vector3d(0.15, 0.005, 0.016)),
                                upright_at(0.0, 0.065, Eigen::Vector3d(0.20, 0.22, 0.04))};
  CHECK(grow_hidden_bottoms(boxes, rays, 0.03) == 1);
  CHECK(bottom_height(boxes[0]) == Approx(0.0));
  CHECK(boxes[0].size.z() == Approx(0.065));
  CHECK(bottom_height(boxes[1]) == Approx(0.065));  // the book as it was
}

TEST_CASE("seen under: a book on a smaller box is two boxes", "[perception][seen_under]") {
  const Points cloud = tp::sensor_view(kAside, kBookOnBox);
  const std::vector<Heights> before = heights(run(cloud, true, false));
  REQUIRE(before.size() == 1);  // one box from the table up to the book's top
  CHECK(before[0].bottom == Approx(0.0).margin(0.003));
  CHECK(before[0].top == Approx(0.10).margin(0.004));
  const std::vector<Heights> after = heights(run(cloud, true, true));
  REQUIRE(after.size() == 2);
  CHECK(after[0].bottom == Approx(0.0).margin(0.003));  // the lower box, from its visible faces
  CHECK(after[0].top == Approx(0.06).margin(0.01));
  CHECK(after[1].bottom == Approx(0.06).margin(0.01));  // the book, resting where the rays stop
  CHECK(after[1].top == Approx(0.10).margin(0.004));
}

TEST_CASE("seen under: boxes standing on the table stay whole", "[perception][seen_under]") {
  const std::vector<tp::CastBox> boxes{tp::upright_box(-0.1, 0.05, 0.0, Eigen::Vector3d(0.08, 0.08, 0.20)),
                                       tp::upright_box(0.12, 0.0, 0.0, Eigen::Vector3d(0.19, 0.25, 0.04))};
  const std::vector<Heights> h = heights(run(tp::sensor_view(kAside, boxes), true, true));
  REQUIRE(h.size() == 2);
  for (const Heights& b : h) CHECK(b.bottom == Approx(0.0).margin(0.003));
  CHECK(h[0].top == Approx(0.04).margin(0.004));
  CHECK(h[1].top == Approx(0.20).margin(0.004));
}

TEST_CASE("seen under: the height the sensor saw up to", "[perception][seen_under]") {
  FreeSpace seen;
  seen.sensor = kAside;
  seen.points = tp::table_view(kAside, kBookOnBox);
  const RayIndex rays(seen);
  UprightBox one;  // the single box from the table up to the book's top
  one.size = Eigen::Vector3d(0.19, 0.25, 0.10);
  one.pose.t = Eigen::Vector3d(0.0, 0.05, 0.05);
  const double cut = seen_under_height(one, rays);
  CHECK(cut > 0.045);  // up to just under the book, less what the inset hides
  CHECK(cut < 0.06);
  UprightBox lower = one;  // where the lower box really is: nothing seen through it
  lower.size = Eigen::Vector3d(0.10, 0.12, 0.06);
  lower.pose.t = Eigen::Vector3d(0.0, 0.05, 0.03);
  CHECK(seen_under_height(lower, rays) == 0.0);
  SeenUnderOptions off;
  off.enabled = false;
  CHECK(cut_seen_under(one, seen.points, rays, BoxFitOptions{}, SideStepOptions{}, off).empty());
}

TEST_CASE("seen under: a box fitted wider than its top is read under its top", "[perception][seen_under]") {
  // The book on a narrower box of kBookOnBox, fitted as one box 12 mm wider than the book at
  // the front (as when the lower box, turned under the book, pokes out there). The rays to the
  // book's front face cross that strip up to the book's top, and the whole box shows no cut;
  // under the book's top face alone the rays see through up to just under the book.
  FreeSpace seen;
  seen.sensor = kAside;
  seen.points = tp::table_view(kAside, kBookOnBox);
  const RayIndex rays(seen);
  Points cluster;
  for (const auto& p : seen.points)
    if (p.z() > 0.012) cluster.push_back(p);
  UprightBox wide;
  wide.size = Eigen::Vector3d(0.19, 0.25 + 0.012, 0.10);
  wide.pose.t = Eigen::Vector3d(0.0, 0.05 - 0.006, 0.05);
  SeenUnderOptions whole;
  whole.top_band = 0.0;
  CHECK(seen_under_height(wide, rays, whole) > 0.09);
  CHECK(cut_seen_under(wide, cluster, rays, BoxFitOptions{}, SideStepOptions{}, whole).empty());
  const std::vector<UprightBox> parts = cut_seen_under(wide, cluster, rays, BoxFitOptions{}, SideStepOptions{});
  REQUIRE(parts.size() == 2);
  CHECK(bottom_height(parts[1]) == Approx(0.06).margin(0.01));  // the book, resting where the rays stop
  CHECK(bottom_height(parts[1]) + parts[1].size.z() == Approx(0.10).margin(0.004));
  CHECK(parts[0].size.z() == Approx(0.06).margin(0.01));  // the box under it
}

namespace {

// The scene's boxes (table frame) with the occluded-gap step on or off.
std::vector<UprightBox> gap_boxes(const Points& cloud, bool bridge) {
  CloudOptions options;
  options.occluded_gap.enabled = bridge;
  const CloudScene cs = scene_from_points(cloud, "synthetic", options);
  std::vector<UprightBox> out;
  for (const auto& o : cs.scene.objects) out.push_back({o.pose, o.size});
  return out;
}

// The box of `boxes` nearest (x, y) and the count of boxes within `r` of it.
const UprightBox& nearest_box(const std::vector<UprightBox>& boxes, double x, double y) {
  REQUIRE(!boxes.empty());
  return *std::min_element(boxes.begin(), boxes.end(), [&](const UprightBox& a, const UprightBox& b) {
    return (a.pose.t.head<2>() - Eigen::Vector2d(x, y)).norm() < (b.pose.t.head<2>() - Eigen::Vector2d(x, y)).norm();
  });
}

}  // namespace

TEST_CASE("occluded gap: a long box with a box across it is one box", "[perception][occluded_gap]") {
  // A 20 cm toothpaste along x; a 22 cm box lies across its middle (resting on it). From the
  // front and above, the crossing box hides the toothpaste's middle: two ends are seen.
  const Eigen::Vector3d paste(0.20, 0.04, 0.035);
  const std::vector<tp::CastBox> scene{tp::upright_box(0.0, 0.05, 0.0, paste),
                                       tp::upright_box(0.0, 0.05, 0.035, Eigen::Vector3d(0.05, 0.22, 0.04))};
  const Points cloud = tp::sensor_view(kFront, scene);
  const std::vector<UprightBox> before = gap_boxes(cloud, false), after = gap_boxes(cloud, true);
  INFO("boxes before " << before.size() << ", after " << after.size());
  CHECK(after.size() + 1 == before.size());
  const UprightBox& one = nearest_box(after, 0.0, 0.05);
  const Eigen::Vector2d footprint = one.size.head<2>();
  CHECK(footprint.maxCoeff() == Approx(paste.x()).margin(0.01));
  CHECK(footprint.minCoeff() == Approx(paste.y()).margin(0.01));
  CHECK(one.size.z() == Approx(paste.z()).margin(0.005));
  CHECK(one.pose.t.x() == Approx(0.0).margin(0.005));
}

TEST_CASE("occluded gap: two boxes in a row with the gap seen stay two", "[perception][occluded_gap]") {
  // The same two ends with nothing across them: the sensor sees the table between them.
  const Eigen::Vector3d end(0.075, 0.04, 0.035);
  const std::vector<tp::CastBox> scene{tp::upright_box(-0.0625, 0.05, 0.0, end), tp::upright_box(0.0625, 0.05, 0.0, end)};
  const std::vector<UprightBox> after = gap_boxes(tp::sensor_view(kFront, scene), true);
  REQUIRE(after.size() == 2);
  for (const UprightBox& b : after) CHECK(b.size.head<2>().maxCoeff() == Approx(end.x()).margin(0.01));
}
