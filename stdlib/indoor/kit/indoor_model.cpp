#include "stdlib/indoor/kit/indoor_model.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <tuple>

#include "stdlib/indoor/blocks/walls.h"
#include "stdlib/indoor/detect/door.h"
#include "stdlib/indoor/detect/fsu.h"
#include "stdlib/indoor/detect/split.h"
#include "stdlib/indoor/kit/door_cache.h"

namespace ksmc::stdlib::indoor::kit {

namespace mcmc = runtime::mcmc;

// Delayed acceptance: the first stage passes every proposal whose cheap log ratio is above
// -kScreenMargin (nats), so only clearly worse proposals are screened out.
constexpr double kScreenMargin = 200.0;

// The run-time state of one source pool: its candidates (refreshed every source_refresh
// proposals), caches and the KernelSet its kernels propose with.
struct IndoorModel::Pool {
  const SourcePool* cfg = nullptr;
  std::vector<CandidateUnit> units;
  std::vector<CandidateDoor> doors;
  std::vector<DoorCandidateCache> door_caches;  // one per detect.doors source
  std::map<std::tuple<double, double, double, double, double>, std::vector<CandidateLine>> splits;
  std::unique_ptr<KernelSet> ks;
};

namespace {

// A door detector's widths (metres) in cells; for detect.doors and move.seam_doors alike.
template <class Widths>
detect::DoorParams door_params(const Widths& d, double resolution) {
  detect::DoorParams dp;
  dp.min_door = d.min_width / resolution;
  dp.max_door = d.max_width / resolution;
  return dp;
}

std::vector<CandidateLine> split_lines_of(const SharedInput& in, const SourcePool& cfg, const Unit& u) {
  std::vector<CandidateLine> lines;
  if (u.rect.w < 2.0 || u.rect.h < 2.0) return lines;
  for (const auto& s : cfg.split) {
    detect::SplitParams sp;
    sp.hough.threshold = s.min_votes;
    sp.axis_tolerance_deg = s.angle_tol * 180.0 / 3.14159265358979323846;
    const auto found = to_line_candidates(detect::detect_split_lines(in.grid, u.rect, sp, detect::GridCheck::Trusted));  // checked by sw_
    lines.insert(lines.end(), found.begin(), found.end());
  }
  return lines;
}

}  // namespace

IndoorModel::IndoorModel(std::shared_ptr<const SharedInput> in) : in_(std::move(in)), sw_(in_->grid, in_->score) {
  for (std::size_t i = 0; i < in_->plan.pools.size(); ++i) {
    auto pool = std::make_unique<Pool>();
    Pool* p = pool.get();
    p->cfg = &in_->plan.pools[i];
    p->units = in_->fixed_units[i];
    for (const auto& d : p->cfg->doors) p->door_caches.emplace_back(door_params(d, in_->resolution));
    KernelSources src;
    src.units = [p](const World&) { return std::span<const CandidateUnit>(p->units); };
    src.doors = [p](const World&) { return std::span<const CandidateDoor>(p->doors); };
    src.split_lines = [p, this](const World&, const Unit& u) {
      const auto key = std::make_tuple(u.rect.cx, u.rect.cy, u.rect.w, u.rect.h, u.rect.theta);
      auto it = p->splits.find(key);
      if (it == p->splits.end()) {
        if (p->splits.size() > 4096) p->splits.clear();
        it = p->splits.emplace(key, split_lines_of(*in_, *p->cfg, u)).first;
      }
      return it->second;
    };
    if (!p->cfg->seam_doors.empty())
      src.seam_doors = [p, this](const OrientedRect& a, const OrientedRect& b) {
        std::vector<CandidateDoor> out;
        for (const auto& sd : p->cfg->seam_doors) {
          if (!blocks::cut_across_corridor(a, b, sd.max_cut / in_->resolution, sd.min_ratio)) continue;
          const auto found = to_door_candidates(
              detect::detect_doors(in_->grid, {a, b}, door_params(sd, in_->resolution), detect::GridCheck::Trusted));
          out.insert(out.end(), found.begin(), found.end());
        }
        return out;
      };
    KernelParams kp = in_->kernel;
    if (!p->cfg->wall_shift.empty()) kp.shift_sigma = p->cfg->wall_shift.front().sigma;
    kp.uniform_share = 0.0;
    for (const auto& u : p->cfg->uniform_rect) kp.uniform_share += u.share;
    kp.uniform_share = std::min(kp.uniform_share, 1.0);
    p->ks = std::make_unique<KernelSet>(*in_->evidence, std::move(src), kp);
    pools_.push_back(std::move(pool));
  }
  if (in_->plan.semantic) {
    sem_.emplace(*in_->binding, in_->plan, in_->resolution, &in_->grid, in_->seed, &in_->free_distance);
    adopt(sem_->evaluate(sw_.world()), KernelKind::Add);
  }
}

IndoorModel::~IndoorModel() = default;

void IndoorModel::refresh_sources() {
  const World& w = sw_.world();
  std::optional<cv::Mat1b> explained;  // cells some unit explains, for FSU
  for (std::size_t i = 0; i < pools_.size(); ++i) {
    Pool* p = pools_[i].get();
    bool fsu_due = false;
    for (const auto& f : p->cfg->fsu) fsu_due = fsu_due || iteration_ >= static_cast<std::uint64_t>(f.after);
    if (fsu_due) {
      if (!explained) {
        explained.emplace(in_->grid.rows, in_->grid.cols, std::uint8_t{0});
        const CoverageGrid& cg = sw_.coverage();
        for (int r = 0; r < cg.rows(); ++r)
          for (int c = 0; c < cg.cols(); ++c)
            if (cg.predicted(r, c) != Predicted::Unknown) (*explained)(r, c) = 255;
      }
      p->units = in_->fixed_units[i];
      for (const auto& f : p->cfg->fsu) {
        if (iteration_ < static_cast<std::uint64_t>(f.after)) continue;
        detect::FsuParams fp;
        fp.min_area = f.min_area_cells;
        fp.frame_deg = in_->frame_deg;
        for (const auto& c : detect::detect_fsu_units(in_->grid, *explained, fp))
          if (c.rect.w >= in_->kernel.min_size && c.rect.h >= in_->kernel.min_size) p->units.push_back({c.rect, c.weight});
      }
    }
    if (!p->door_caches.empty()) {
      std::vector<OrientedRect> rects;
      for (const Unit& u : w.units()) rects.push_back(u.rect);
      p->doors.clear();
      for (auto& cache : p->door_caches) {
        auto found = cache.candidates(in_->grid, rects);  // = detect_doors on all units, per pair cached
        p->doors.insert(p->doors.end(), found.begin(), found.end());
      }
    }
  }
}

std::vector<UnitChange> IndoorModel::relabel(const SemanticResult& r) const {
  std::vector<UnitChange> out;
  if (in_->plan.type_free_likelihood) return out;  // the tables are equal: nothing to switch
  for (std::size_t i = 0; i < r.ids.size(); ++i) {
    const int type = r.type[i];
    const bool lenient = type >= 0 && in_->plan.lenient[static_cast<std::size_t>(type)];
    const Unit* u = sw_.world().find_unit(r.ids[i]);
    if (!u) continue;
    const std::uint8_t want = lenient ? 1 : 0;
    if (u->lut_class == want) continue;
    Unit after = *u;
    after.lut_class = want;
    out.push_back({u->id, *u, after});
  }
  return out;
}

std::optional<Move> IndoorModel::adopt(SemanticResult r, KernelKind kind) {
  std::optional<Move> applied;
  if (r.possible()) {  // an impossible world is rejected: its tables do not matter
    auto changes = relabel(r);
    if (!changes.empty()) {
      Move m;
      m.kind = kind;
      m.units = std::move(changes);
      sw_.apply(m);
      applied = std::move(m);
    }
  }
  knowledge_ = r.log_knowledge();
  current_ = std::move(r);
  return applied;
}

bool IndoorModel::propose(std::size_t kernel, mcmc::Rng& rng, double& log_q_fwd, double& log_q_bwd,
                          double& log_screened) {
  if (pending_) throw std::logic_error("IndoorModel: propose() before the previous proposal ended");
  const KernelPlan& kp = in_->plan.kernels[kernel];
  const KernelKind k = kp.kind;
  ++iteration_;
  if (!krng_seeded_) {
    krng_.seed(rng());
    krng_seeded_ = true;
  }
  const RunTuning& t = in_->tuning;
  if (t.source_refresh > 0 && (iteration_ == 1 || iteration_ % t.source_refresh == 0)) refresh_sources();
  auto p = pools_[kp.pool]->ks->propose(k, sw_.world(), krng_);
  if (!p) return false;  // declined: untouched
  Pending pend;
  const double cheap_before = sw_.log_likelihood() + sw_.log_prior();
  // Previewed when possible: a rejection then costs no revert (see ScoredWorld::preview).
  pend.previewed = sw_.preview(p->move);
  if (!pend.previewed) sw_.apply(p->move);
  log_screened = 0.0;
  if (sem_ && in_->plan.type_free_likelihood) {
    // Delayed acceptance, first stage, on the likelihood and weak prior alone (they do not
    // depend on the types here): r1 is their log MH ratio, which changes sign for the reverse
    // move. The first stage accepts with α1(x→y) = min(1, r1 e^m): a proposal within m nats
    // of the current cheap value always passes, so good moves keep the plain MH test; a
    // clearly worse one is declined before the knowledge part is computed. The engine's
    // second stage divides by α1(x→y) / α1(y→x) (Proposal::log_screened).
    const double r1 = (sw_.log_likelihood() + sw_.log_prior() - cheap_before) + (p->log_q_bwd - p->log_q_fwd);
    const double fwd = std::min(0.0, r1 + kScreenMargin), bwd = std::min(0.0, kScreenMargin - r1);
    const double u = (static_cast<double>(krng_() >> 11) + 0.5) * 0x1.0p-53;
    if (!(fwd >= 0.0) && !(std::log(u) < fwd)) {
      if (pend.previewed) sw_.discard();
      else sw_.revert(p->move);
      ++screened_out_;
      return false;
    }
    log_screened = fwd - bwd;
  }
  stage(std::move(pend), std::move(p->move), k);
  log_q_fwd = p->log_q_fwd;
  log_q_bwd = p->log_q_bwd;
  return true;
}

void IndoorModel::stage(Pending pend, Move move, KernelKind k) {
  if (sem_) {
    // The knowledge part of log p(W') on the proposed world: the units the move touched
    // (directly or through a door) are the constants whose evidence may have changed.
    std::vector<UnitId> changed;
    for (const UnitChange& c : move.units) changed.push_back(c.id);
    for (const DoorChange& c : move.doors)
      for (const auto& d : {c.before, c.after})
        if (d) changed.insert(changed.end(), {d->unit_a, d->unit_b});
    pend.old_semantics = std::move(current_);
    pend.old_knowledge = knowledge_;
    current_.reset();
    SemanticResult r = pend.old_semantics ? sem_->evaluate(sw_.world(), *pend.old_semantics, changed)
                                          : sem_->evaluate(sw_.world());
    auto relabels = r.possible() ? relabel(r) : std::vector<UnitChange>{};  // impossible: rejected anyway
    if (!relabels.empty() && pend.previewed) {
      // A type changed: the tables switch inside this proposal. Previewed as one move with the
      // kernel's when it fits, so that a rejection still costs no revert.
      Move merged = move;
      for (UnitChange& c : relabels) {
        auto it = std::find_if(merged.units.begin(), merged.units.end(), [&](const UnitChange& m) { return m.id == c.id; });
        if (it == merged.units.end()) merged.units.push_back(std::move(c));
        else it->after->lut_class = c.after->lut_class;
      }
      relabels.clear();
      sw_.discard();
      pend.previewed = sw_.preview(merged);
      if (pend.previewed) move = std::move(merged);
      else {
        sw_.apply(move);
        relabels = relabel(r);
      }
    }
    if (!relabels.empty()) {
      Move m;
      m.kind = k;
      m.units = std::move(relabels);
      sw_.apply(m);
      pend.relabel = std::move(m);
    }
    knowledge_ = r.log_knowledge();
    current_ = std::move(r);
  }
  pend.move = std::move(move);
  pending_ = std::move(pend);
}

bool IndoorModel::improve(const Move& move) {
  if (pending_) throw std::logic_error("IndoorModel: improve() during a proposal");
  const double before = log_posterior();
  Pending pend;
  pend.previewed = sw_.preview(move);
  if (!pend.previewed) sw_.apply(move);
  stage(std::move(pend), move, move.kind);
  if (log_posterior() > before) {
    accept();
    return true;
  }
  reject();
  return false;
}

void IndoorModel::accept() {
  if (pending_ && pending_->previewed) sw_.commit();
  pending_.reset();
}

void IndoorModel::reject() {
  if (!pending_) return;
  if (pending_->relabel) sw_.revert(*pending_->relabel);
  if (pending_->previewed) sw_.discard();
  else if (pending_->move) sw_.revert(*pending_->move);
  if (sem_) {
    current_ = std::move(pending_->old_semantics);
    knowledge_ = pending_->old_knowledge;
  }
  pending_.reset();
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
  s["units"] = std::move(units);
  s["doors"] = std::move(doors);
  s["proposals"] = iteration_;
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
    iteration_ = s.value("proposals", std::uint64_t{0});
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(std::string("indoor state snapshot: ") + e.what());
  }
  pending_.reset();
  current_.reset();
  knowledge_ = 0.0;
  if (sem_) adopt(sem_->evaluate(sw_.world()), KernelKind::Add);
}

}  // namespace ksmc::stdlib::indoor::kit
