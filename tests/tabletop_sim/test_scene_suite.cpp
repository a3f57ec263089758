// The generated scene suite: files parse and satisfy the format's invariants, and the ground
// truth is physically right (at rest, touching supporters, hidden/false as claimed).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "tools/tabletop_sim/scene_writer.h"

using namespace ksmc::tools::tabletop_sim;
namespace fs = std::filesystem;

namespace {

constexpr int kSuiteSize = 54;
constexpr std::uint64_t kSuiteSeed = 20240611;
constexpr double kDeg = std::numbers::pi / 180.0;

GeneratorOptions suite_options() {
  GeneratorOptions o;
  o.min_objects = 3;
  o.max_objects = 9;
  o.corruption.hidden_rate = 0.3;  // the defaults, spelled out: the counts below depend on them
  o.corruption.false_rate = 0.1;
  return o;
}

struct Suite {
  fs::path dir;
  std::vector<GeneratedScene> scenes;
};

// Generated once and shared by the test cases below.
const Suite& suite() {
  static const Suite s = [] {
    Suite r;
    r.dir = fs::path(KSMC_BINARY_DIR) / "test_output" / "tabletop_sim_suite";
    fs::remove_all(r.dir);
    fs::create_directories(r.dir);
    const auto options = suite_options();
    for (int i = 0; i < kSuiteSize; ++i) {
      r.scenes.push_back(generate_scene(scene_seed(kSuiteSeed, static_cast<std::uint64_t>(i)), options));
      char stem[32];
      std::snprintf(stem, sizeof stem, "scene_%03d", i);
      write_scene_files(r.dir, stem, r.scenes.back());
    }
    return r;
  }();
  return s;
}

nlohmann::json read_json(const fs::path& p) {
  std::ifstream in(p);
  REQUIRE(in.good());
  return nlohmann::json::parse(in);  // throws (fails the test) on malformed JSON
}

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

double quat_norm(const nlohmann::json& q) {
  double s = 0;
  for (const auto& v : q) s += v.get<double>() * v.get<double>();
  return std::sqrt(s);
}

Box clean_box(const SceneObject& o) { return Box{o.item.size, o.clean_pose}; }

}  // namespace

TEST_CASE("Same seed gives byte-identical files, another seed does not", "[tabletop_sim][determinism]") {
  GeneratorOptions o;
  o.min_objects = 4;
  o.max_objects = 12;
  const fs::path a = fs::path(KSMC_BINARY_DIR) / "test_output" / "tabletop_sim_det_a";
  const fs::path b = fs::path(KSMC_BINARY_DIR) / "test_output" / "tabletop_sim_det_b";
  for (const auto& d : {a, b}) {
    fs::remove_all(d);
    fs::create_directories(d);
  }
  for (int i = 0; i < 3; ++i) {
    const std::string stem = "scene_00" + std::to_string(i);
    write_scene_files(a, stem, generate_scene(scene_seed(99, static_cast<std::uint64_t>(i)), o));
    write_scene_files(b, stem, generate_scene(scene_seed(99, static_cast<std::uint64_t>(i)), o));
    for (const char* ext : {".json", ".truth.json"}) {
      const std::string fa = read_bytes(a / (stem + ext));
      REQUIRE(!fa.empty());
      CHECK(fa == read_bytes(b / (stem + ext)));
    }
  }
  const auto other = generate_scene(scene_seed(100, 0), o);
  CHECK(scene_json(other) != read_bytes(a / "scene_000.json"));
}

