#include "stdlib/segments/kit/semantics.h"

#include <array>
#include <chrono>
#include <cmath>
#include <limits>

#include "runtime/mln/error.h"
#include "runtime/mln/evidence.h"
#include "runtime/mln/inference.h"

namespace ksmc::stdlib::segments::kit {

namespace dom = runtime::domain;
namespace mln = runtime::mln;

namespace {

constexpr double kNegInf = -std::numeric_limits<double>::infinity();

bool relation(const ExtractSpec& x, const Segment& s, const Segment& t) {
  switch (x.relation) {
    case Relation::Touching: return touching(s, t, x.param);
    case Relation::Perpendicular: return perpendicular(s, t, x.param);
    case Relation::Parallel: return parallel(s, t, x.param);
    case Relation::Close: return close_lines(s, t, x.param);
    case Relation::Short: return is_short(s, x.param);
  }
  return false;
}

double measure(Measure m, const Segment& s, const Segment& t) {
  switch (m) {
    case Measure::EndpointGap: return endpoint_gap(s, t);
    case Measure::LineOffset: return line_offset(s, t);
    case Measure::CornerAngleError: return corner_angle_error(s, t);
    case Measure::ParallelAngleError: return parallel_angle_error(s, t);
  }
  return 0.0;
}

std::size_t ipow(std::size_t n, std::size_t k) {
  std::size_t r = 1;
  for (std::size_t i = 0; i < k; ++i) r *= n;
  return r;
}

}  // namespace

Semantics::Semantics(const SegmentsSettings& settings, const dom::MlnBinding& binding, std::size_t cache_capacity)
    : settings_(settings), binding_(binding), cache_(cache_capacity) {
  if (!binding_.program || !binding_.make_domain || !binding_.ground)
    throw dom::ConfigError("segments kit: incomplete Markov logic binding");
  program_ = &binding_.program();
  const mln::Program& p = *program_;
  const auto t = p.find_type(settings.collection);
  if (!t)
    throw dom::ConfigError("segments kit: the knowledge base needs a type named like the model collection '" +
                           settings.collection + "'");
  type_ = *t;
  for (std::size_t i = 0; i < p.predicates.size(); ++i) {
    const mln::Predicate& pr = p.predicates[i];
    for (const std::int32_t a : pr.arg_types)
      if (a != type_)
        throw dom::ConfigError("segments kit: predicate " + pr.name + " must range over '" + settings.collection + "' only");
    if (pr.arg_types.empty() || pr.arg_types.size() > 2)
      throw dom::ConfigError("segments kit: predicate " + pr.name + " must take one or two segments");
    if (pr.query) queries_.push_back(static_cast<std::int32_t>(i));
  }
  for (const ExtractSpec& x : settings.extracts) {
    const auto id = p.find_predicate(x.predicate);
    if (!id || p.predicates[static_cast<std::size_t>(*id)].query ||
        p.predicates[static_cast<std::size_t>(*id)].arg_types.size() != x.arity)
      throw dom::ConfigError(x.where + ": " + x.predicate + " must be an evidence predicate of arity " +
                             std::to_string(x.arity));
    extract_pred_.push_back(*id);
  }
  for (std::size_t i = 0; i < p.predicates.size(); ++i) {
    if (p.predicates[i].query) continue;
    bool bound = false;
    for (const auto e : extract_pred_) bound = bound || e == static_cast<std::int32_t>(i);
    if (!bound)
      throw dom::ConfigError("segments kit: evidence predicate " + p.predicates[i].name + " has no extractor");
  }
  for (const SemanticTermSpec& term : settings.terms) {
    std::vector<std::int32_t> preds;
    for (const ConditionSpec& c : term.conditions) {
      const auto id = p.find_predicate(c.predicate);
      if (!id || p.predicates[static_cast<std::size_t>(*id)].arg_types.size() != c.args.size() ||
          (c.probability && !p.predicates[static_cast<std::size_t>(*id)].query))
        throw dom::ConfigError(term.where + ": condition on " + c.predicate + ": unknown predicate or wrong arity");
      preds.push_back(*id);
    }
    term_cond_pred_.push_back(std::move(preds));
  }
}

std::vector<std::uint8_t> Semantics::key(const std::vector<Line>& lines) const {
  const std::size_t n = lines.size();
  std::vector<std::uint8_t> bits;
  bits.reserve(4 + settings_.extracts.size() * n * n);
  for (int k = 0; k < 4; ++k) bits.push_back(static_cast<std::uint8_t>((n >> (8 * k)) & 0xFF));
  for (const ExtractSpec& x : settings_.extracts) {
    if (x.arity == 1) {
      for (std::size_t a = 0; a < n; ++a) bits.push_back(relation(x, lines[a].seg, lines[a].seg) ? 1 : 0);
    } else {
      // A segment is never in a relation with itself.
      for (std::size_t a = 0; a < n; ++a)
        for (std::size_t b = 0; b < n; ++b)
          bits.push_back(a != b && relation(x, lines[a].seg, lines[b].seg) ? 1 : 0);
    }
  }
  return bits;
}

std::shared_ptr<const MlnOutcome> Semantics::evaluate(const std::vector<Line>& lines) {
  ++stats_.lookups;
  const std::vector<std::uint8_t> bits = key(lines);
  if (auto hit = cache_.find(bits)) {
    ++stats_.hits;
    return hit;
  }
  const auto t0 = std::chrono::steady_clock::now();
  auto outcome = run(bits, lines.size());
  stats_.run_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ++stats_.runs;
  cache_.insert(bits, outcome);
  return outcome;
}

std::shared_ptr<const MlnOutcome> Semantics::run(const std::vector<std::uint8_t>& bits, std::size_t n) {
  const mln::Program& program = *program_;
  auto out = std::make_shared<MlnOutcome>();
  out->lines = n;
  out->values.resize(program.predicates.size());
  for (std::size_t p = 0; p < program.predicates.size(); ++p)
    out->values[p].assign(ipow(n, program.predicates[p].arg_types.size()), 0.0);
  if (n == 0) {
    out->method = "none";
    return out;
  }
  mln::Domain domain = binding_.make_domain();
  for (std::size_t i = 0; i < n; ++i) domain.add(type_, "L" + std::to_string(i));
  mln::Evidence evidence(program, domain);
  std::size_t k = 4;
  for (std::size_t e = 0; e < settings_.extracts.size(); ++e) {
    const std::int32_t p = extract_pred_[e];
    auto& vals = out->values[static_cast<std::size_t>(p)];
    if (settings_.extracts[e].arity == 1) {
      for (std::size_t a = 0; a < n; ++a) {
        const std::array<std::int32_t, 1> args{static_cast<std::int32_t>(a)};
        const bool v = bits[k++] != 0;
        evidence.set(p, args, v);
        vals[a] = v ? 1.0 : 0.0;
      }
    } else {
      for (std::size_t a = 0; a < n; ++a)
        for (std::size_t b = 0; b < n; ++b) {
          const std::array<std::int32_t, 2> args{static_cast<std::int32_t>(a), static_cast<std::int32_t>(b)};
          const bool v = bits[k++] != 0;
          evidence.set(p, args, v);
          vals[a * n + b] = v ? 1.0 : 0.0;
        }
    }
  }
  try {
    const mln::Grounding g = binding_.ground(domain, evidence);
    mln::InferenceOptions opt;
    opt.method = mln::Method::Auto;
    opt.compute_log_z = true;
    opt.mcsat.seed = 1;
    const mln::InferenceResult r = mln::infer(g.network, opt);
    out->log_z = r.log_z;
    out->method = r.method;
    for (const std::int32_t q : queries_) {
      auto& vals = out->values[static_cast<std::size_t>(q)];
      const std::size_t arity = program.predicates[static_cast<std::size_t>(q)].arg_types.size();
      for (std::size_t flat = 0; flat < vals.size(); ++flat) {
        std::array<std::int32_t, 2> args{};
        if (arity == 1) {
          args[0] = static_cast<std::int32_t>(flat);
        } else {
          args[0] = static_cast<std::int32_t>(flat / n);
          args[1] = static_cast<std::int32_t>(flat % n);
        }
        vals[flat] = g.marginal(r, q, std::span<const std::int32_t>(args.data(), arity));
      }
    }
  } catch (const mln::MlnError& e) {
    out->log_z = kNegInf;
    out->method = std::string("impossible: ") + e.what();
  }
  return out;
}

double Semantics::baseline_log_z(std::size_t n) {
  if (auto it = baseline_.find(n); it != baseline_.end()) return it->second;
  std::vector<std::uint8_t> bits(4 + settings_.extracts.size() * n * n, 0);
  for (int k = 0; k < 4; ++k) bits[static_cast<std::size_t>(k)] = static_cast<std::uint8_t>((n >> (8 * k)) & 0xFF);
  const double z = run(bits, n)->log_z;
  const double v = std::isfinite(z) ? z : 0.0;
  baseline_.emplace(n, v);
  return v;
}

double Semantics::value(const MlnOutcome& o, std::int32_t pred, const std::vector<std::size_t>& args) const {
  std::size_t flat = 0;
  for (const std::size_t a : args) flat = flat * o.lines + a;
  return o.values[static_cast<std::size_t>(pred)][flat];
}

double Semantics::semantic_terms(const std::vector<Line>& lines, const MlnOutcome& outcome) const {
  const std::size_t n = lines.size();
  double total = 0.0;
  for (std::size_t t = 0; t < settings_.terms.size(); ++t) {
    const SemanticTermSpec& term = settings_.terms[t];
    const std::size_t k = term.vars.size();
    const std::size_t count = ipow(n, k);
    std::vector<std::size_t> binding(k, 0), args;
    for (std::size_t flat = 0; flat < count; ++flat) {
      std::size_t r = flat;
      for (std::size_t v = k; v-- > 0;) {
        binding[v] = r % n;
        r /= n;
      }
      bool pass = true;
      for (std::size_t c = 0; c < term.conditions.size() && pass; ++c) {
        const ConditionSpec& cond = term.conditions[c];
        args.clear();
        for (const std::size_t a : cond.args) args.push_back(binding[a]);
        const double v = value(outcome, term_cond_pred_[t][c], args);
        bool ok;
        if (cond.probability) {
          ok = cond.op == ">" ? v > cond.threshold
             : cond.op == ">=" ? v >= cond.threshold
             : cond.op == "<" ? v < cond.threshold
                              : v <= cond.threshold;
        } else {
          ok = v > 0.5;
        }
        pass = cond.negated ? !ok : ok;
      }
      if (!pass) continue;
      const double x = measure(term.measure, lines[binding[term.arg_a]].seg, lines[binding[term.arg_b]].seg) / term.sigma;
      total -= 0.5 * x * x;
    }
  }
  return total;
}

}  // namespace ksmc::stdlib::segments::kit
