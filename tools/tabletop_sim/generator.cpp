#include "tools/tabletop_sim/generator.h"

#include <algorithm>
#include <map>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

namespace ksmc::tools::tabletop_sim {

namespace {

// Independent random streams per stage, so that e.g. keypoint settings do not change physics.
enum Stage : std::uint64_t { kLayout = 1, kCorrupt = 2, kView = 3, kNoise = 4, kOrder = 5, kCount = 6 };
std::uint64_t stage_seed(std::uint64_t seed, int attempt, Stage stage) {
  return mix_seed(seed, static_cast<std::uint64_t>(attempt) * 16 + stage);
}

struct Draft {
  std::vector<PhysicalBox> physical;
  Relations relations;
  std::vector<SceneObject> objects;  // physical order, then false extras
  double settle_time = 0.0;
  Eigen::Vector2d region;
};

// Steps 1-3: layout, Bullet settling, true relations.
// The box count is drawn once per scene, so redraws (more frequent for crowded tables) do not
// bias the generated counts towards small scenes.
// Draws past max_attempts (a second round, after the first failed) widen the drop region by
// half: a box count drawn too large for the usual region (24 boxes: placement, settling and
// the camera's view fail there) still yields a scene, and every scene found in the first
// round is as it was.
std::optional<Draft> simulate(std::uint64_t seed, int attempt, int n, const GeneratorOptions& o, std::string& why) {
  Rng rng(stage_seed(seed, attempt, kLayout));
  auto layout = draw_layout(rng, n, o.table, o.layout, attempt < o.max_attempts ? 1.0 : 1.5);
  if (!layout) {
    why = fmt::format("could not place {} boxes without overlap", n);
    return std::nullopt;
  }
  const SettleResult settled = settle(layout->bodies, o.table, o.settle);
  if (settled.status != SettleStatus::settled) {
    why = fmt::format("{} boxes: {}", n, settled.detail);
    return std::nullopt;
  }
  Draft d;
  d.settle_time = settled.time;
  d.region = layout->region_half;
  std::vector<Box> boxes;
  for (std::size_t i = 0; i < layout->bodies.size(); ++i) {
    PhysicalBox p{layout->items[i], layout->bodies[i], false};
    p.body.box.pose = settled.poses[i];
    boxes.push_back(p.body.box);
    d.physical.push_back(p);
  }
  d.relations = compute_relations(boxes, o.relations);
  return d;
}

bool supports_present(int i, const Relations& rel, const std::vector<PhysicalBox>& physical) {
  return std::any_of(rel.support.begin(), rel.support.end(), [&](const auto& s) {
    return s.second == i && !physical[static_cast<std::size_t>(s.first)].undetected;
  });
}

// Steps 4-5: undetected supporters (-> hidden) and false estimates.
void corrupt(std::uint64_t seed, int attempt, const GeneratorOptions& o, Draft& d) {
  Rng rng(stage_seed(seed, attempt, kCorrupt));
  std::vector<Box> boxes;
  for (const auto& p : d.physical) boxes.push_back(p.body.box);
  const auto removed = choose_undetected(rng, boxes, d.relations, o.corruption);
  const auto hidden = hidden_boxes(boxes.size(), d.relations, removed);
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    d.physical[i].undetected = removed[i];
    if (removed[i]) continue;
    SceneObject s;
    s.item = d.physical[i].item;
    s.physical = static_cast<int>(i);
    s.hidden = hidden[i];
    s.stable = d.relations.stable[i];
    s.clean_pose = boxes[i].pose;
    d.objects.push_back(s);
  }

