#include "stdlib/segments/kit/segments_model.h"

#include <cmath>
#include <stdexcept>

namespace ksmc::stdlib::segments::kit {

namespace dom = runtime::domain;

namespace {

dom::SemanticOptions semantic_options(const ModelParams& p) {
  dom::SemanticOptions o;
  o.log_z = p.mln_prior;
  o.mcsat_samples = 1000;
  o.mcsat_burn_in = 50;
  return o;
}

}  // namespace

SegmentsModel::SegmentsModel(std::shared_ptr<const SharedInput> shared)
    : shared_(std::move(shared)),
      scene_(shared_->points, shared_->params.likelihood),
      view_(scene_),
      semantics_(*shared_->binding, semantic_options(shared_->params)) {
  prior_ = compute_prior(outcome_);
}

PriorParts SegmentsModel::compute_prior(std::shared_ptr<const dom::Outcome>& outcome) {
  const auto& lines = scene_.lines();
  const std::size_t n = lines.size();
  outcome = semantics_.evaluate(view_, n);
  PriorParts p;
  for (const blocks::Prior& prior : shared_->params.priors) {
    if (const auto* c = std::get_if<blocks::Complexity>(&prior)) {
      double len = 0.0;
      for (const Line& l : lines) len += l.seg.length();
      p.complexity += -c->per_segment * static_cast<double>(n) - c->per_metre * len;
    } else if (std::holds_alternative<blocks::MlnPrior>(prior)) {
      const double base = semantics_.empty_evidence(n)->log_z;
      p.mln += outcome->log_z - (std::isfinite(base) ? base : 0.0);
    }
  }
  if (outcome->possible) p.semantic = semantics_.conditional_priors(view_, *outcome);
  return p;
}

std::vector<std::string> SegmentsModel::constant_names() const {
  const auto& core = semantics_.core();
  const std::string& type = core.program().types[static_cast<std::size_t>(core.constant_type())];
  std::vector<std::string> names;
  for (const Line& l : scene_.lines()) names.push_back(type + std::to_string(l.id));
  return names;
}

std::vector<std::size_t> SegmentsModel::change(std::span<const std::size_t> remove, std::span<const Segment> add,
                                               std::span<const std::uint64_t> ids) {
  if (!ids.empty() && ids.size() != add.size()) throw std::logic_error("segments model: one id per added line");
  saved_prior_ = prior_;
  saved_outcome_ = outcome_;
  auto added = scene_.change(remove, add, ids);
  prior_ = compute_prior(outcome_);
  return added;
}

void SegmentsModel::accept() {
  scene_.commit();
  saved_outcome_.reset();
}

void SegmentsModel::reject() {
  if (!scene_.pending()) return;
  scene_.rollback();
  prior_ = saved_prior_;
  outcome_ = saved_outcome_;
  saved_outcome_.reset();
}

runtime::mcmc::Snapshot SegmentsModel::snapshot() const {
  nlohmann::json lines = nlohmann::json::array();
  for (const Line& l : scene_.lines()) lines.push_back({l.id, l.seg.a.x, l.seg.a.y, l.seg.b.x, l.seg.b.y});
  return {{"lines", std::move(lines)}, {"next_id", scene_.next_id()}};
}

void SegmentsModel::restore(const runtime::mcmc::Snapshot& state) {
  std::vector<Line> lines;
  for (const auto& l : state.at("lines")) {
    Line x;
    x.id = l.at(0).get<std::uint64_t>();
    x.seg = canonical({l.at(1).get<double>(), l.at(2).get<double>()}, {l.at(3).get<double>(), l.at(4).get<double>()});
    lines.push_back(x);
  }
  scene_.reset(std::move(lines), state.at("next_id").get<std::uint64_t>());
  prior_ = compute_prior(outcome_);
}

double SegmentsModel::recompute_log_posterior() {
  std::shared_ptr<const dom::Outcome> o;
  return scene_.recompute_log_likelihood() + compute_prior(o).total();
}

}  // namespace ksmc::stdlib::segments::kit
