#include "stdlib/segments/kit/segments_model.h"

#include <cmath>
#include <stdexcept>

namespace ksmc::stdlib::segments::kit {

SegmentsModel::SegmentsModel(std::shared_ptr<const SharedInput> shared)
    : shared_(std::move(shared)),
      scene_(shared_->points, shared_->settings.likelihood),
      semantics_(shared_->settings, shared_->binding) {
  prior_ = compute_prior(outcome_);
}

PriorParts SegmentsModel::compute_prior(std::shared_ptr<const MlnOutcome>& outcome) {
  const SegmentsSettings& s = shared_->settings;
  const auto& lines = scene_.lines();
  PriorParts p;
  if (s.complexity) {
    double len = 0.0;
    for (const Line& l : lines) len += l.seg.length();
    p.complexity = -s.per_segment * static_cast<double>(lines.size()) - s.per_metre * len;
  }
  outcome = semantics_.evaluate(lines);
  if (s.mln_prior) p.mln = outcome->log_z - semantics_.baseline_log_z(lines.size());
  if (std::isfinite(outcome->log_z)) p.semantic = semantics_.semantic_terms(lines, *outcome);
  return p;
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
  std::shared_ptr<const MlnOutcome> o;
  return scene_.recompute_log_likelihood() + compute_prior(o).total();
}

}  // namespace ksmc::stdlib::segments::kit