  const std::size_t real_count = d.objects.size();
  std::vector<Box> placed_false;
  std::vector<Box> floating_false;
  std::vector<std::size_t> targeted;  // boxes a false estimate intersects: their estimate stays put
  // A moved estimate must belong to a detected, non-hidden box that carries nothing detected.
  auto movable_objects = [&] {
    std::vector<std::size_t> movable;
    for (std::size_t c = 0; c < real_count; ++c) {
      const auto& obj = d.objects[c];
      const bool is_target = std::find(targeted.begin(), targeted.end(), c) != targeted.end();
      if (obj.false_kind != FalseKind::none || obj.hidden || is_target ||
          supports_present(obj.physical, d.relations, d.physical)) {
        continue;
      }
      // Boxes that touch only this one must not be left hovering by moving its estimate away.
      std::vector<bool> missing = removed;
      for (const auto& other : d.objects) {
        if (other.false_kind != FalseKind::none && other.physical >= 0) missing[static_cast<std::size_t>(other.physical)] = true;
      }
      missing[static_cast<std::size_t>(obj.physical)] = true;
      if (estimate_is_consistent(boxes, d.relations, missing, o.corruption)) movable.push_back(c);
    }
    return movable;
  };
  // Floating false estimates placed earlier must stay clear of everything.
  auto crowds = [&](const std::optional<Box>& box) {
    return std::any_of(floating_false.begin(), floating_false.end(), [&](const Box& f) {
      return box && sat_overlap(*box, f) > -o.corruption.min_float_gap && box_distance(*box, f) < o.corruption.min_float_gap;
    });
  };
  auto pick = [&](const std::vector<std::size_t>& from) {
    return from[static_cast<std::size_t>(rng.uniform_int(0, static_cast<int>(from.size()) - 1))];
  };
  for (std::size_t k = 0; k < real_count; ++k) {
    if (!rng.bernoulli(o.corruption.false_rate)) continue;
    if (o.corruption.extra_kind_rate > 0.0 && rng.bernoulli(o.corruption.extra_kind_rate)) {
      const ExtraKind kind = kExtraKinds[rng.weighted_index(o.corruption.extra_kinds.odds)];
      const bool copy = kind == ExtraKind::shifted_copy || kind == ExtraKind::duplicate;
      std::vector<std::size_t> candidates;
      if (copy) {
        for (std::size_t c = 0; c < real_count; ++c)
          if (d.objects[c].false_kind == FalseKind::none) candidates.push_back(c);
      } else {
        candidates = movable_objects();
      }
      if (candidates.empty()) continue;
      const std::size_t c = pick(candidates);
      const Box original{d.objects[c].item.size, d.objects[c].clean_pose};
      const auto& p = o.corruption.extra_kinds;
      std::optional<Box> box = kind == ExtraKind::shifted_copy ? shifted_copy(rng, original, p)
                               : kind == ExtraKind::duplicate  ? duplicate_detection(rng, original, p)
                               : kind == ExtraKind::wrong_size ? wrong_size(rng, original, p)
                                                               : flipped(rng, original, p);
      if (!box || crowds(box)) continue;
      placed_false.push_back(*box);
      const FalseKind fk = kind == ExtraKind::shifted_copy ? FalseKind::shifted_copy
                           : kind == ExtraKind::duplicate  ? FalseKind::duplicate
                           : kind == ExtraKind::wrong_size ? FalseKind::wrong_size
                                                           : FalseKind::flipped;
      if (copy) {
        targeted.push_back(c);
        SceneObject s;
        s.item = d.objects[c].item;
        s.false_kind = fk;
        s.clean_pose = box->pose;
        d.objects.push_back(s);
      } else {
        auto& obj = d.objects[c];
        obj.false_kind = fk;
        obj.stable = false;
        obj.clean_pose = box->pose;
        obj.item.size = box->size;
      }
      continue;
    }
    const bool floating = rng.bernoulli(0.5);
    bool moved = rng.bernoulli(0.5);
    const std::vector<std::size_t> movable = movable_objects();
    if (movable.empty()) moved = false;
    const std::size_t mover = moved ? movable[static_cast<std::size_t>(rng.uniform_int(0, static_cast<int>(movable.size()) - 1))] : 0;
    const BoxItem item = moved ? d.objects[mover].item : draw_box(rng, o.layout.catalogue);

    std::optional<Box> box;
    if (floating) {
      std::vector<Box> others = placed_false;
      for (std::size_t i = 0; i < boxes.size(); ++i) {
        if (!(moved && d.objects[mover].physical == static_cast<int>(i))) others.push_back(boxes[i]);
      }
      box = place_floating(rng, item, others, d.region, o.corruption);
    } else {
      std::vector<std::size_t> targets;
      for (std::size_t c = 0; c < real_count; ++c) {
        if (!(moved && c == mover) && d.objects[c].false_kind == FalseKind::none) targets.push_back(c);
      }
      if (!targets.empty()) {
        const auto t = targets[static_cast<std::size_t>(rng.uniform_int(0, static_cast<int>(targets.size()) - 1))];
        box = place_intersecting(rng, item, Box{d.objects[t].item.size, d.objects[t].clean_pose}, o.corruption);
        if (box) targeted.push_back(t);
        if (crowds(box)) box.reset();
      }
    }
    if (!box) continue;
    placed_false.push_back(*box);
    if (floating) floating_false.push_back(*box);
    const FalseKind kind = floating ? (moved ? FalseKind::moved_floating : FalseKind::extra_floating)
                                    : (moved ? FalseKind::moved_intersecting : FalseKind::extra_intersecting);
    if (moved) {
      auto& obj = d.objects[mover];
      obj.false_kind = kind;
      obj.stable = false;
      obj.clean_pose = box->pose;
    } else {
      SceneObject s;
      s.item = item;
      s.false_kind = kind;
      s.clean_pose = box->pose;
      d.objects.push_back(s);
    }
  }
}

// Step 6: a camera that sees every detected box well enough, and the keypoints.
bool observe(std::uint64_t seed, int attempt, const GeneratorOptions& o, Draft& d, Pose& camera_pose) {
  Rng rng(stage_seed(seed, attempt, kView));
  std::vector<Box> boxes;
  for (const auto& p : d.physical) boxes.push_back(p.body.box);
  for (int view = 0; view < 8; ++view) {
    camera_pose = draw_camera_pose(rng, o.camera_placement);
    bool all_seen = true;
    for (auto& obj : d.objects) {
      std::vector<Box> occluders;
      const bool real = obj.false_kind == FalseKind::none;
      if (real) {
        for (std::size_t i = 0; i < boxes.size(); ++i) {
          if (static_cast<int>(i) != obj.physical) occluders.push_back(boxes[i]);
        }
      }
      auto kp = sample_keypoints(rng, o.camera, camera_pose, Box{obj.item.size, obj.clean_pose}, occluders, o.keypoints);
      if (!kp) {
        all_seen = false;
        break;
      }
      obj.keypoints = std::move(*kp);
    }
    if (all_seen) return true;
  }
  return false;
}

std::string id_of(int object_index, const std::vector<SceneObject>& objects) {
  return object_index < 0 ? std::string("table") : objects[static_cast<std::size_t>(object_index)].id;
}

}  // namespace

