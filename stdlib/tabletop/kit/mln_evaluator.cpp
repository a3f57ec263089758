#include "stdlib/tabletop/kit/mln_evaluator.h"

#include <array>
#include <chrono>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "runtime/mln/error.h"
#include "runtime/mln/inference.h"
#include "runtime/mln/maxwalksat.h"

namespace ksmc::stdlib::tabletop::kit {

namespace mln = ksmc::runtime::mln;
namespace rd = ksmc::runtime::domain;

namespace {

std::int32_t predicate(const mln::Program& p, const char* name, std::size_t arity) {
  const auto id = p.find_predicate(name);
  if (!id) throw rd::ConfigError(fmt::format("tabletop kit: the domain's Markov logic program has no predicate '{}'", name));
  if (p.predicates[*id].arg_types.size() != arity)
    throw rd::ConfigError(fmt::format("tabletop kit: predicate '{}' must have arity {}", name, arity));
  return *id;
}

}  // namespace

MlnEvaluator::MlnEvaluator(const rd::MlnBinding& binding, const std::vector<std::string>& body_ids,
                           std::size_t cache_capacity)
    : binding_(binding), n_(body_ids.size()), cache_(cache_capacity) {
  if (!binding_.program || !binding_.make_domain || !binding_.ground)
    throw rd::ConfigError("tabletop kit: incomplete Markov logic binding");
  const mln::Program& p = binding_.program();
  p_stable_ = predicate(p, "stable", 1);
  p_table_ = predicate(p, "table", 1);
  p_hover_ = predicate(p, "hover", 1);
  p_contact_ = predicate(p, "contact", 2);
  p_intersect_ = predicate(p, "intersect", 2);
  p_higher_ = predicate(p, "higher", 2);
  p_false_ = predicate(p, "falseEst", 1);
  p_hidden_ = predicate(p, "hidden", 1);
  const std::int32_t type = p.predicates[p_stable_].arg_types[0];
  for (const std::int32_t q : {p_table_, p_hover_, p_contact_, p_intersect_, p_higher_, p_false_, p_hidden_})
    for (const std::int32_t t : p.predicates[q].arg_types)
      if (t != type) throw rd::ConfigError("tabletop kit: every predicate must range over the one object type");
  domain_ = binding_.make_domain();
  if (domain_.size(type) != 0)
    throw rd::ConfigError("tabletop kit: the object type must not have constants in the domain file");
  for (std::size_t i = 0; i < n_; ++i) {
    const std::int32_t idx = domain_.add(type, body_ids[i]);
    if (static_cast<std::size_t>(idx) != i)
      throw rd::ConfigError(fmt::format("tabletop kit: duplicate body id '{}'", body_ids[i]));
  }
}

std::vector<std::uint8_t> MlnEvaluator::key(const Evidence& ev) const {
  if (ev.size() != n_)
    throw std::invalid_argument(fmt::format("tabletop kit: evidence has {} bodies, expected {}", ev.size(), n_));
  std::vector<std::uint8_t> bits;
  bits.reserve(3 * n_ + 3 * n_ * n_);
  for (std::size_t a = 0; a < n_; ++a) bits.push_back(ev.stable[a] ? 1 : 0);
  for (std::size_t a = 0; a < n_; ++a) bits.push_back(ev.is_table[a] ? 1 : 0);
  for (std::size_t a = 0; a < n_; ++a) bits.push_back(ev.hover[a] ? 1 : 0);
  for (const auto* m : {&ev.contact, &ev.intersect, &ev.higher})
    for (std::size_t a = 0; a < n_; ++a)
      for (std::size_t b = 0; b < n_; ++b) bits.push_back((*m)[a][b] ? 1 : 0);
  return bits;
}

namespace {

class Stopwatch {
 public:
  explicit Stopwatch(double& sink) : sink_(sink), start_(std::chrono::steady_clock::now()) {}
  ~Stopwatch() { sink_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
  Stopwatch(const Stopwatch&) = delete;
  Stopwatch& operator=(const Stopwatch&) = delete;

 private:
  double& sink_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace

std::shared_ptr<const MlnOutcome> MlnEvaluator::evaluate(const Evidence& ev) {
  Stopwatch w(stats_.seconds);
  return lookup(key(ev));
}

std::shared_ptr<const MlnOutcome> MlnEvaluator::evaluate_key(const std::vector<std::uint8_t>& bits) {
  Stopwatch w(stats_.seconds);
  return lookup(bits);
}

std::shared_ptr<const MlnOutcome> MlnEvaluator::lookup(const std::vector<std::uint8_t>& bits) {
  ++stats_.lookups;
  if (auto hit = cache_.find(bits)) {
    ++stats_.hits;
    return hit;
  }
  std::shared_ptr<const MlnOutcome> outcome;
  {
    Stopwatch w(stats_.run_seconds);
    outcome = run(bits);
  }
  ++stats_.runs;
  cache_.insert(bits, outcome);
  return outcome;
}

std::shared_ptr<const MlnOutcome> MlnEvaluator::run(const std::vector<std::uint8_t>& bits) {
  const mln::Program& program = binding_.program();
  mln::Evidence evidence(program, domain_);
  std::size_t k = 0;
  for (const std::int32_t p : {p_stable_, p_table_, p_hover_})
    for (std::size_t a = 0; a < n_; ++a) {
      const std::array<std::int32_t, 1> args{static_cast<std::int32_t>(a)};
      evidence.set(p, args, bits[k++] != 0);
    }
  for (const std::int32_t p : {p_contact_, p_intersect_, p_higher_})
    for (std::size_t a = 0; a < n_; ++a)
      for (std::size_t b = 0; b < n_; ++b) {
        const std::array<std::int32_t, 2> args{static_cast<std::int32_t>(a), static_cast<std::int32_t>(b)};
        evidence.set(p, args, bits[k++] != 0);
      }
  auto out = std::make_shared<MlnOutcome>();
  out->false_prob.assign(n_, 0.0);
  out->hidden_prob.assign(n_, 0.0);
  try {
    const mln::Grounding g = binding_.ground(domain_, evidence);
    mln::InferenceOptions opt;
    opt.method = mln::Method::Auto;
    opt.compute_log_z = true;
    const mln::InferenceResult r = mln::infer(g.network, opt);
    out->log_z = r.log_z;
    out->log_z_exact = r.log_z_exact;
    mln::MapResult map;
    try {
      map = mln::exact_map(g.network);
    } catch (const mln::MlnError&) {
      map = mln::max_walksat(g.network);  // a component too large to enumerate
      out->log_map_exact = false;
    }
    out->log_map = map.feasible ? map.log_weight : -std::numeric_limits<double>::infinity();
    out->method = r.method;
    for (std::size_t a = 0; a < n_; ++a) {
      const std::array<std::int32_t, 1> args{static_cast<std::int32_t>(a)};
      out->false_prob[a] = g.marginal(r, p_false_, args);
      out->hidden_prob[a] = g.marginal(r, p_hidden_, args);
    }
  } catch (const mln::MlnError& e) {
    // A hard rule cannot hold under this evidence: the state is impossible.
    out->log_z = -std::numeric_limits<double>::infinity();
    out->log_map = out->log_z;
    out->method = std::string("impossible: ") + e.what();
  }
  return out;
}

}  // namespace ksmc::stdlib::tabletop::kit
