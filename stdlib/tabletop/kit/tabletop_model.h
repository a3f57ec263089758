// The table-top posterior of eq. 4.1 as an mcmc::Model:
//   log p(M|D) = log p(D|M) + log p(M)
//   log p(D|M) = Σ_o keypoint log-likelihood of o at its pose (eq. 4.4, kit_likelihood.h)
//   log p(M)   = eq. 4.3 for the scene graph of the poses: Σ w n of the world made of the
//                extracted evidence and the most probable query atoms (or, with
//                PriorQuantity::log_z, log Z over the query atoms; mln_evaluator.h)
// The state is the pose of every object (sizes and keypoints are fixed). A move changes one
// object's pose: its evidence is re-extracted incrementally (update_evidence), its
// likelihood term recomputed, and the MLN term looked up (re-run only on new evidence bits).
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "runtime/domain/config.h"
#include "runtime/mcmc/model.h"
#include "stdlib/tabletop/evidence.h"
#include "stdlib/tabletop/kit/kit_config.h"
#include "stdlib/tabletop/kit/mln_evaluator.h"
#include "stdlib/tabletop/scene.h"

namespace ksmc::stdlib::tabletop::kit {

class TabletopModel : public runtime::mcmc::Model {
 public:
  TabletopModel(std::shared_ptr<const Scene> initial, std::shared_ptr<const KitConfig> config,
                const runtime::domain::MlnBinding& binding);

  double log_likelihood() const override { return log_likelihood_; }
  double log_prior() const override {
    return config_->prior_quantity == PriorQuantity::map ? outcome_->log_map : outcome_->log_z;
  }
  void accept() override;
  void reject() override;
  runtime::mcmc::Snapshot snapshot() const override;
  void restore(const runtime::mcmc::Snapshot& state) override;

  // Tentatively moves object `object` (index into scene().objects) to `pose`.
  // `log_likelihood_at_pose` may pass the object's likelihood at `pose` when the caller
  // already computed it (the proposal does); NaN to compute it here.
  void begin_move(std::size_t object, const Pose& pose, double log_likelihood_at_pose);
  bool in_move() const noexcept { return moving_; }

  const Scene& scene() const noexcept { return scene_; }
  const Evidence& evidence() const noexcept { return moving_ ? tentative_ : evidence_; }
  const MlnOutcome& mln_outcome() const noexcept { return *outcome_; }
  double object_log_likelihood(std::size_t object) const { return object_ll_[object]; }
  double object_log_likelihood_at(std::size_t object, const Pose& pose) const;
  // Indices of the objects with at least one keypoint (what the refine move may pick).
  const std::vector<std::size_t>& observed_objects() const noexcept { return observed_; }
  const KitConfig& config() const noexcept { return *config_; }
  MlnEvaluator& mln() noexcept { return mln_; }
  const MlnEvaluator& mln() const noexcept { return mln_; }

 private:
  void recompute_all();

  std::shared_ptr<const KitConfig> config_;
  Scene scene_;
  MlnEvaluator mln_;
  Evidence evidence_;
  Evidence tentative_;
  std::vector<std::size_t> observed_;
  std::vector<double> object_ll_;
  double log_likelihood_ = 0.0;
  std::shared_ptr<const MlnOutcome> outcome_;
  // Undo record of the current move.
  bool moving_ = false;
  std::size_t moved_ = 0;
  Pose old_pose_;
  double old_object_ll_ = 0.0;
  double old_log_likelihood_ = 0.0;
  std::shared_ptr<const MlnOutcome> old_outcome_;
};

}  // namespace ksmc::stdlib::tabletop::kit