void validate(const GeneratorOptions& o) {
  auto fail = [](const std::string& what) { throw std::invalid_argument(what); };
  if (o.min_objects < 1) fail(fmt::format("objects: minimum must be at least 1 (got {})", o.min_objects));
  if (o.max_objects > 60) fail(fmt::format("objects: maximum must be at most 60 (got {})", o.max_objects));
  if (o.min_objects > o.max_objects)
    fail(fmt::format("objects: minimum {} exceeds maximum {}", o.min_objects, o.max_objects));
  auto rate = [&](const char* name, double r) {
    if (!(r >= 0.0 && r <= 1.0)) fail(fmt::format("{} must be in [0, 1] (got {})", name, r));
  };
  rate("hidden-rate", o.corruption.hidden_rate);
  rate("false-rate", o.corruption.false_rate);
  rate("outlier-rate", o.keypoints.outlier_rate);
  if (!(o.corruption.sigma_translation >= 0.0) || !(o.corruption.sigma_rotation >= 0.0))
    fail("pose noise must be non-negative");
  if (!(o.keypoints.pixel_sigma >= 0.0)) fail("pixel noise must be non-negative");
  if (o.keypoints.min_count < 1 || o.keypoints.min_count > o.keypoints.max_count)
    fail(fmt::format("keypoints: need 1 <= min ({}) <= max ({})", o.keypoints.min_count, o.keypoints.max_count));
  if (o.max_attempts < 1) fail("max attempts must be at least 1");
}

std::size_t GeneratedScene::hidden_count() const {
  return static_cast<std::size_t>(std::count_if(objects.begin(), objects.end(), [](const auto& o) { return o.hidden; }));
}

std::size_t GeneratedScene::false_count() const {
  return static_cast<std::size_t>(
      std::count_if(objects.begin(), objects.end(), [](const auto& o) { return o.false_kind != FalseKind::none; }));
}

