#include "stdlib/tabletop/kit/tabletop_model.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>

#include <fmt/format.h>

#include "runtime/mln/mcsat.h"
#include "stdlib/tabletop/cloud_likelihood.h"
#include "stdlib/tabletop/kit/kit_likelihood.h"

namespace ksmc::stdlib::tabletop::kit {

namespace rd = ksmc::runtime::domain;

namespace {

rd::SemanticOptions semantic_options(const KitOptions& o) {
  rd::SemanticOptions s;
  s.cache_capacity = o.cache_capacity;
  s.log_z = true;  // both readings of `prior mln` are reported (summary, tests)
  s.log_map = true;
  // mln::infer's own sampling defaults (components too large to enumerate), as the kit has
  // always run them.
  const runtime::mln::McSatOptions mcsat;
  s.mcsat_samples = static_cast<std::uint64_t>(mcsat.samples);
  s.mcsat_burn_in = static_cast<std::uint64_t>(mcsat.burn_in);
  return s;
}

bool has_mln_prior(const blocks::Binding& b) {
  for (const auto& p : b.priors)
    if (std::holds_alternative<blocks::MlnPrior>(p)) return true;
  return false;
}

}  // namespace

TabletopModel::TabletopModel(std::shared_ptr<const Scene> initial, const blocks::Binding& binding, KitOptions options)
    : binding_(binding),
      options_(options),
      mln_prior_(has_mln_prior(binding)),
      input_(initial),
      scene_(*initial),
      sem_(binding, semantic_options(options)) {
  cloud_ = cloud_term();
  const CloudObservation* cloud = cloud_;
  for (std::size_t i = 0; i < scene().objects.size(); ++i)
    if ((binding.likelihood.keypoint_term && !scene().objects[i].keypoints_model.empty()) ||
        (cloud != nullptr && i < cloud->object_points.size() && !cloud->object_points[i].empty()))
      observed_.push_back(i);
  likelihood_ = binding.likelihood;
  if (binding.likelihood.keypoint_term) {
    // From the fits the scene caches for the fit kernel: each object is fitted once.
    static_cast<blocks::KeypointGaussian&>(likelihood_) =
        scene_likelihood(*initial, binding.likelihood, [this](std::size_t i) -> const KeypointFit& {
          return scene_.fit(blocks::Scene::body_of_object(i));
        });
  }
  recompute_all();
}

double TabletopModel::prior_of(const rd::Outcome& o) const {
  if (!o.possible) return -std::numeric_limits<double>::infinity();
  double lp = 0.0;
  if (mln_prior_) lp += options_.prior_quantity == PriorQuantity::map ? o.log_map : o.log_z;
  if (!binding_.conditional_priors.empty()) lp += sem_.conditional_priors(scene_, o);
  return lp;
}

void TabletopModel::recompute_all() {
  object_ll_.assign(scene().objects.size(), 0.0);
  log_likelihood_ = 0.0;
  for (std::size_t i = 0; i < scene().objects.size(); ++i) {
    object_ll_[i] = object_log_likelihood_at(i, scene().objects[i].pose);
    log_likelihood_ += object_ll_[i];
  }
  outcome_ = sem_.evaluate(scene_, scene_.bodies());
  log_prior_ = prior_of(*outcome_);
  moving_ = false;
}

const CloudObservation* TabletopModel::cloud_term() const {
  if (!binding_.likelihood.cloud || scene().cloud == nullptr) return nullptr;
  if (scene().cloud->object_points.size() != scene().objects.size())
    throw std::invalid_argument(fmt::format("cloud.surface: the scene's cloud has point sets for {} objects, the scene has {}",
                                            scene().cloud->object_points.size(), scene().objects.size()));
  return scene().cloud.get();
}

double TabletopModel::object_log_likelihood_at(std::size_t object, const Pose& pose) const {
  const SceneObject& o = scene().objects.at(object);
  double ll = likelihood_.keypoint_term ? kit::object_log_likelihood(scene(), o, pose, likelihood_) : 0.0;
  if (const CloudObservation* cloud = cloud_) {  // cloud.surface
    const blocks::CloudSurface& c = *likelihood_.cloud;
    const Obb box = Obb::from_pose(pose, o.size);
    ll += cloud_log_likelihood(cloud->object_points[object], box,
                               {c.sigma, c.robust, c.outlier, c.inside_sigma, cloud->sensor});
    if (c.free_space_cost > 0.0) ll -= c.free_space_cost * static_cast<double>(cloud->rays.see_through_count(box));
  }
  // The input pose estimate as a measurement (keypoints.gaussian's estimate_sigma_*).
  const Pose& estimate = input_->objects[object].pose;
  const double sigma_t = options_.pose_sigma_t.value_or(binding_.likelihood.estimate_sigma_t);
  const double sigma_r = options_.pose_sigma_r.value_or(binding_.likelihood.estimate_sigma_r);
  if (sigma_t > 0.0) {
    const double d = (pose.t - estimate.t).norm() / sigma_t;
    ll -= 0.5 * d * d;
  }
  if (sigma_r > 0.0) {
    const double a = Eigen::AngleAxisd(pose.q * estimate.q.conjugate()).angle() / sigma_r;
    ll -= 0.5 * a * a;
  }
  return ll;
}

void TabletopModel::begin_move(std::size_t object, const Pose& pose, double ll_at_pose) {
  if (moving_) throw std::logic_error("TabletopModel::begin_move: a move is already pending");
  if (object >= scene().objects.size()) throw std::out_of_range("TabletopModel::begin_move: no such object");
  moving_ = true;
  moved_ = object;
  old_object_ll_ = object_ll_[object];
  old_log_likelihood_ = log_likelihood_;
  old_log_prior_ = log_prior_;
  old_outcome_ = outcome_;

  const std::int32_t body = blocks::Scene::body_of_object(object);
  // hover(j) reads every pair of j: it can change only for bodies whose touching status
  // with the moved body changes (blocks::touching_row); overhang(j) reads the poses of the
  // bodies j touches: it can change for every body touching the moved one, before or after
  // the move. Those bodies are re-extracted too.
  const std::vector<std::uint32_t> before = blocks::touching_row(scene_, body);
  scene_.set_pose(body, pose);
  const std::vector<std::uint32_t> after = blocks::touching_row(scene_, body);
  changed_.assign(1, body);
  const bool every = scene_.hover_tolerances().size() > 32;  // more than touching_row tracks
  for (std::size_t j = 0; j < before.size(); ++j)
    if (static_cast<std::int32_t>(j) != body && (every || (before[j] | after[j]) != 0))
      changed_.push_back(static_cast<std::int32_t>(j));

  const double ll = std::isnan(ll_at_pose) ? object_log_likelihood_at(object, pose) : ll_at_pose;
  object_ll_[object] = ll;
  log_likelihood_ = old_log_likelihood_ - old_object_ll_ + ll;
  if (!std::isfinite(log_likelihood_) || !std::isfinite(old_log_likelihood_)) {
    // Sums with infinities cannot be updated by differences.
    log_likelihood_ = 0.0;
    for (const double v : object_ll_) log_likelihood_ += v;
  }
  outcome_ = sem_.update(scene_, scene_.bodies(), changed_, *old_outcome_);
  log_prior_ = prior_of(*outcome_);
}

void TabletopModel::accept() {
  if (!moving_) return;
  scene_.commit();
  moving_ = false;
  old_outcome_.reset();
}

void TabletopModel::reject() {
  if (!moving_) return;
  scene_.undo();
  object_ll_[moved_] = old_object_ll_;
  log_likelihood_ = old_log_likelihood_;
  log_prior_ = old_log_prior_;
  outcome_ = std::move(old_outcome_);
  moving_ = false;
}

runtime::mcmc::Snapshot TabletopModel::snapshot() const {
  nlohmann::json poses = nlohmann::json::array();
  for (const auto& o : scene().objects)
    poses.push_back({{"id", o.id},
                     {"t", {o.pose.t.x(), o.pose.t.y(), o.pose.t.z()}},
                     {"q", {o.pose.q.w(), o.pose.q.x(), o.pose.q.y(), o.pose.q.z()}}});
  return nlohmann::json{{"poses", std::move(poses)}};
}

void TabletopModel::restore(const runtime::mcmc::Snapshot& state) {
  const auto& poses = state.at("poses");
  if (!poses.is_array() || poses.size() != scene().objects.size())
    throw std::invalid_argument("TabletopModel::restore: snapshot does not match the scene");
  if (moving_) reject();
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const auto& p = poses[i];
    if (p.at("id").get<std::string>() != scene().objects[i].id)
      throw std::invalid_argument(fmt::format("TabletopModel::restore: snapshot object {} is not '{}'", i,
                                              scene().objects[i].id));
    const auto& t = p.at("t");
    const auto& q = p.at("q");
    Pose pose;
    pose.t = Eigen::Vector3d(t.at(0).get<double>(), t.at(1).get<double>(), t.at(2).get<double>());
    pose.q = Eigen::Quaterniond(q.at(0).get<double>(), q.at(1).get<double>(), q.at(2).get<double>(),
                                q.at(3).get<double>());
    scene_.set_pose(blocks::Scene::body_of_object(i), pose);
    scene_.commit();
  }
  recompute_all();
}

}  // namespace ksmc::stdlib::tabletop::kit
