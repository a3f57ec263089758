#include "stdlib/beads/kit/kit.h"

#include <cmath>
#include <fstream>
#include <limits>
#include <memory>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include "runtime/domain/kernels.h"
#include "runtime/domain/semantics.h"
#include "runtime/mcmc/model.h"

namespace ksmc::stdlib::beads::kit {

namespace cli = runtime::cli;
namespace dom = runtime::domain;
namespace mcmc = runtime::mcmc;
using blocks::Vec2;

namespace {

struct Shared {
  const blocks::Binding* binding = nullptr;
  std::vector<double> data;
  blocks::Nearest likelihood;
};

// The model: the beads, the likelihood of the data, the binding's priors and the
// conditional priors through the shared Markov logic evaluator.
class BeadsModel final : public mcmc::Model {
 public:
  explicit BeadsModel(std::shared_ptr<const Shared> sh)
      : sh_(std::move(sh)), view_(beads_), sem_(*sh_->binding) { score(); }
  BeadsModel(const BeadsModel&) = delete;
  BeadsModel& operator=(const BeadsModel&) = delete;

  double log_likelihood() const override { return ll_; }
  double log_prior() const override { return lp_; }
  void accept() override { saved_.reset(); }
  void reject() override {
    if (!saved_) return;
    beads_ = saved_->beads;
    ll_ = saved_->ll;
    lp_ = saved_->lp;
    outcome_ = saved_->outcome;
    saved_.reset();
  }
  mcmc::Snapshot snapshot() const override {
    nlohmann::json xs = nlohmann::json::array();
    for (const Vec2& b : beads_) xs.push_back(b.x);
    return {{"beads", xs}};
  }
  void restore(const mcmc::Snapshot& s) override {
    beads_.clear();
    for (const auto& x : s.at("beads")) beads_.push_back({x.get<double>(), 0.0});
    saved_.reset();
    score();
  }

  // Tentative change: removes bead `remove` (if >= 0), then appends `add` (if any).
  void change(std::int64_t remove, const Vec2* add) {
    saved_ = Saved{beads_, ll_, lp_, outcome_};
    if (remove >= 0) beads_.erase(beads_.begin() + remove);
    if (add) beads_.push_back(*add);
    score();
  }
  const std::vector<Vec2>& beads() const { return beads_; }
  const dom::Semantics<blocks::Scene>& semantics() const { return sem_; }
  const dom::Outcome& outcome() const { return *outcome_; }
  std::vector<std::string> names() const {
    std::vector<std::string> n;
    for (std::size_t i = 0; i < beads_.size(); ++i) n.push_back("b" + std::to_string(i));
    return n;
  }

 private:
  struct Saved {
    std::vector<Vec2> beads;
    double ll, lp;
    std::shared_ptr<const dom::Outcome> outcome;
  };
  void score() {
    const auto& lk = sh_->likelihood;
    ll_ = 0.0;
    for (const double x : sh_->data) {
      double d = std::numeric_limits<double>::infinity();
      for (const Vec2& b : beads_) d = std::min(d, std::abs(x - b.x));
      const double fit = std::isinf(d) ? 0.0 : std::exp(-0.5 * (d / lk.sigma) * (d / lk.sigma));
      ll_ += std::log((1.0 - lk.background) * fit + lk.background);
    }
    outcome_ = sem_.evaluate(view_, beads_.size());
    lp_ = outcome_->possible ? sem_.conditional_priors(view_, *outcome_) : -std::numeric_limits<double>::infinity();
    for (const blocks::Prior& p : sh_->binding->priors)
      lp_ -= std::get<blocks::Count>(p).per_bead * static_cast<double>(beads_.size());
  }

  std::shared_ptr<const Shared> sh_;
  std::vector<Vec2> beads_;
  blocks::Scene view_;
  dom::Semantics<blocks::Scene> sem_;
  std::shared_ptr<const dom::Outcome> outcome_;
  std::optional<Saved> saved_;
  double ll_ = 0.0, lp_ = 0.0;
};

double log_normal(double x, double sigma) {
  return -0.5 * (x / sigma) * (x / sigma) - std::log(sigma * std::sqrt(2.0 * std::numbers::pi));
}

// log density of a spawned bead at x: a datum uniformly, then a Gaussian around it.
double spawn_log_density(const Shared& sh, double x, double spread) {
  double sum = 0.0;
  for (const double d : sh.data) sum += std::exp(log_normal(x - d, spread));
  return std::log(sum / static_cast<double>(sh.data.size()));
}

class BeadKernel final : public mcmc::NamedKernel<BeadsModel> {
 public:
  BeadKernel(const dom::KernelDecl<blocks::Move, blocks::Source>& d, std::shared_ptr<const Shared> sh)
      : NamedKernel(d.name, d.reverse), move_(d.move), sh_(std::move(sh)) {
    for (const blocks::Source& s : d.sources) {
      if (const auto* sp = std::get_if<blocks::Spawn>(&s)) spread_ = sp->spread;
      if (const auto* nu = std::get_if<blocks::Nudge>(&s)) sigma_ = nu->sigma;
    }
  }

