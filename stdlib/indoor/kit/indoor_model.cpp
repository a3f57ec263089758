#include "stdlib/indoor/kit/indoor_model.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "stdlib/indoor/detect/door.h"
#include "stdlib/indoor/detect/fsu.h"
#include "stdlib/indoor/detect/split.h"

namespace ksmc::stdlib::indoor::kit {

namespace mcmc = runtime::mcmc;

std::optional<KernelKind> kernel_kind(const std::string& n) {
  if (n == "ADD") return KernelKind::Add;
  if (n == "REMOVE") return KernelKind::Remove;
  if (n == "SPLIT") return KernelKind::Split;
  if (n == "MERGE") return KernelKind::Merge;
  if (n == "SHRINK") return KernelKind::Shrink;
  if (n == "DILATE") return KernelKind::Dilate;
  if (n == "ALLOCATE") return KernelKind::Allocate;
  if (n == "DELETE") return KernelKind::Delete;
  if (n == "INTERCHANGE") return KernelKind::Interchange;
  return std::nullopt;
}

namespace {
detect::DoorParams door_params(const SharedInput& in) {
  detect::DoorParams dp;
  dp.min_door = in.settings.sources.door_min_width_m / in.resolution;
  dp.max_door = in.settings.sources.door_max_width_m / in.resolution;
  return dp;
}
}  // namespace

IndoorModel::IndoorModel(std::shared_ptr<const SharedInput> in)
    : in_(std::move(in)), sw_(in_->grid, in_->score), door_cache_(door_params(*in_)) {
  units_ = in_->fixed_units;
  KernelSources src;
  src.units = [this](const World&) { return std::span<const CandidateUnit>(units_); };
  src.doors = [this](const World&) { return std::span<const CandidateDoor>(doors_); };
  if (in_->settings.sources.split) {
    src.split_lines = [this](const World&, const Unit& u) {
      const auto key = std::make_tuple(u.rect.cx, u.rect.cy, u.rect.w, u.rect.h, u.rect.theta);
      auto it = splits_.find(key);
      if (it == splits_.end()) {
        if (splits_.size() > 4096) splits_.clear();
        detect::SplitParams sp;
        sp.hough.threshold = in_->settings.sources.split_min_votes;
        sp.axis_tolerance_deg = in_->settings.sources.split_angle_tol_rad * 180.0 / 3.14159265358979323846;
        std::vector<CandidateLine> lines;
        if (u.rect.w >= 2.0 && u.rect.h >= 2.0) lines = to_line_candidates(
              detect::detect_split_lines(in_->grid, u.rect, sp, detect::GridCheck::Trusted));  // checked by sw_
        it = splits_.emplace(key, std::move(lines)).first;
      }
      return it->second;
    };
  } else {
    src.split_lines = [](const World&, const Unit&) { return std::vector<CandidateLine>{}; };
  }
  ks_ = std::make_unique<KernelSet>(*in_->evidence, std::move(src), in_->kernel);
  if (in_->settings.semantic.enabled) sem_.emplace(in_->settings.semantic, in_->binding, in_->resolution, in_->seed);
}

void IndoorModel::refresh_sources() {
  const SourceSettings& s = in_->settings.sources;
  const World& w = sw_.world();
  if (s.fsu && iteration_ >= static_cast<std::uint64_t>(s.fsu_after)) {
    cv::Mat1b explained(in_->grid.rows, in_->grid.cols, std::uint8_t{0});
    const CoverageGrid& cg = sw_.coverage();
    for (int r = 0; r < cg.rows(); ++r)
      for (int c = 0; c < cg.cols(); ++c)
        if (cg.predicted(r, c) != Predicted::Unknown) explained(r, c) = 255;
    detect::FsuParams fp;
    fp.min_area = s.fsu_min_area_cells;
    fp.frame_deg = in_->frame_deg;
    units_ = in_->fixed_units;
    for (const auto& c : detect::detect_fsu_units(in_->grid, explained, fp))
      if (c.rect.w >= in_->kernel.min_size && c.rect.h >= in_->kernel.min_size) units_.push_back({c.rect, c.weight});
  }
  if (s.doors) {
    std::vector<OrientedRect> rects;
    for (const Unit& u : w.units()) rects.push_back(u.rect);
    doors_ = door_cache_.candidates(in_->grid, rects);  // = detect_doors on all units, per pair cached
  }
}

double IndoorModel::sale_log_prior(const World& w) const {
  if (sale_pairs_.empty()) return 0.0;
  const double sigma = in_->settings.semantic.sale_sigma_m;
  double lp = 0.0;
  for (auto [a, b] : sale_pairs_) {
    const Unit* ua = w.find_unit(a);
    const Unit* ub = w.find_unit(b);
    if (!ua || !ub) continue;
    const auto d = wall_length_diff(ua->rect, ub->rect, in_->settings.semantic.adjacent_dilate_cells, in_->resolution);
    if (d) lp -= 0.5 * (*d / sigma) * (*d / sigma);
  }
  return lp;
}

std::vector<UnitChange> IndoorModel::relabel(const SemanticResult& r) const {
  std::vector<UnitChange> out;
  const auto& sem = in_->settings.semantic;
  for (const UnitSemantics& us : r.units) {
    const std::string& type = sem.type_predicates[static_cast<std::size_t>(us.type)];
    const bool lenient = std::find(sem.lenient_types.begin(), sem.lenient_types.end(), type) != sem.lenient_types.end();
    const Unit* u = sw_.world().find_unit(us.id);
    if (!u) continue;
    const std::uint8_t want = lenient ? 1 : 0;
    if (u->lut_class == want) continue;
    Unit after = *u;
    after.lut_class = want;
    out.push_back({u->id, *u, after});
  }
  return out;
}

bool IndoorModel::propose(KernelKind k, mcmc::Rng& rng, double& log_q_fwd, double& log_q_bwd) {
  if (pending_) throw std::logic_error("IndoorModel: propose() before the previous proposal ended");
  ++iteration_;
  if (!krng_seeded_) {
    krng_.seed(rng());
    krng_seeded_ = true;
  }
  const RunTuning& t = in_->tuning;
  if (t.source_refresh > 0 && (iteration_ == 1 || iteration_ % t.source_refresh == 0)) refresh_sources();
  Pending pend;
  pend.old_offset = offset_;
  pend.old_pairs = sale_pairs_;
  pend.old_sale = sale_log_prior_;
  if (sem_ && t.semantic_every > 0 && iteration_ >= t.semantic_after &&
      (iteration_ - t.semantic_after) % t.semantic_every == 0)
    semantic_due_ = true;
  double target_shift = 0.0;
  if (semantic_due_ && sw_.world().units().size() > t.semantic_max_units) semantic_due_ = false;
  if (semantic_due_) {
    // The refresh changes the target (types -> tables, SaLe pairs -> prior) for the current
    // world W; its own change of log p(W) is reported in log_q_fwd so that the engine's
    // acceptance ratio compares M' with M under the refreshed target.
    const double before = log_posterior();
    if (!due_result_) due_result_ = sem_->evaluate(sw_.world());
    const SemanticResult& r = *due_result_;
    auto changes = relabel(r);
    if (!changes.empty()) {
      Move m;
      m.kind = k;
      m.units = std::move(changes);
      sw_.apply(m);
      pend.relabel = std::move(m);
    }
    sale_pairs_ = r.same_length;
    sale_log_prior_ = sale_log_prior(sw_.world());
    target_shift = log_posterior() - before;
    offset_ += target_shift;
    pend.refresh = true;
  }
  auto p = ks_->propose(k, sw_.world(), krng_);
  if (!p) {
    // Declined: undo the refresh too (it stays due and rides on the next proposal).
    if (pend.relabel) sw_.revert(*pend.relabel);
    sale_pairs_ = std::move(pend.old_pairs);
    sale_log_prior_ = pend.old_sale;
    offset_ = pend.old_offset;
    return false;
  }
  // Previewed when possible: a rejection then costs no revert (see ScoredWorld::preview).
  pend.previewed = sw_.preview(p->move);
  if (!pend.previewed) sw_.apply(p->move);
  pend.move = std::move(p->move);
  if (!sale_pairs_.empty()) sale_log_prior_ = sale_log_prior(sw_.world());
  log_q_fwd = p->log_q_fwd;
  log_q_bwd = p->log_q_bwd;
  pending_ = std::move(pend);
  return true;
}

void IndoorModel::accept() {
  if (pending_ && pending_->refresh) semantic_due_ = false;
  due_result_.reset();  // the world changed (or the refresh is done)
  if (pending_ && pending_->previewed) sw_.commit();
  pending_.reset();
}

void IndoorModel::reject() {
  if (!pending_) return;
  if (pending_->previewed) sw_.discard();
  else if (pending_->move) sw_.revert(*pending_->move);
  if (pending_->relabel) sw_.revert(*pending_->relabel);
  sale_pairs_ = std::move(pending_->old_pairs);
  sale_log_prior_ = pending_->old_sale;
  offset_ = pending_->old_offset;
  pending_.reset();
}

std::optional<SemanticResult> IndoorModel::final_semantics() {
  if (!sem_) return std::nullopt;
  return sem_->evaluate(sw_.world());
}

mcmc::Snapshot IndoorModel::snapshot() const {
  mcmc::Snapshot s = mcmc::Snapshot::object();
  mcmc::Snapshot units = mcmc::Snapshot::array();
  for (const Unit& u : sw_.world().units())
    units.push_back({{"id", u.id}, {"cx", u.rect.cx}, {"cy", u.rect.cy}, {"w", u.rect.w}, {"h", u.rect.h},
                     {"theta", u.rect.theta}, {"lut", u.lut_class}});
  mcmc::Snapshot doors = mcmc::Snapshot::array();
  for (const Door& d : sw_.world().doors())
    doors.push_back({{"id", d.id}, {"a", d.unit_a}, {"b", d.unit_b}, {"ax", d.a.x}, {"ay", d.a.y}, {"bx", d.b.x}, {"by", d.b.y}});
  mcmc::Snapshot pairs = mcmc::Snapshot::array();
  for (auto [a, b] : sale_pairs_) pairs.push_back({a, b});
  s["units"] = std::move(units);
  s["doors"] = std::move(doors);
  s["same_length"] = std::move(pairs);
  s["proposals"] = iteration_;
  s["target_offset"] = offset_;
  return s;
}

void IndoorModel::restore(const mcmc::Snapshot& s) {
  try {
    Move m;
    for (const auto& u : s.at("units")) {
      const OrientedRect r{u.at("cx").get<double>(), u.at("cy").get<double>(), u.at("w").get<double>(),
                           u.at("h").get<double>(), u.at("theta").get<double>()};
      const auto id = u.at("id").get<UnitId>();
      m.units.push_back({id, std::nullopt, in_->evidence->make_unit(id, r, u.at("lut").get<std::uint8_t>())});
    }
    for (const auto& d : s.at("doors")) {
      const auto id = d.at("id").get<DoorId>();
      m.doors.push_back({id, std::nullopt,
                         in_->evidence->make_door(id, d.at("a").get<UnitId>(), d.at("b").get<UnitId>(),
                                                  {d.at("ax").get<double>(), d.at("ay").get<double>()},
                                                  {d.at("bx").get<double>(), d.at("by").get<double>()})});
    }
    World w;
    w.apply(m);
    sw_.reset(w);
    sale_pairs_.clear();
    for (const auto& p : s.at("same_length")) sale_pairs_.emplace_back(p.at(0).get<UnitId>(), p.at(1).get<UnitId>());
    iteration_ = s.value("proposals", std::uint64_t{0});
    offset_ = s.value("target_offset", 0.0);
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(std::string("indoor state snapshot: ") + e.what());
  }
  sale_log_prior_ = sale_log_prior(sw_.world());
  due_result_.reset();
  pending_.reset();
}

}  // namespace ksmc::stdlib::indoor::kit
