// Reusable detailed-balance checker for kernel pairs with discrete outcomes.
//
// Given a model, a kernel K, its reverse R and a list of start states (snapshots), it
// checks, from each start state M:
//  1. protocol: reject() restores M exactly (snapshot and log posterior); a declined
//     proposal leaves the model untouched;
//  2. honesty of Q: each outcome M' of K is reported with one log Q(M'|M), and its
//     empirical frequency over `draws` proposals matches exp(log Q(M'|M)) (5 sigma);
//  3. reversibility: from each outcome M', R proposes M back; R's log_q_fwd equals K's
//     log_q_bwd and R's log_q_bwd equals K's log_q_fwd (the two kernels agree on both
//     densities), and the return frequency matches exp(K's log_q_bwd);
//  4. detailed balance of the MH transition built from the kernels' OWN reports:
//       p(M) Phi(K) Q_K(M'|M) a(M,M') = p(M') Phi(R) Q_R(M|M') a(M',M),
//     with a() computed as the engine does.
// Continuous proposals (every outcome unique) cannot be checked this way.
//
// Usage in a Catch2 test:
//   auto report = ksmc::tests::mcmc::check_kernel_pair(model, up, down, states, 0.3, 0.5, rng);
//   INFO(report.summary());
//   CHECK(report.ok());
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "runtime/mcmc/model.h"

namespace ksmc::tests::mcmc {

struct DetailedBalanceOptions {
  std::size_t draws = 20000;  // proposals per start state (and per outcome, for the reverse)
  double sigmas = 5.0;        // frequency tolerance in binomial standard deviations
  double slack = 1e-3;        // plus this absolute tolerance on frequencies
  double log_tol = 1e-9;      // tolerance on exact log-density identities
  std::size_t max_failures = 20;
};

struct DetailedBalanceReport {
  std::size_t start_states = 0;
  std::size_t transitions = 0;       // distinct (M, M') pairs checked
  double max_frequency_error = 0.0;  // |empirical - exp(log Q)|, forward and reverse
  double max_log_q_mismatch = 0.0;   // between K's and R's reports of the same density
  double max_balance_error = 0.0;    // |log lhs - log rhs| of detailed balance
  std::vector<std::string> failures;