TEST_CASE("Every written scene parses and satisfies the format invariants", "[tabletop_sim][suite]") {
  const Suite& s = suite();
  for (int i = 0; i < kSuiteSize; ++i) {
    char stem[32];
    std::snprintf(stem, sizeof stem, "scene_%03d", i);
    INFO("scene " << stem);
    const auto scene = read_json(s.dir / (std::string(stem) + ".json"));
    const auto truth = read_json(s.dir / (std::string(stem) + ".truth.json"));

    const auto& cam = scene.at("camera");
    CHECK(cam.at("fx").get<double>() == 615.0);
    CHECK(cam.at("width").get<int>() == 640);
    CHECK(cam.at("height").get<int>() == 480);
    CHECK(quat_norm(scene.at("table").at("pose").at("q")) == Approx(1.0).margin(1e-6));
    // The camera is 0.8-1.2 m from the table origin (look-at jitter of 3 cm aside).
    const auto& tt = scene.at("table").at("pose").at("t");
    const double d = std::hypot(tt[0].get<double>(), tt[1].get<double>(), tt[2].get<double>());
    CHECK(d > 0.75);
    CHECK(d < 1.25);

    std::set<std::string> ids;
    const auto& objects = scene.at("objects");
    REQUIRE(objects.size() >= 1);
    for (const auto& o : objects) {
      const std::string id = o.at("id").get<std::string>();
      CHECK(ids.insert(id).second);
      CHECK(!o.at("model").get<std::string>().empty());
      REQUIRE(o.at("size").size() == 3);
      for (const auto& v : o.at("size")) CHECK(v.get<double>() > 0.0);
      REQUIRE(o.at("pose").at("t").size() == 3);
      REQUIRE(o.at("pose").at("q").size() == 4);
      CHECK(quat_norm(o.at("pose").at("q")) == Approx(1.0).margin(1e-6));
      CHECK(o.at("pose").at("t")[2].get<double>() > 0.2);  // in front of the camera
      const auto& kp = o.at("keypoints");
      CHECK(kp.at("model").size() == kp.at("image").size());
      CHECK(kp.at("model").size() >= 10);
      CHECK(kp.at("model").size() <= 30);
      for (std::size_t k = 0; k < kp.at("model").size(); ++k) {
        const auto& m = kp.at("model")[k];
        const auto& u = kp.at("image")[k];
        REQUIRE(m.size() == 3);
        REQUIRE(u.size() == 2);
        // Model points lie on the box surface (object frame = OBB centre).
        double worst = -1;
        for (int c = 0; c < 3; ++c) {
          const double excess = std::abs(m[static_cast<std::size_t>(c)].get<double>()) - 0.5 * o.at("size")[static_cast<std::size_t>(c)].get<double>();
          CHECK(excess <= 2e-5);
          worst = std::max(worst, excess);
        }
        CHECK(worst > -2e-5);
        CHECK(u[0].get<double>() >= -5.0);
        CHECK(u[0].get<double>() <= 645.0);
        CHECK(u[1].get<double>() >= -5.0);
        CHECK(u[1].get<double>() <= 485.0);
      }
    }

    // Truth: same ids in the same order, edges over known ids, flags consistent.
    const auto& tobj = truth.at("objects");
    REQUIRE(tobj.size() == objects.size());
    std::map<std::string, nlohmann::json> flags;
    for (std::size_t k = 0; k < tobj.size(); ++k) {
      CHECK(tobj[k].at("id") == objects[k].at("id"));
      flags[tobj[k].at("id").get<std::string>()] = tobj[k];
      CHECK(!(tobj[k].at("false").get<bool>() && tobj[k].at("hidden").get<bool>()));
      if (tobj[k].at("false").get<bool>()) CHECK(!tobj[k].at("stable").get<bool>());
    }
    auto known = [&](const std::string& id) { return id == "table" || ids.count(id) == 1; };
    std::set<std::pair<std::string, std::string>> support_pairs;
    for (const auto& e : truth.at("support")) {
      const auto up = e[0].get<std::string>();
      const auto lo = e[1].get<std::string>();
      CHECK(known(up));
      CHECK(known(lo));
      CHECK(up != lo);
      CHECK(up != "table");
      CHECK(!flags[up].at("false").get<bool>());
      CHECK(!flags[up].at("hidden").get<bool>());
      CHECK(flags[up].at("stable").get<bool>());
      if (lo != "table") CHECK(!flags[lo].at("false").get<bool>());
      support_pairs.insert({up, lo});
    }
    for (const auto& e : truth.at("contact")) {
      const auto a = e[0].get<std::string>();
      const auto b = e[1].get<std::string>();
      CHECK(known(a));
      CHECK(known(b));
      CHECK(a != b);
      CHECK(!flags[a].at("false").get<bool>());
      if (b != "table") CHECK(!flags[b].at("false").get<bool>());
      CHECK(support_pairs.count({a, b}) == 0);
      CHECK(support_pairs.count({b, a}) == 0);
    }
  }
}

TEST_CASE("The suite mixes clean, hidden and false scenes", "[tabletop_sim][suite]") {
  const Suite& s = suite();
  int with_hidden = 0, with_false = 0, clean = 0, stacked = 0, with_contact = 0;
  std::set<FalseKind> kinds;
  for (const auto& sc : s.scenes) {
    with_hidden += sc.hidden_count() > 0;
    with_false += sc.false_count() > 0;
    clean += sc.hidden_count() == 0 && sc.false_count() == 0;
    with_contact += !sc.relations.contact.empty();
    stacked += std::any_of(sc.relations.support.begin(), sc.relations.support.end(),
                           [](const auto& e) { return e.second != kTableIndex; });
    for (const auto& o : sc.objects) kinds.insert(o.false_kind);
  }
  INFO("hidden " << with_hidden << ", false " << with_false << ", clean " << clean << ", stacked " << stacked
                 << ", contact " << with_contact);
  CHECK(s.scenes.size() >= 50);
  CHECK(with_hidden >= 10);
  CHECK(with_false >= 10);
  CHECK(clean >= 8);
  CHECK(stacked >= 30);
  CHECK(with_contact >= 10);
  CHECK(kinds.size() == 5);  // none + the four kinds of false estimate
}