 protected:
  mcmc::Proposal propose_typed(BeadsModel& m, mcmc::Rng& rng) const override {
    const std::size_t n = m.beads().size();
    switch (move_) {
      case blocks::Move::spawn: {
        if (sh_->data.empty()) return mcmc::Proposal::declined();
        const Vec2 b{sh_->data[rng.uniform_int(sh_->data.size())] + rng.normal(0.0, spread_), 0.0};
        m.change(-1, &b);
        return mcmc::Proposal::made(spawn_log_density(*sh_, b.x, spread_), -std::log(static_cast<double>(n + 1)));
      }
      case blocks::Move::remove: {
        if (n == 0) return mcmc::Proposal::declined();
        const std::size_t k = rng.uniform_int(n);
        const double x = m.beads()[k].x;
        m.change(static_cast<std::int64_t>(k), nullptr);
        return mcmc::Proposal::made(-std::log(static_cast<double>(n)), spawn_log_density(*sh_, x, spread_));
      }
      case blocks::Move::nudge: {
        if (n == 0) return mcmc::Proposal::declined();
        const std::size_t k = rng.uniform_int(n);
        const Vec2 b{m.beads()[k].x + rng.normal(0.0, sigma_), 0.0};
        m.change(static_cast<std::int64_t>(k), &b);
        return mcmc::Proposal::made(0.0, 0.0);  // symmetric
      }
    }
    return mcmc::Proposal::declined();
  }

 private:
  blocks::Move move_;
  std::shared_ptr<const Shared> sh_;
  double spread_ = blocks::Spawn{}.spread, sigma_ = blocks::Nudge{}.sigma;
};

std::vector<double> read_data(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot open");
  std::vector<double> data;
  std::string line;
  for (int no = 1; std::getline(in, line); ++no) {
    std::istringstream s(line);
    double x;
    if (!(s >> x) || !std::isfinite(x)) throw std::runtime_error(path.string() + ":" + std::to_string(no) + ": expected a number");
    data.push_back(x);
  }
  if (data.empty()) throw std::runtime_error(path.string() + ": no data");
  return data;
}

cli::DomainSetup load(const blocks::Binding& b, const cli::DomainInput& in) {
  auto sh = std::make_shared<Shared>();
  sh->binding = &b;
  sh->data = read_data(in.inputs.at(0));
  sh->likelihood = std::get<blocks::Nearest>(b.likelihood);
  dom::KernelTable t = dom::make_kernels(b.kernels, b.schedule, [&](const auto& d) {
    return std::make_shared<const BeadKernel>(d, sh);
  });
  cli::DomainSetup setup;
  setup.kernels = std::move(t.kernels);
  setup.schedule = std::move(t.schedule);
  std::shared_ptr<const Shared> csh = sh;
  { BeadsModel check(csh); }  // ConfigError here, not in a chain
  setup.model_factory = [csh](unsigned) { return std::make_unique<BeadsModel>(csh); };
  setup.write_results = [](const mcmc::RunResult&, mcmc::Model& best, cli::OutputDir& out) {
    const auto& m = static_cast<const BeadsModel&>(best);
    nlohmann::ordered_json j;
    j["beads"] = m.snapshot().at("beads");
    j["queries"] = m.semantics().queries_json(m.outcome(), m.names());
    j["log_posterior"] = m.log_posterior();
    out.write("beads.json", j.dump(2) + "\n");
  };
  setup.evidence_db = [](mcmc::Model& best) {
    const auto& m = static_cast<const BeadsModel&>(best);
    return m.semantics().evidence_db(m.outcome(), m.names());
  };
  return setup;
}

}  // namespace

cli::DomainSpec domain_spec(const blocks::Binding& binding) {
  cli::DomainSpec spec;
  spec.name = binding.domain;
  spec.version = "0.1";
  spec.description = "beads on a line fitted to 1D data (test kit of docs/extending.md)";
  spec.inputs_help = "DATA.txt";
  spec.default_iterations = 3000;
  spec.load = [&binding](const cli::DomainInput& in) { return load(binding, in); };
  return spec;
}

}  // namespace ksmc::stdlib::beads::kit
