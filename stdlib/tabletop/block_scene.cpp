#include "stdlib/tabletop/block_scene.h"

#include "stdlib/tabletop/gap_noise.h"
#include "stdlib/tabletop/tilt_noise.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <utility>

namespace ksmc::stdlib::tabletop::blocks {

Scene::Scene(tabletop::Scene input) : input_(std::move(input)) {
  const Obb slab = input_.table.obb();
  table_pose_.t = slab.center;
  const std::size_t n = bodies();
  boxes_.resize(n);
  box_valid_.assign(n, 0);
  pairs_.assign(n * n, PairSlot{});
  fits_.resize(n);
  memo_.assign(n, 0.0);
  memo_valid_.assign(n, 0);
  for (const auto& o : input_.objects) input_poses_.push_back(o.pose);
  const EvidenceParams defaults;
  // A scene whose depth noise is known (the cloud front end's) takes it as is: its poses were
  // seated on their supporters, so their gaps are 0 and say nothing of the noise.
  const GapNoise noise = input_.depth_noise > 0.0
                             ? GapNoise{input_.depth_noise, std::numeric_limits<std::size_t>::max()}
                             : gap_noise(input_, defaults.stable_tol_rad);
  vertical_tolerance_ = tabletop::vertical_tolerance(noise, 3.0, defaults.intersect_eps, defaults.vertical_contact_eps);
  gap_sigma_ = tabletop::vertical_tolerance(noise, 1.0, 0.0, vertical_tolerance_ / 3.0);
  const TiltNoise tilts = tilt_noise(input_, defaults.stable_tol_rad);
  if (tilts.tilts >= 3) tilt_sigma_ = tilts.sigma;
}

const KeypointFit& Scene::fit(std::int32_t c) const {
  auto& slot = fits_.at(static_cast<std::size_t>(c));
  if (!slot) {
    if (c == 0) {
      slot = KeypointFit{};
    } else {
      SceneObject o = input_.objects.at(static_cast<std::size_t>(c - 1));
      o.pose = input_poses_[static_cast<std::size_t>(c - 1)];
      slot = fit_keypoints(input_, o);
    }
  }
  return *slot;
}

std::vector<std::string> Scene::names() const {
  std::vector<std::string> out{kTableId};
  for (const auto& o : input_.objects) out.push_back(o.id);
  return out;
}

const Pose& Scene::pose(std::int32_t c) const {
  if (c == 0) return table_pose_;
  return input_.objects.at(static_cast<std::size_t>(c - 1)).pose;
}

const Eigen::Vector3d& Scene::size(std::int32_t c) const {
  if (c == 0) return input_.table.size;
  return input_.objects.at(static_cast<std::size_t>(c - 1)).size;
}

const Obb& Scene::box(std::int32_t c) const {
  const auto i = static_cast<std::size_t>(c);
  if (!box_valid_.at(i)) {
    boxes_[i] = c == 0 ? input_.table.obb() : input_.objects[i - 1].obb();
    box_valid_[i] = 1;
  }
  return boxes_[i];
}

std::size_t Scene::slot(std::int32_t a, std::int32_t b) const {
  const auto lo = static_cast<std::size_t>(std::min(a, b)), hi = static_cast<std::size_t>(std::max(a, b));
  return lo * bodies() + hi;
}

const PairGeometry& Scene::pair(std::int32_t a, std::int32_t b, double exact_below) const {
  if (a == b) throw std::invalid_argument("blocks::Scene::pair: a body paired with itself");
  PairSlot& s = pairs_.at(slot(a, b));
  // A cached gap that is only a lower bound is good enough while it exceeds the tolerance
  // asked about; otherwise compute the exact distance.
  const bool enough = s.valid && (s.g.distance_exact || s.g.distance > exact_below || s.exact_below >= exact_below);
  if (!enough) {
    const std::int32_t lo = std::min(a, b), hi = std::max(a, b);
    s.exact_below = std::max(exact_below, s.valid ? s.exact_below : 0.0);
    s.g = pair_geometry(box(lo), box(hi), s.exact_below);
    s.valid = true;
  }
  return s.g;
}

void Scene::set_pose(std::int32_t c, const Pose& pose) {
  if (c <= 0 || static_cast<std::size_t>(c) >= bodies())
    throw std::out_of_range("blocks::Scene::set_pose: not an object body");
  if (undo_.active) throw std::logic_error("blocks::Scene::set_pose: the previous move is neither committed nor undone");
  const auto i = static_cast<std::size_t>(c);
  undo_.active = true;
  undo_.body = c;
  undo_.pose = input_.objects[i - 1].pose;
  undo_.box = boxes_[i];
  undo_.box_valid = box_valid_[i];
  undo_.row.resize(bodies());
  for (std::size_t j = 0; j < bodies(); ++j) {
    PairSlot& s = pairs_[slot(c, static_cast<std::int32_t>(j))];
    undo_.row[j] = s;
    s.valid = false;
  }
  input_.objects[i - 1].pose = pose;
  box_valid_[i] = 0;
  std::fill(memo_valid_.begin(), memo_valid_.end(), 0);
}

void Scene::undo() {
  if (!undo_.active) return;
  const auto i = static_cast<std::size_t>(undo_.body);
  input_.objects[i - 1].pose = undo_.pose;
  boxes_[i] = undo_.box;
  box_valid_[i] = undo_.box_valid;
  for (std::size_t j = 0; j < bodies(); ++j) pairs_[slot(undo_.body, static_cast<std::int32_t>(j))] = undo_.row[j];
  undo_.active = false;
  std::fill(memo_valid_.begin(), memo_valid_.end(), 0);
}

std::optional<double> Scene::memo(std::int32_t c, double key) const {
  const auto i = static_cast<std::size_t>(c);
  if (key != memo_key_ || !memo_valid_.at(i)) return std::nullopt;
  return memo_[i];
}

void Scene::set_memo(std::int32_t c, double key, double value) const {
  if (key != memo_key_) {
    memo_key_ = key;
    std::fill(memo_valid_.begin(), memo_valid_.end(), 0);
  }
  const auto i = static_cast<std::size_t>(c);
  memo_.at(i) = value;
  memo_valid_[i] = 1;
}

void Scene::note_hover_tolerance(double eps) const {
  if (std::find(hover_eps_.begin(), hover_eps_.end(), eps) == hover_eps_.end()) hover_eps_.push_back(eps);
}

}  // namespace ksmc::stdlib::tabletop::blocks
