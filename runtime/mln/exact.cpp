#include "runtime/mln/exact.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <string>

#include "runtime/io/cancel.h"
#include "runtime/mln/error.h"

namespace ksmc::runtime::mln {
namespace {

constexpr double kNegInf = -std::numeric_limits<double>::infinity();

std::string describe_labels(const GroundNetwork& net, std::span<const AtomId> atoms) {
  std::set<std::string> names;
  for (AtomId a : atoms) names.insert(net.label_name(a));
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// A component of one free atom outside any block: closed form from its unit clauses.
double single_atom_solve(const GroundNetwork& net, const Component& comp, std::vector<double>& marg,
                   std::vector<std::uint8_t>* mode, double* mode_lw) {
  const AtomId a = comp.atoms[0];
  double s0 = 0.0, s1 = 0.0;
  bool allow0 = true, allow1 = true;
  for (std::int32_t c : comp.clauses) {
    const bool neg = lit_negated(net.clause(c)[0]);
    if (net.is_hard(c)) (neg ? allow1 : allow0) = false;
    else (neg ? s0 : s1) += net.weight(c);
  }
  if (!allow0 && !allow1) {
    std::set<std::string> names;
    for (std::int32_t c : comp.clauses) names.insert(net.origin_name(c));
    std::string rules;
    for (const auto& n : names) rules += (rules.empty() ? "" : ", ") + n;
    throw MlnError("exact inference: no state satisfies the hard constraints (" + rules + ") over " +
                   net.label_name(a));
  }
  const bool best1 = allow1 && (!allow0 || s1 > s0);
  if (mode) (*mode)[a] = best1 ? 1 : 0;
  if (mode_lw) *mode_lw = best1 ? s1 : s0;
  if (!allow0) { marg[a] = 1.0; return s1; }
  if (!allow1) { marg[a] = 0.0; return s0; }
  const double mx = std::max(s0, s1);
  const double e0 = std::exp(s0 - mx), e1 = std::exp(s1 - mx);
  marg[a] = e1 / (e0 + e1);
  return mx + std::log(e0 + e1);
}

double single_atom(const GroundNetwork& net, const Component& comp, std::vector<double>& marg,
                   std::vector<std::uint8_t>* mode, double* mode_lw, std::vector<double>* clause_prob) {
  const double log_z = single_atom_solve(net, comp, marg, mode, mode_lw);
  if (clause_prob) {  // unit clauses
    const double p = marg[comp.atoms[0]];
    for (std::int32_t c : comp.clauses) (*clause_prob)[c] = lit_negated(net.clause(c)[0]) ? 1.0 - p : p;
  }
  return log_z;
}

// Enumerates components of one network in place (global atom/clause ids), reusing
// its buffers across components: no per-component network copies.
class Enumerator {
 public:
  explicit Enumerator(const GroundNetwork& net) : net_(net), occ_(build_occurrences(net)) {
    const auto n = static_cast<std::size_t>(net.num_atoms());
    const auto m = static_cast<std::size_t>(net.num_clauses());
    val_.assign(n, 0);
    acc_.assign(n, 0.0);
    since_.assign(n, 0.0);
    cnt_.assign(m, 0);
    w_.resize(m);
    hard_.resize(m);
    for (std::size_t c = 0; c < m; ++c) {
      hard_[c] = net.is_hard(static_cast<std::int32_t>(c)) ? 1 : 0;
      w_[c] = hard_[c] ? 0.0 : net.weight(static_cast<std::int32_t>(c));
    }
  }

  // Marginals go to marg[atom] (global ids); returns the component's log Z (no constant).
  // If mode != nullptr, writes a most probable state of the component into (*mode)[atom].
  // If clause_prob != nullptr, writes P(clause satisfied) of the component's clauses.
  double run(const Component& comp, std::vector<double>& marg, std::vector<std::uint8_t>* mode, double* mode_lw,
             std::vector<double>* clause_prob = nullptr) {
    want_clauses_ = clause_prob != nullptr;
    if (want_clauses_ && cacc_.empty()) {
      cacc_.assign(cnt_.size(), 0.0);
      csince_.assign(cnt_.size(), 0.0);
    }
    double ref = 0.0;
    for (std::int32_t c : comp.clauses)
      if (!hard_[c]) ref += std::max(w_[c], 0.0);
    radix_.clear();
    first_.clear();
    datoms_.clear();
    for (AtomId a : comp.atoms) {
      if (net_.block_of(a) >= 0) continue;
      radix_.push_back(2);
      first_.push_back(static_cast<std::int32_t>(datoms_.size()));
      datoms_.push_back(a);
    }
    const auto nplain = static_cast<std::int32_t>(radix_.size());
    for (std::int32_t b : comp.blocks) {
      const auto atoms = net_.block(b);
      radix_.push_back(static_cast<std::int32_t>(atoms.size()));
      first_.push_back(static_cast<std::int32_t>(datoms_.size()));
      datoms_.insert(datoms_.end(), atoms.begin(), atoms.end());
    }
    nplain_ = nplain;
    enumerate(comp, ref, mode != nullptr);
    if (max_s_ == kNegInf) {
      throw MlnError("exact inference: no state satisfies the hard constraints (" + hard_origins(comp) +
                     ") over atoms of " + labels(comp));
    }
    double shift = ref;
    if (!(z_ > 1e-250)) {  // everything underflowed against the bound: rescale on the true max
      shift = max_s_;
      enumerate(comp, shift, false);
    }
    for (AtomId a : comp.atoms) marg[a] = std::clamp(acc_[a] / z_, 0.0, 1.0);
    if (clause_prob)
      for (std::int32_t c : comp.clauses) (*clause_prob)[c] = std::clamp(cacc_[c] / z_, 0.0, 1.0);
    if (mode) {
      for (std::size_t i = 0; i < comp.atoms.size(); ++i) (*mode)[comp.atoms[i]] = best_[i];
      if (mode_lw) *mode_lw = max_s_;
    }
    return shift + std::log(z_);
  }

 private:
  void flip(AtomId a) {
    const std::uint8_t nv = val_[a] ? 0 : 1;
    if (nv) since_[a] = z_; else acc_[a] += z_ - since_[a];
    val_[a] = nv;
    for (std::int32_t k = occ_.offsets[a]; k < occ_.offsets[a + 1]; ++k) {
      const std::int32_t c = occ_.clause[k];
      if ((nv != 0) != (occ_.negated[k] != 0)) {
        if (cnt_[c]++ == 0) {
          if (hard_[c]) --violated_; else s_ += w_[c];
          if (want_clauses_) csince_[c] = z_;
        }
      } else if (--cnt_[c] == 0) {
        if (hard_[c]) ++violated_; else s_ -= w_[c];
        if (want_clauses_) cacc_[c] += z_ - csince_[c];
      }
    }
  }

  // Loopless reflected mixed-radix Gray code (Knuth, TAOCP 7.2.1.1, Algorithm H).
  void enumerate(const Component& comp, double shift, bool want_mode) {
    const auto nd = static_cast<std::int32_t>(radix_.size());
    for (AtomId a : comp.atoms) {
      val_[a] = 0;
      acc_[a] = 0.0;
      since_[a] = 0.0;
    }
    for (std::int32_t d = nplain_; d < nd; ++d) val_[datoms_[first_[d]]] = 1;
    z_ = 0.0;
    s_ = 0.0;
    violated_ = 0;
    max_s_ = kNegInf;
    for (std::int32_t c : comp.clauses) {
      std::int32_t k = 0;
      for (Lit l : net_.clause(c)) k += lit_true(l, val_[lit_atom(l)]) ? 1 : 0;
      cnt_[c] = k;
      if (k > 0) { if (!hard_[c]) s_ += w_[c]; }
      else if (hard_[c]) ++violated_;
      if (want_clauses_) cacc_[c] = csince_[c] = 0.0;
    }
    digit_.assign(static_cast<std::size_t>(nd), 0);
    dir_.assign(static_cast<std::size_t>(nd), 1);
    focus_.resize(static_cast<std::size_t>(nd) + 1);
    for (std::int32_t d = 0; d <= nd; ++d) focus_[d] = d;
    while (true) {
      if (violated_ == 0) {
        z_ += std::exp(s_ - shift);
        if (s_ > max_s_) {
          max_s_ = s_;
          if (want_mode) {
            best_.resize(comp.atoms.size());
            for (std::size_t i = 0; i < comp.atoms.size(); ++i) best_[i] = val_[comp.atoms[i]];
          }
        }
      }
      const std::int32_t j = focus_[0];
      focus_[0] = 0;
      if (j == nd) break;
      const std::int32_t old = digit_[j];
      digit_[j] += dir_[j];
      if (j < nplain_) {
        flip(datoms_[first_[j]]);
      } else {
        flip(datoms_[first_[j] + old]);
        flip(datoms_[first_[j] + digit_[j]]);
      }
      if (digit_[j] == 0 || digit_[j] == radix_[j] - 1) {
        dir_[j] = -dir_[j];
        focus_[j] = focus_[j + 1];
        focus_[j + 1] = j + 1;
      }
    }
    for (AtomId a : comp.atoms)
      if (val_[a]) acc_[a] += z_ - since_[a];
    if (want_clauses_)
      for (std::int32_t c : comp.clauses)
        if (cnt_[c] > 0) cacc_[c] += z_ - csince_[c];
  }

  std::string hard_origins(const Component& comp) const {
    std::set<std::string> names;
    for (std::int32_t c : comp.clauses)
      if (hard_[c]) names.insert(net_.origin_name(c));
    std::string out;
    for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
    if (!comp.blocks.empty()) out += std::string(out.empty() ? "" : ", ") + "exactly-one blocks";
    return out;
  }
  std::string labels(const Component& comp) const { return describe_labels(net_, comp.atoms); }

  const GroundNetwork& net_;
  const Occurrences occ_;
  std::vector<std::uint8_t> val_, hard_, best_;
  std::vector<double> acc_, since_, w_, cacc_, csince_;
  bool want_clauses_ = false;
  std::vector<std::int32_t> cnt_, radix_, first_, digit_, dir_, focus_;
  std::vector<AtomId> datoms_;
  std::int32_t nplain_ = 0, violated_ = 0;
  double z_ = 0.0, s_ = 0.0, max_s_ = kNegInf;
};

Component whole(const GroundNetwork& net) {
  Component c;
  for (AtomId a = 0; a < net.num_atoms(); ++a) c.atoms.push_back(a);
  for (std::int32_t k = 0; k < net.num_clauses(); ++k) c.clauses.push_back(k);
  for (std::int32_t b = 0; b < net.num_blocks(); ++b) c.blocks.push_back(b);
  return c;
}

}  // namespace

double component_state_bits(const GroundNetwork& net, const Component& comp) {
  double bits = 0.0;
  for (AtomId a : comp.atoms)
    if (net.block_of(a) < 0) bits += 1.0;
  for (std::int32_t b : comp.blocks) bits += std::log2(static_cast<double>(net.block(b).size()));
  return bits;
}

ComponentResult enumerate_network(const GroundNetwork& net) {
  ComponentResult r;
  if (net.num_atoms() == 0) return r;
  Enumerator e(net);
  r.marginals.assign(static_cast<std::size_t>(net.num_atoms()), 0.0);
  r.mode.assign(static_cast<std::size_t>(net.num_atoms()), 0);
  r.log_z = e.run(whole(net), r.marginals, &r.mode, &r.mode_log_weight);
  return r;
}

ExactPlan plan_exact(const GroundNetwork& net, const Component& comp, const ExactOptions& options) {
  ExactPlan p;
  p.bits = component_state_bits(net, comp);
  const bool can_enumerate = p.bits <= options.max_component_bits + 1e-9;
  if (p.bits <= 10.0 || !options.use_elimination) {
    p.solver = can_enumerate ? ExactPlan::Solver::Enumerate : ExactPlan::Solver::TooLarge;
    return p;
  }
  p.elimination = plan_elimination(net, comp, options.max_cluster_entries);
  const bool can_eliminate = p.elimination.order.size() == static_cast<std::size_t>(p.elimination.num_vars()) &&
                             p.elimination.total_entries <= options.max_elimination_entries;
  // Rough costs in table-entry operations: a Gray-code step touches a few clauses; an
  // elimination pass visits every cluster entry about four times (potentials, up, down,
  // marginal) plus once per assigned clause.
  const double enum_cost = std::exp2(p.bits) * 3.0;
  const double elim_cost = p.elimination.total_entries * 8.0;
  if (can_eliminate && (!can_enumerate || elim_cost < enum_cost)) p.solver = ExactPlan::Solver::Eliminate;
  else if (can_enumerate) p.solver = ExactPlan::Solver::Enumerate;
  else p.solver = ExactPlan::Solver::TooLarge;
  return p;
}

void ExactSummary::add(const ExactPlan& plan) {
  switch (plan.solver) {
    case ExactPlan::Solver::Enumerate: ++enumerated; break;
    case ExactPlan::Solver::Eliminate:
      ++eliminated;
      width = std::max(width, plan.elimination.width);
      break;
    case ExactPlan::Solver::TooLarge: ++sampled; break;
  }
}

std::string ExactSummary::describe() const {
  std::string out = sampled > 0 ? "auto:" : "exact:";
  std::string sep;
  if (enumerated > 0 || (eliminated == 0 && sampled == 0)) {
    out += "enum " + std::to_string(enumerated);
    sep = ", ";
  }
  if (eliminated > 0) {
    out += sep + "elim " + std::to_string(eliminated) + " (width " + std::to_string(width) + ")";
    sep = ", ";
  }
  if (sampled > 0) out += sep + "mcsat " + std::to_string(sampled);
  return out;
}

double solve_components(const GroundNetwork& net, std::span<const Component> comps, std::span<const ExactPlan> plans,
                        std::vector<double>& marginals, std::vector<std::uint8_t>* mode,
                        std::vector<double>* clause_prob) {
  double log_z = 0.0;
  std::optional<Enumerator> e;
  for (std::size_t i = 0; i < comps.size(); ++i) {
    io::throw_if_cancelled("exact inference");
    if (plans[i].solver == ExactPlan::Solver::Eliminate) {
      log_z += eliminate_component(net, comps[i], plans[i].elimination, marginals, mode, nullptr, clause_prob);
      continue;
    }
    if (comps[i].atoms.size() == 1 && comps[i].blocks.empty()) {
      log_z += single_atom(net, comps[i], marginals, mode, nullptr, clause_prob);
      continue;
    }
    if (!e) e.emplace(net);
    log_z += e->run(comps[i], marginals, mode, nullptr, clause_prob);
  }
  return log_z;
}

namespace {

std::vector<ExactPlan> plan_all(const GroundNetwork& net, const std::vector<Component>& comps,
                                const ExactOptions& options, ExactSummary& summary) {
  std::vector<ExactPlan> plans;
  plans.reserve(comps.size());
  for (const auto& comp : comps) {
    io::throw_if_cancelled("planning exact inference");
    plans.push_back(plan_exact(net, comp, options));
    if (plans.back().solver == ExactPlan::Solver::TooLarge) throw MlnError(too_large_message(net, comp, options));
    summary.add(plans.back());
  }
  return plans;
}

InferenceResult exact_solve(const GroundNetwork& net, const ExactOptions& options, std::vector<double>* clause_prob) {
  const auto comps = split_components(net);
  ExactSummary summary;
  const auto plans = plan_all(net, comps, options, summary);
  InferenceResult r;
  r.method = summary.describe();
  r.marginals.assign(static_cast<std::size_t>(net.num_atoms()), 0.0);
  if (clause_prob) clause_prob->assign(static_cast<std::size_t>(net.num_clauses()), 1.0);
  r.log_z = net.constant() + solve_components(net, comps, plans, r.marginals, nullptr, clause_prob);
  r.log_z_exact = true;
  return r;
}

}  // namespace

InferenceResult exact_inference(const GroundNetwork& net, const ExactOptions& options) {
  return exact_solve(net, options, nullptr);
}

InferenceResult exact_clause_probabilities(const GroundNetwork& net, std::vector<double>& clause_prob,
                                           const ExactOptions& options) {
  return exact_solve(net, options, &clause_prob);
}

double exact_components(const GroundNetwork& net, std::span<const Component> comps, std::vector<double>& marginals) {
  ExactOptions unlimited;
  unlimited.max_component_bits = 1 << 20;
  std::vector<ExactPlan> plans;
  for (const auto& comp : comps) plans.push_back(plan_exact(net, comp, unlimited));
  return solve_components(net, comps, plans, marginals);
}

MapResult exact_map(const GroundNetwork& net, const ExactOptions& options) {
  const auto comps = split_components(net);
  ExactSummary summary;
  const auto plans = plan_all(net, comps, options, summary);
  MapResult r;
  r.state.assign(static_cast<std::size_t>(net.num_atoms()), 0);
  std::vector<double> marg(static_cast<std::size_t>(net.num_atoms()));
  solve_components(net, comps, plans, marg, &r.state);
  r.feasible = net.feasible(r.state);
  r.log_weight = net.log_weight(r.state);
  return r;
}

std::string too_large_message(const GroundNetwork& net, const Component& comp,
                              const ExactOptions& options) {
  return "exact inference: a connected component has " + std::to_string(comp.atoms.size()) +
         " free atoms (" + std::to_string(static_cast<long long>(std::ceil(component_state_bits(net, comp)))) +
         " bits of state), above the limit of " + std::to_string(options.max_component_bits) +
         " bits (network: " + std::to_string(net.num_atoms()) + " atoms, " +
         std::to_string(net.num_clauses()) + " clauses); its atoms come from " +
         describe_labels(net, comp.atoms) +
         "; neither enumeration nor variable elimination fits the limits; use the auto or mcsat method, or raise max_component_bits";
}

}  // namespace ksmc::runtime::mln