GeneratedScene generate_scene(std::uint64_t seed, const GeneratorOptions& o) {
  validate(o);
  GeneratedScene scene;
  scene.seed = seed;
  scene.numeric_ids = o.numeric_ids;
  scene.camera = o.camera;
  Rng count_rng(stage_seed(seed, 0, kCount));
  const int n = count_rng.uniform_int(o.min_objects, o.max_objects);
  for (int attempt = 0; attempt < 2 * o.max_attempts; ++attempt) {
    std::string why;
    auto draft = simulate(seed, attempt, n, o, why);
    if (!draft) {
      scene.redraws.push_back(why);
      continue;
    }
    corrupt(seed, attempt, o, *draft);
    if (!observe(seed, attempt, o, *draft, scene.table_from_camera)) {
      scene.redraws.push_back("some box has too few visible keypoints from every camera drawn");
      continue;
    }
    Rng noise(stage_seed(seed, attempt, kNoise));
    for (auto& obj : draft->objects) obj.estimate = add_pose_noise(noise, obj.clean_pose, o.corruption);

    // Output order is shuffled so that ids carry no hint (false extras would otherwise come last).
    Rng order(stage_seed(seed, attempt, kOrder));
    auto& objs = draft->objects;
    for (std::size_t i = objs.size(); i > 1; --i) {
      std::swap(objs[i - 1], objs[static_cast<std::size_t>(order.uniform_int(0, static_cast<int>(i) - 1))]);
    }
    std::map<int, int> object_of_physical;  // real, non-false objects only
    for (std::size_t i = 0; i < objs.size(); ++i) {
      objs[i].id = o.numeric_ids ? fmt::format("{}", i) : fmt::format("box_{}", i);
      if (objs[i].false_kind == FalseKind::none) object_of_physical[objs[i].physical] = static_cast<int>(i);
    }
    auto mapped = [&](int physical) -> std::optional<int> {
      if (physical == kTableIndex) return kTableIndex;
      const auto it = object_of_physical.find(physical);
      return it == object_of_physical.end() ? std::nullopt : std::optional<int>(it->second);
    };
    // Sort key: object order, the table after every box.
    auto key = [](int i) { return i == kTableIndex ? 1 << 30 : i; };
    std::vector<std::pair<int, int>> support;
    std::vector<std::pair<int, int>> contact;
    for (const auto& [u, l] : draft->relations.support) {
      const auto a = mapped(u);
      const auto b = mapped(l);
      if (a && b) support.emplace_back(*a, *b);
    }
    for (const auto& [u, l] : draft->relations.contact) {
      auto a = mapped(u);
      auto b = mapped(l);
      if (!a || !b) continue;
      if (key(*a) > key(*b)) std::swap(a, b);
      contact.emplace_back(*a, *b);
    }
    auto by_key = [&](const auto& x, const auto& y) {
      return std::pair(key(x.first), key(x.second)) < std::pair(key(y.first), key(y.second));
    };
    std::sort(support.begin(), support.end(), by_key);
    std::sort(contact.begin(), contact.end(), by_key);
    for (const auto& [a, b] : support) scene.support.emplace_back(id_of(a, objs), id_of(b, objs));
    for (const auto& [a, b] : contact) scene.contact.emplace_back(id_of(a, objs), id_of(b, objs));

    scene.physical = std::move(draft->physical);
    scene.relations = std::move(draft->relations);
    scene.objects = std::move(objs);
    scene.settle_time = draft->settle_time;
    scene.attempts = attempt + 1;
    return scene;
  }
  // Each reason with how many draws it ended, in order of first occurrence.
  std::vector<std::pair<std::string, int>> reasons;
  for (const auto& why : scene.redraws) {
    auto it = std::find_if(reasons.begin(), reasons.end(), [&](const auto& r) { return r.first == why; });
    if (it == reasons.end()) reasons.emplace_back(why, 1);
    else ++it->second;
  }
  std::string summary;
  for (const auto& [why, count] : reasons) summary += fmt::format("{}{} x {}", summary.empty() ? "" : "; ", count, why);
  throw std::runtime_error(fmt::format("scene seed {}: no valid scene after {} draws ({})", seed, 2 * o.max_attempts,
                                       summary.empty() ? std::string("none") : summary));
}

}  // namespace ksmc::tools::tabletop_sim
