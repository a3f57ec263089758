// The table-top posterior of eq. 4.1 as an mcmc::Model, driven by a domain's binding:
//   log p(M|D) = log p(D|M) + log p(M)
//   log p(D|M) = Σ_o keypoint log-likelihood of o at its pose (eq. 4.4, kit_likelihood.h)
//                + Σ_o cloud log-likelihood of o's points and the rays its box blocks
//                (`cloud.surface`, cloud_likelihood.h; scenes of the --cloud front end)
//   log p(M)   = with `prior mln`: eq. 4.3 for the scene graph of the poses, Σ w n of the
//                world made of the extracted evidence and the most probable query atoms (or,
//                with PriorQuantity::log_z, log Z over the query atoms); plus the conditional
//                prior terms of the binding
// The evidence is what the binding's generated extractors say of the scene
// (runtime/domain/semantics.h), the Markov logic run only for new evidence bits. The state is
// the pose of every object (sizes and keypoints are fixed). A move changes one object's pose:
// only atoms touching it (and hover atoms of bodies whose touching status with it changes)
// are re-extracted, its likelihood term recomputed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "runtime/domain/semantics.h"
#include "runtime/mcmc/model.h"
#include "stdlib/tabletop/blocks.h"
#include "stdlib/tabletop/scene.h"

namespace ksmc::stdlib::tabletop::kit {

// What `prior mln` scores a state with (docs/tabletop_kit.md, "Posterior"):
//   map   — eq. 4.3 for the scene graph the state stands for: Σ_i w_i n_i(x*) of the world
//           x* = (extracted evidence, most probable query atoms), the default;
//   log_z — log Σ_q exp(Σ_i w_i n_i(e, q)) over all query worlds (the earlier reading; it
//           rewards evidence that leaves query atoms unconstrained, i.e. fewer relations).
enum class PriorQuantity { map, log_z };

// Sampler settings that are not part of a domain file (tests and calibration compare them).
struct KitOptions {
  PriorQuantity prior_quantity = PriorQuantity::map;
  // The current pose takes part in the refine move's choice of the best weight (refine_kernel.h).
  bool current_competes = true;
  std::size_t cache_capacity = 512;
  // Overrides of the domain's pose-estimate measurement (keypoints.gaussian's
  // estimate_sigma_t / estimate_sigma_r, declared in the domain file; 0 turns it off), for
  // evaluations that compare settings. Unset: the domain's values run.
  std::optional<double> pose_sigma_t;  // [m]
  std::optional<double> pose_sigma_r;  // [rad]
};

class TabletopModel : public runtime::mcmc::Model {
 public:
  // `binding` must outlive the model (the generated binding is a static).
  TabletopModel(std::shared_ptr<const Scene> initial, const blocks::Binding& binding, KitOptions options = {});

  double log_likelihood() const override { return log_likelihood_; }
  double log_prior() const override { return log_prior_; }
  void accept() override;
  void reject() override;
  runtime::mcmc::Snapshot snapshot() const override;
  void restore(const runtime::mcmc::Snapshot& state) override;

  // Tentatively moves object `object` (index into scene().objects) to `pose`.
  // `log_likelihood_at_pose` may pass the object's likelihood at `pose` when the caller
  // already computed it (the proposal does); NaN to compute it here.
  void begin_move(std::size_t object, const Pose& pose, double log_likelihood_at_pose);
  bool in_move() const noexcept { return moving_; }

  const Scene& scene() const noexcept { return scene_.input(); }
  const blocks::Scene& block_scene() const noexcept { return scene_; }
  const runtime::domain::Outcome& outcome() const noexcept { return *outcome_; }
  const runtime::domain::Semantics<blocks::Scene>& semantics() const noexcept { return sem_; }
  const blocks::Binding& binding() const noexcept { return binding_; }
  const KitOptions& options() const noexcept { return options_; }
  // The likelihood this scene is scored with (the binding's; the keypoint σ from the scene
  // when it declares sigma_from_scene; kit_likelihood.h).
  const blocks::Likelihood& likelihood() const noexcept { return likelihood_; }
  // Object `object`'s input pose estimate (the chain's start and the pose-estimate term's mean).
  const Pose& input_pose(std::size_t object) const { return input_->objects.at(object).pose; }
  double object_log_likelihood(std::size_t object) const { return object_ll_[object]; }
  double object_log_likelihood_at(std::size_t object, const Pose& pose) const;
  // Indices of the objects with at least one keypoint, or cloud points when the domain's
  // likelihood has `cloud.surface` (what the refine move may pick).
  const std::vector<std::size_t>& observed_objects() const noexcept { return observed_; }
  // Constants re-extracted by the last move (the moved body first).
  const std::vector<std::int32_t>& last_changed() const noexcept { return changed_; }

 private:
  void recompute_all();
  // The scene's cloud when the likelihood has `cloud.surface` and the scene came with one
  // (checked once, kept in cloud_).
  const CloudObservation* cloud_term() const;
  double prior_of(const runtime::domain::Outcome& o) const;

  const blocks::Binding& binding_;
  KitOptions options_;
  bool mln_prior_ = false;
  std::shared_ptr<const Scene> input_;  // the input estimates (pose term of the likelihood)
  blocks::Likelihood likelihood_;       // the binding's, with the scene's σ (scene_likelihood)
  blocks::Scene scene_;
  runtime::domain::Semantics<blocks::Scene> sem_;
  const CloudObservation* cloud_ = nullptr;  // the scene's, owned by scene_'s input (shared)
  std::vector<std::size_t> observed_;
  std::vector<double> object_ll_;
  double log_likelihood_ = 0.0;
  double log_prior_ = 0.0;
  std::shared_ptr<const runtime::domain::Outcome> outcome_;
  std::vector<std::int32_t> changed_;
  // Undo record of the current move.
  bool moving_ = false;
  std::size_t moved_ = 0;
  double old_object_ll_ = 0.0;
  double old_log_likelihood_ = 0.0;
  double old_log_prior_ = 0.0;
  std::shared_ptr<const runtime::domain::Outcome> old_outcome_;
};

}  // namespace ksmc::stdlib::tabletop::kit