  bool ok() const { return failures.empty() && transitions > 0; }
  std::string summary() const {
    std::ostringstream os;
    os << "detailed balance: " << start_states << " start states, " << transitions
       << " transitions, max |freq - Q| = " << max_frequency_error
       << ", max log-Q mismatch = " << max_log_q_mismatch
       << ", max balance error = " << max_balance_error << ", " << failures.size() << " failure(s)";
    for (const auto& f : failures) os << "\n  " << f;
    return os.str();
  }
};

namespace detail {

struct Outcome {
  std::size_t count = 0;
  double log_q_fwd = 0.0;
  double log_q_bwd = 0.0;
  double log_p = 0.0;
  runtime::mcmc::Snapshot state;
};

struct Sampled {
  std::map<std::string, Outcome> outcomes;  // keyed by the snapshot's JSON text
  std::size_t declined = 0;
};

inline void fail(DetailedBalanceReport& r, const DetailedBalanceOptions& o, std::string msg) {
  if (r.failures.size() < o.max_failures) r.failures.push_back(std::move(msg));
}

// Draws `draws` proposals of `k` from the model's current state.
inline Sampled sample_kernel(runtime::mcmc::Model& model, const runtime::mcmc::Kernel& k,
                             runtime::mcmc::Rng& rng, const DetailedBalanceOptions& o,
                             DetailedBalanceReport& r) {
  Sampled s;
  const std::string start = model.snapshot().dump();
  const double start_lp = model.log_posterior();
  for (std::size_t i = 0; i < o.draws; ++i) {
    const runtime::mcmc::Proposal p = k.propose(model, rng);
    if (p.was_declined()) {
      ++s.declined;
    } else {
      const auto snap = model.snapshot();
      auto [it, fresh] = s.outcomes.try_emplace(snap.dump());
      Outcome& out = it->second;
      if (fresh) {
        out.log_q_fwd = p.log_q_fwd;
        out.log_q_bwd = p.log_q_bwd;
        out.log_p = model.log_posterior();
        out.state = snap;
      } else if (std::fabs(out.log_q_fwd - p.log_q_fwd) > o.log_tol ||
                 std::fabs(out.log_q_bwd - p.log_q_bwd) > o.log_tol) {
        fail(r, o, std::string(k.name()) + " from " + start + " to " + it->first +
                       ": the same move reported with different densities");
      }
      ++out.count;
      model.reject();
    }
    if (model.snapshot().dump() != start || model.log_posterior() != start_lp) {
      fail(r, o, std::string(k.name()) + " from " + start + ": " +
                     (p.was_declined() ? "declined proposal changed the model"
                                       : "reject() did not restore the state exactly"));
      model.restore(nlohmann::json::parse(start));
    }
  }
  return s;
}

inline double freq_tolerance(double p, const DetailedBalanceOptions& o) {
  return o.sigmas * std::sqrt(std::max(p * (1.0 - p), 0.0) / static_cast<double>(o.draws)) + o.slack;
}

// log a(M -> M') as the engine computes it.
inline double log_alpha(double lp_from, double lp_to, double log_q_fwd, double log_q_bwd,
                        double log_sel_fwd, double log_sel_rev) {
  const double v = (lp_to - lp_from) + (log_q_bwd + log_sel_rev) - (log_q_fwd + log_sel_fwd);
  return std::min(0.0, v);
}

}  // namespace detail

// phi_fwd / phi_rev: the schedule's selection probabilities of K and R (equal and 1 for a
// self-reverse kernel like INTERCHANGE: pass the same kernel twice). Leaves the model in
// an unspecified one of the given states.
inline DetailedBalanceReport check_kernel_pair(runtime::mcmc::Model& model,
                                               const runtime::mcmc::Kernel& fwd,
                                               const runtime::mcmc::Kernel& rev,
                                               const std::vector<runtime::mcmc::Snapshot>& states,
                                               double phi_fwd, double phi_rev,
                                               runtime::mcmc::Rng& rng,
                                               const DetailedBalanceOptions& o = {}) {
  DetailedBalanceReport r;
  if (fwd.reverse_name() != rev.name() || rev.reverse_name() != fwd.name()) {
    detail::fail(r, o, std::string("kernels ") + std::string(fwd.name()) + " and " +
                           std::string(rev.name()) + " are not declared as a reverse pair");
    return r;
  }
  const double lsf = std::log(phi_fwd);
  const double lsr = std::log(phi_rev);
  const double n = static_cast<double>(o.draws);
  for (const auto& start : states) {
    ++r.start_states;
    model.restore(start);
    const std::string from_key = model.snapshot().dump();
    const double lp_from = model.log_posterior();
    const detail::Sampled fw = detail::sample_kernel(model, fwd, rng, o, r);

    // Reported mass must account for what was observed, declines included.
    double reported = 0.0;
    for (const auto& [key, out] : fw.outcomes) reported += std::exp(out.log_q_fwd);
    const double decl = static_cast<double>(fw.declined) / n;
    if (std::fabs((1.0 - reported) - decl) > detail::freq_tolerance(decl, o)) {
      detail::fail(r, o, std::string(fwd.name()) + " from " + from_key + ": reported Q sums to " +
                             std::to_string(reported) + " but " + std::to_string(decl) +
                             " of the proposals were declined");
    }
    for (const auto& [to_key, out] : fw.outcomes) {
      ++r.transitions;
      const double q = std::exp(out.log_q_fwd);
      const double err = std::fabs(static_cast<double>(out.count) / n - q);
      r.max_frequency_error = std::max(r.max_frequency_error, err);
      if (err > detail::freq_tolerance(q, o)) {
        detail::fail(r, o, std::string(fwd.name()) + " " + from_key + " -> " + to_key +
                               ": frequency " + std::to_string(out.count / n) + " but Q = " +
                               std::to_string(q));
      }
      // Reverse move from M'.
      model.restore(out.state);
      const detail::Sampled bw = detail::sample_kernel(model, rev, rng, o, r);
      const auto back = bw.outcomes.find(from_key);
      const double q_back = std::exp(out.log_q_bwd);
      if (back == bw.outcomes.end()) {
        if (q_back > detail::freq_tolerance(0.0, o)) {
          detail::fail(r, o, std::string(rev.name()) + " " + to_key + " -> " + from_key +
                                 ": never proposed, but " + std::string(fwd.name()) +
                                 " reported Q(M|M') = " + std::to_string(q_back));
        }
        continue;
      }
      const detail::Outcome& b = back->second;
      const double mismatch = std::max(std::fabs(b.log_q_fwd - out.log_q_bwd),
                                       std::fabs(b.log_q_bwd - out.log_q_fwd));
      r.max_log_q_mismatch = std::max(r.max_log_q_mismatch, mismatch);
      if (mismatch > o.log_tol) {
        detail::fail(r, o, std::string(fwd.name()) + "/" + std::string(rev.name()) + " " + from_key +
                               " <-> " + to_key + ": forward reports (q_fwd " +
                               std::to_string(out.log_q_fwd) + ", q_bwd " +
                               std::to_string(out.log_q_bwd) + "), reverse reports (q_fwd " +
                               std::to_string(b.log_q_fwd) + ", q_bwd " +
                               std::to_string(b.log_q_bwd) + ")");
      }
      const double back_err = std::fabs(static_cast<double>(b.count) / n - std::exp(b.log_q_fwd));
      r.max_frequency_error = std::max(r.max_frequency_error, back_err);
      if (back_err > detail::freq_tolerance(std::exp(b.log_q_fwd), o)) {
        detail::fail(r, o, std::string(rev.name()) + " " + to_key + " -> " + from_key +
                               ": frequency " + std::to_string(b.count / n) + " but Q = " +
                               std::to_string(std::exp(b.log_q_fwd)));
      }
      // Detailed balance with each side's own reports.
      const double lhs = lp_from + lsf + out.log_q_fwd +
                         detail::log_alpha(lp_from, out.log_p, out.log_q_fwd, out.log_q_bwd, lsf, lsr);
      const double rhs = out.log_p + lsr + b.log_q_fwd +
                         detail::log_alpha(out.log_p, lp_from, b.log_q_fwd, b.log_q_bwd, lsr, lsf);
      const double bal = std::fabs(lhs - rhs);
      r.max_balance_error = std::max(r.max_balance_error, bal);
      if (bal > 1e-6) {
        detail::fail(r, o, std::string(fwd.name()) + "/" + std::string(rev.name()) + " " + from_key +
                               " <-> " + to_key + ": detailed balance off by " + std::to_string(bal) +
                               " in log");
      }
    }
  }
  return r;
}

}  // namespace ksmc::tests::mcmc