TEST_CASE("Settled configurations are at rest when simulated again for 1 s", "[tabletop_sim][suite][physics]") {
  const GeneratorOptions o = suite_options();
  for (const auto& sc : suite().scenes) {
    std::vector<SimBody> bodies;
    for (const auto& p : sc.physical) bodies.push_back(p.body);
    const Drift d = resimulate(bodies, o.table, o.settle, 1.0);
    INFO("scene seed " << sc.seed << " worst box " << d.worst_body);
    CHECK(d.max_translation <= 0.002);
    CHECK(d.max_rotation <= kDeg);
  }
}

TEST_CASE("Supported boxes touch their supporter; hidden boxes float over nothing detected", "[tabletop_sim][suite]") {
  for (const auto& sc : suite().scenes) {
    INFO("scene seed " << sc.seed);
    std::map<std::string, const SceneObject*> by_id;
    for (const auto& o : sc.objects) by_id[o.id] = &o;
    for (const auto& [up, lo] : sc.support) {
      const SceneObject& u = *by_id.at(up);
      REQUIRE(u.physical >= 0);
      const Box ub = sc.physical[static_cast<std::size_t>(u.physical)].body.box;
      CHECK(u.clean_pose.t == ub.pose.t);  // real boxes are stated at their true pose (before noise)
      if (lo == "table") {
        CHECK(std::abs(lowest_z(ub)) <= 0.002);
      } else {
        const SceneObject& l = *by_id.at(lo);
        REQUIRE(l.physical >= 0);
        const Box lb = sc.physical[static_cast<std::size_t>(l.physical)].body.box;
        CHECK(box_distance(ub, lb) <= 0.002);
        CHECK(ub.pose.t.z() > lb.pose.t.z());
      }
    }
    for (const auto& o : sc.objects) {
      if (!o.hidden) continue;
      CHECK(o.false_kind == FalseKind::none);
      CHECK(std::none_of(sc.support.begin(), sc.support.end(), [&](const auto& e) { return e.first == o.id; }));
      CHECK(lowest_z(clean_box(o)) > 0.01);
      // What it physically rests on exists, was simulated, and is missing from the scene.
      bool rests_on_undetected = false;
      for (const auto& [a, b] : sc.relations.support) {
        if (a == o.physical && b != kTableIndex) rests_on_undetected |= sc.physical[static_cast<std::size_t>(b)].undetected;
      }
      CHECK(rests_on_undetected);
    }
  }
}

TEST_CASE("False estimates interpenetrate or float tilted", "[tabletop_sim][suite]") {
  int intersecting = 0, floating = 0;
  for (const auto& sc : suite().scenes) {
    for (const auto& f : sc.objects) {
      if (f.false_kind == FalseKind::none) continue;
      INFO("scene seed " << sc.seed << " " << f.id << " " << to_string(f.false_kind));
      const Box fb = clean_box(f);
      double deepest = -1.0;
      double nearest = 1e9;
      for (const auto& o : sc.objects) {
        if (&o == &f) continue;
        const Box ob = clean_box(o);
        if (o.false_kind == FalseKind::none) deepest = std::max(deepest, sat_overlap(fb, ob));
        nearest = std::min(nearest, box_distance(fb, ob));
      }
      const bool penetrates = deepest >= 0.01;
      const bool floats = lowest_z(fb) >= 0.02 && nearest >= 0.02 && tilt_from_vertical(fb.pose.q) >= 10 * kDeg;
      CHECK((penetrates || floats));
      intersecting += penetrates;
      floating += floats;
    }
  }
  CHECK(intersecting >= 4);
  CHECK(floating >= 4);
}

TEST_CASE("Estimates carry the configured noise and keypoints reproject at the true pose", "[tabletop_sim][suite]") {
  const GeneratorOptions o = suite_options();
  double sum_t2 = 0.0, sum_r2 = 0.0;
  int n = 0, inliers = 0, total = 0;
  for (const auto& sc : suite().scenes) {
    for (const auto& obj : sc.objects) {
      sum_t2 += (obj.estimate.t - obj.clean_pose.t).squaredNorm();
      sum_r2 += std::pow(rotation_angle(obj.estimate.q, obj.clean_pose.q), 2);
      ++n;
      for (std::size_t k = 0; k < obj.keypoints.model.size(); ++k) {
        const auto uv = project(sc.camera, sc.table_from_camera, obj.clean_pose.apply(obj.keypoints.model[k]));
        REQUIRE(uv);
        inliers += (*uv - obj.keypoints.image[k]).norm() < 5.0 * o.keypoints.pixel_sigma;
        ++total;
      }
    }
  }
  const double rms_t = std::sqrt(sum_t2 / n);
  const double rms_r = std::sqrt(sum_r2 / n);
  CHECK(rms_t == Approx(o.corruption.sigma_translation).epsilon(0.15));
  CHECK(rms_r == Approx(o.corruption.sigma_rotation).epsilon(0.15));
  const double inlier_fraction = static_cast<double>(inliers) / total;
  CHECK(inlier_fraction > 1.0 - o.keypoints.outlier_rate - 0.02);
  CHECK(inlier_fraction < 1.0 - o.keypoints.outlier_rate + 0.02);
}
