// A toy model with a small enumerable state space for sampler tests: an integer x in
// [0, n) with a non-uniform target split into a "likelihood" and a "prior", and kernels
// with asymmetric proposals (UP/DOWN jumps with different step weights, an independent
// RESAMPLE that is its own reverse).
#pragma once

#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "runtime/mcmc/model.h"

namespace ksmc::tests::mcmc {

namespace rm = ksmc::runtime::mcmc;

// Unnormalised log target: two bumps of different height.
inline std::vector<double> toy_log_target(int n = 20) {
  std::vector<double> lp(static_cast<std::size_t>(n));
  for (int x = 0; x < n; ++x) {
    const double a = std::exp(-0.5 * (x - 4.0) * (x - 4.0) / 4.0);
    const double b = 0.6 * std::exp(-0.5 * (x - 14.0) * (x - 14.0) / 6.0);
    lp[static_cast<std::size_t>(x)] = std::log(a + b + 0.01);
  }
  return lp;
}

inline std::vector<double> normalised(const std::vector<double>& log_p) {
  double z = 0.0;
  for (double v : log_p) z += std::exp(v);
  std::vector<double> p;
  for (double v : log_p) p.push_back(std::exp(v) / z);
  return p;
}

class ToyModel : public rm::Model {
 public:
  ToyModel(std::shared_ptr<const std::vector<double>> log_target, int x0)
      : target_(std::move(log_target)), x_(x0) {}

  int size() const { return static_cast<int>(target_->size()); }
  int x() const { return x_; }

  // Prior -0.05 x, likelihood the rest: the engine must add both.
  double log_prior() const override { return -0.05 * x_; }
  double log_likelihood() const override {
    return (*target_)[static_cast<std::size_t>(x_)] + 0.05 * x_;
  }

  // Called by kernels: tentative move.
  void move_to(int x) {
    saved_ = x_;
    x_ = x;
    ++proposals_;
  }
  void accept() override {}
  void reject() override { x_ = saved_; }

  rm::Snapshot snapshot() const override { return rm::Snapshot{{"x", x_}}; }
  void restore(const rm::Snapshot& s) override { x_ = s.at("x").get<int>(); }

  long proposals() const { return proposals_; }

 private:
  std::shared_ptr<const std::vector<double>> target_;
  int x_;
  int saved_ = 0;
  long proposals_ = 0;
};

// Jump by k in {1, 2, 3} with weights w[k-1], up (+k) or down (-k); declines when
// the target would leave [0, n). UP and DOWN use different weights, so Q is asymmetric.
class JumpKernel : public rm::NamedKernel<ToyModel> {
 public:
  JumpKernel(bool up, std::vector<double> own, std::vector<double> reverse,
             double bwd_error = 0.0)
      : NamedKernel(up ? "UP" : "DOWN", up ? "DOWN" : "UP"),
        up_(up), own_(std::move(own)), reverse_(std::move(reverse)), bwd_error_(bwd_error) {}

  static std::vector<double> up_weights() { return {0.5, 0.3, 0.2}; }
  static std::vector<double> down_weights() { return {0.6, 0.3, 0.1}; }

 protected:
  rm::Proposal propose_typed(ToyModel& m, rm::Rng& rng) const override {
    const double u = rng.uniform();
    std::size_t k = 0;
    double acc = own_[0];
    while (u >= acc && k + 1 < own_.size()) acc += own_[++k];
    const int step = static_cast<int>(k) + 1;
    const int target = up_ ? m.x() + step : m.x() - step;
    if (target < 0 || target >= m.size()) return rm::Proposal::declined();
    m.move_to(target);
    // bwd_error_ != 0 makes a deliberately wrong kernel (negative controls).
    return rm::Proposal::made(std::log(own_[k]), std::log(reverse_[k]) + bwd_error_);
  }

 private:
  bool up_;
  std::vector<double> own_;
  std::vector<double> reverse_;
  double bwd_error_;
};

// Independent proposal x' ~ q(x') proportional to (1 + x'): its own reverse.
class ResampleKernel : public rm::NamedKernel<ToyModel> {
 public:
  ResampleKernel() : NamedKernel("RESAMPLE", "RESAMPLE") {}

 protected:
  rm::Proposal propose_typed(ToyModel& m, rm::Rng& rng) const override {
    const int n = m.size();
    const double z = n * (n + 1) / 2.0;
    double u = rng.uniform() * z;
    int target = 0;
    while (target + 1 < n && u >= target + 1.0) {
      u -= target + 1.0;
      ++target;
    }
    const int from = m.x();
    m.move_to(target);
    return rm::Proposal::made(std::log((target + 1) / z), std::log((from + 1) / z));
  }
};

// Always declines (for decline counting).
class DeclineKernel : public rm::NamedKernel<ToyModel> {
 public:
  DeclineKernel() : NamedKernel("NOPE", "NOPE") {}

 protected:
  rm::Proposal propose_typed(ToyModel&, rm::Rng&) const override { return rm::Proposal::declined(); }
};

inline rm::KernelList toy_kernels(double up_bwd_error = 0.0) {
  return {std::make_shared<JumpKernel>(true, JumpKernel::up_weights(), JumpKernel::down_weights(),
                                       up_bwd_error),
          std::make_shared<JumpKernel>(false, JumpKernel::down_weights(), JumpKernel::up_weights()),
          std::make_shared<ResampleKernel>()};
}

inline rm::ModelFactory toy_factory(int x0 = 0, int n = 20) {
  auto target = std::make_shared<const std::vector<double>>(toy_log_target(n));
  return [target, x0](unsigned) { return std::make_unique<ToyModel>(target, x0); };
}

}  // namespace ksmc::tests::mcmc
