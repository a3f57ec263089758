#include "stdlib/tabletop/kit/tabletop_model.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "stdlib/tabletop/kit/kit_likelihood.h"

namespace ksmc::stdlib::tabletop::kit {

namespace {

std::vector<std::string> body_ids(const Scene& s) {
  std::vector<std::string> ids{kTableId};
  for (const auto& o : s.objects) ids.push_back(o.id);
  return ids;
}

}  // namespace

TabletopModel::TabletopModel(std::shared_ptr<const Scene> initial, std::shared_ptr<const KitConfig> config,
                             const runtime::domain::MlnBinding& binding)
    : config_(std::move(config)), scene_(*initial), mln_(binding, body_ids(scene_)) {
  for (std::size_t i = 0; i < scene_.objects.size(); ++i)
    if (!scene_.objects[i].keypoints_model.empty()) observed_.push_back(i);
  recompute_all();
}

void TabletopModel::recompute_all() {
  evidence_ = extract_evidence(scene_, config_->evidence);
  object_ll_.assign(scene_.objects.size(), 0.0);
  log_likelihood_ = 0.0;
  for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
    object_ll_[i] = object_log_likelihood_at(i, scene_.objects[i].pose);
    log_likelihood_ += object_ll_[i];
  }
  outcome_ = mln_.evaluate(evidence_);
  moving_ = false;
}

double TabletopModel::object_log_likelihood_at(std::size_t object, const Pose& pose) const {
  return kit::object_log_likelihood(scene_, scene_.objects.at(object), pose, config_->likelihood);
}

void TabletopModel::begin_move(std::size_t object, const Pose& pose, double ll_at_pose) {
  if (moving_) throw std::logic_error("TabletopModel::begin_move: a move is already pending");
  if (object >= scene_.objects.size()) throw std::out_of_range("TabletopModel::begin_move: no such object");
  moving_ = true;
  moved_ = object;
  old_pose_ = scene_.objects[object].pose;
  old_object_ll_ = object_ll_[object];
  old_log_likelihood_ = log_likelihood_;
  old_outcome_ = outcome_;

  scene_.objects[object].pose = pose;
  const double ll = std::isnan(ll_at_pose) ? object_log_likelihood_at(object, pose) : ll_at_pose;
  object_ll_[object] = ll;
  log_likelihood_ = old_log_likelihood_ - old_object_ll_ + ll;
  if (!std::isfinite(log_likelihood_) || !std::isfinite(old_log_likelihood_)) {
    // Sums with infinities cannot be updated by differences.
    log_likelihood_ = 0.0;
    for (const double v : object_ll_) log_likelihood_ += v;
  }
  tentative_ = evidence_;  // copy-assignment reuses the storage of the previous move
  update_evidence(tentative_, scene_, object, config_->evidence);
  outcome_ = mln_.evaluate(tentative_);
}

void TabletopModel::accept() {
  if (!moving_) return;
  std::swap(evidence_, tentative_);
  moving_ = false;
  old_outcome_.reset();
}

void TabletopModel::reject() {
  if (!moving_) return;
  scene_.objects[moved_].pose = old_pose_;
  object_ll_[moved_] = old_object_ll_;
  log_likelihood_ = old_log_likelihood_;
  outcome_ = std::move(old_outcome_);
  moving_ = false;
}

runtime::mcmc::Snapshot TabletopModel::snapshot() const {
  nlohmann::json poses = nlohmann::json::array();
  for (const auto& o : scene_.objects)
    poses.push_back({{"id", o.id},
                     {"t", {o.pose.t.x(), o.pose.t.y(), o.pose.t.z()}},
                     {"q", {o.pose.q.w(), o.pose.q.x(), o.pose.q.y(), o.pose.q.z()}}});
  return nlohmann::json{{"poses", std::move(poses)}};
}

void TabletopModel::restore(const runtime::mcmc::Snapshot& state) {
  const auto& poses = state.at("poses");
  if (!poses.is_array() || poses.size() != scene_.objects.size())
    throw std::invalid_argument("TabletopModel::restore: snapshot does not match the scene");
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const auto& p = poses[i];
    if (p.at("id").get<std::string>() != scene_.objects[i].id)
      throw std::invalid_argument(fmt::format("TabletopModel::restore: snapshot object {} is not '{}'", i,
                                              scene_.objects[i].id));
    const auto& t = p.at("t");
    const auto& q = p.at("q");
    scene_.objects[i].pose.t = Eigen::Vector3d(t.at(0).get<double>(), t.at(1).get<double>(), t.at(2).get<double>());
    scene_.objects[i].pose.q = Eigen::Quaterniond(q.at(0).get<double>(), q.at(1).get<double>(),
                                                  q.at(2).get<double>(), q.at(3).get<double>());
  }
  recompute_all();
}

}  // namespace ksmc::stdlib::tabletop::kit
