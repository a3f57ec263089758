#include "runtime/domain/semantics.h"

#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "runtime/mln/error.h"
#include "runtime/mln/evidence.h"
#include "runtime/mln/exact.h"
#include "runtime/mln/ground_bound.h"
#include "runtime/mln/inference.h"
#include "runtime/mln/maxwalksat.h"

namespace ksmc::runtime::domain {

namespace {

constexpr double kNegInf = -std::numeric_limits<double>::infinity();

// Internal names of run-time constants: `#` never starts a domain-file constant.
std::string anonymous(std::size_t i) { return "#" + std::to_string(i); }

double round6(double v) { return std::round(v * 1e6) / 1e6; }

// Calls fn(args) for every tuple of constant indices under `radix`, odometer order.
template <class Fn>
void for_each_tuple(const std::vector<std::int32_t>& radix, Fn&& fn) {
  std::size_t count = 1;
  for (const std::int32_t r : radix) count *= static_cast<std::size_t>(r);
  std::vector<std::int32_t> args(radix.size(), 0);
  for (std::size_t flat = 0; flat < count; ++flat) {
    if (flat != 0)
      for (std::size_t i = args.size(); i-- > 0;) {
        if (++args[i] < radix[i]) break;
        args[i] = 0;
      }
    fn(flat, args);
  }
}

}  // namespace

SemanticsCore::SemanticsCore(const MlnBinding& mln, std::int32_t constant_type, std::vector<std::int32_t> extracted,
                             SemanticOptions options)
    : mln_(mln),
      constant_type_(constant_type),
      extracted_(std::move(extracted)),
      options_(options),
      cache_(options.cache_capacity) {
  if (!mln_.program || !mln_.make_domain || !mln_.ground)
    throw ConfigError("semantics: incomplete Markov logic binding (program, make_domain and ground are required)");
  program_ = &mln_.program();
  const mln::Program& p = *program_;
  if (constant_type_ < 0 || static_cast<std::size_t>(constant_type_) >= p.types.size())
    throw ConfigError("semantics: constant type " + std::to_string(constant_type_) + " is not a type of the program");
  base_domain_ = mln_.make_domain();
  base_domain_.resize(p.types.size());
  std::vector<bool> seen(p.predicates.size(), false);
  for (const std::int32_t e : extracted_) {
    if (e < 0 || static_cast<std::size_t>(e) >= p.predicates.size())
      throw ConfigError("semantics: extractor for predicate " + std::to_string(e) + ", which the program lacks");
    const mln::Predicate& pr = p.predicates[static_cast<std::size_t>(e)];
    if (pr.query) throw ConfigError("semantics: an extractor computes query predicate " + pr.name);
    if (seen[static_cast<std::size_t>(e)]) throw ConfigError("semantics: two extractors compute " + pr.name);
    seen[static_cast<std::size_t>(e)] = true;
  }
  for (std::size_t i = 0; i < p.predicates.size(); ++i)
    if (p.predicates[i].query) queries_.push_back(static_cast<std::int32_t>(i));
}

std::size_t SemanticsCore::constants_of(std::int32_t type, std::size_t n) const {
  const std::size_t fixed =
      static_cast<std::size_t>(type) < base_domain_.num_types() ? static_cast<std::size_t>(base_domain_.size(type)) : 0;
  return type == constant_type_ ? fixed + n : fixed;
}

std::size_t SemanticsCore::atoms_of(std::int32_t predicate, std::size_t n) const {
  std::size_t count = 1;
  for (const std::int32_t t : program_->predicates[static_cast<std::size_t>(predicate)].arg_types)
    count *= constants_of(t, n);
  return count;
}

bool SemanticsCore::prepare(std::size_t n, bool full, std::span<const std::int32_t> changed, const Outcome* base) {
  const std::size_t total = constants_of(constant_type_, n);
  if (!have_bits_ || bits_n_ != n) {
    shapes_.assign(extracted_.size(), {});
    bits_.assign(extracted_.size(), {});
    for (std::size_t k = 0; k < extracted_.size(); ++k) {
      for (const std::int32_t t : program_->predicates[static_cast<std::size_t>(extracted_[k])].arg_types) {
        shapes_[k].radix.push_back(static_cast<std::int32_t>(constants_of(t, n)));
        shapes_[k].of_constant_type.push_back(t == constant_type_);
      }
      bits_[k].assign(atoms_of(extracted_[k], n), 0);
    }
  }
  bool all = full || (base == nullptr && (!have_bits_ || bits_n_ != n));
  if (!all && base != nullptr) {
    if (base->constants != n || base->values.size() != program_->predicates.size()) {
      all = true;
    } else {
      for (std::size_t k = 0; k < extracted_.size(); ++k) {
        const auto& v = base->values[static_cast<std::size_t>(extracted_[k])];
        auto& bits = bits_[k];
        for (std::size_t flat = 0; flat < bits.size(); ++flat) bits[flat] = v[flat] > 0.5 ? 1 : 0;
      }
    }
  }
  have_bits_ = true;
  bits_n_ = n;
  changed_.assign(total, 0);
  if (!all)
    for (const std::int32_t c : changed) {
      if (c < 0 || static_cast<std::size_t>(c) >= total)
        throw std::out_of_range("semantics: changed constant " + std::to_string(c) + " of " + std::to_string(total));
      changed_[static_cast<std::size_t>(c)] = 1;
    }
  return all;
}

std::shared_ptr<const Outcome> SemanticsCore::finish(std::size_t n) {
  ++stats_.evaluations;
  std::vector<std::uint8_t> key;
  std::size_t size = 8;
  for (const auto& b : bits_) size += b.size();
  key.reserve(size);
  for (int k = 0; k < 8; ++k) key.push_back(static_cast<std::uint8_t>((static_cast<std::uint64_t>(n) >> (8 * k)) & 0xFF));
  for (const auto& b : bits_) key.insert(key.end(), b.begin(), b.end());
  if (auto hit = cache_.find(key)) {
    ++stats_.cache_hits;
    return hit;
  }
  auto out = infer_bits(n);
  cache_.insert(std::move(key), out);
  return out;
}

std::shared_ptr<const Outcome> SemanticsCore::empty_evidence(std::size_t n) {
  if (auto it = empty_.find(n); it != empty_.end()) return it->second;
  // infer_bits reads bits_: run it on all-false bits and restore the caller's state.
  auto saved_bits = std::move(bits_);
  auto saved_shapes = std::move(shapes_);
  const bool saved_have = have_bits_;
  const std::size_t saved_n = bits_n_;
  have_bits_ = false;
  prepare(n, true, {}, nullptr);
  auto out = infer_bits(n);
  bits_ = std::move(saved_bits);
  shapes_ = std::move(saved_shapes);
  have_bits_ = saved_have;
  bits_n_ = saved_n;
  empty_.emplace(n, out);
  return out;
}

std::shared_ptr<const Outcome> SemanticsCore::infer_bits(std::size_t n) {
  const auto t0 = std::chrono::steady_clock::now();
  const mln::Program& program = *program_;
  auto out = std::make_shared<Outcome>();
  out->constants = n;
  out->values.resize(program.predicates.size());
  std::size_t atoms = 0;
  for (std::size_t p = 0; p < program.predicates.size(); ++p) {
    out->values[p].assign(atoms_of(static_cast<std::int32_t>(p), n), 0.0);
    atoms += out->values[p].size();
  }
  for (std::size_t k = 0; k < extracted_.size(); ++k) {
    auto& v = out->values[static_cast<std::size_t>(extracted_[k])];
    for (std::size_t flat = 0; flat < v.size(); ++flat) v[flat] = bits_[k][flat];
  }
  if (atoms == 0) {
    out->method = "none";
    return out;
  }
  mln::Domain domain = base_domain_;
  for (std::size_t i = 0; i < n; ++i) domain.add(constant_type_, anonymous(i));
  mln::Evidence evidence(program, domain);
  for (std::size_t p = 0; p < program.predicates.size(); ++p) {
    if (program.predicates[p].query) continue;
    const auto& v = out->values[p];
    for (std::size_t flat = 0; flat < v.size(); ++flat)
      evidence.set_flat(static_cast<std::int32_t>(p), static_cast<std::int64_t>(flat), v[flat] > 0.5 ? 1 : 0);
  }
  try {
    const mln::Grounding g = mln_.ground(domain, evidence);
    mln::InferenceOptions opt;
    opt.method = mln::Method::Auto;
    opt.compute_log_z = options_.log_z;
    opt.mcsat.seed = options_.seed;
    opt.mcsat.samples = static_cast<std::int64_t>(options_.mcsat_samples);
    opt.mcsat.burn_in = static_cast<std::int64_t>(options_.mcsat_burn_in);
    opt.log_z.seed = options_.seed;
    const mln::InferenceResult r = mln::infer(g.network, opt);
    out->method = r.method;
    out->exact = r.samples == 0 && (!options_.log_z || r.log_z_exact);
    if (options_.log_z) out->log_z = r.log_z;
    if (options_.log_map) {
      mln::MapResult map;
      try {
        map = mln::exact_map(g.network);
      } catch (const mln::MlnError&) {
        mln::MapOptions mo;
        mo.seed = options_.seed;
        map = mln::max_walksat(g.network, mo);  // a component too large to enumerate
        out->exact = false;
      }
      out->log_map = map.feasible ? map.log_weight : kNegInf;
    }
    for (const std::int32_t q : queries_) {
      auto& v = out->values[static_cast<std::size_t>(q)];
      std::vector<std::int32_t> radix;
      for (const std::int32_t t : program.predicates[static_cast<std::size_t>(q)].arg_types)
        radix.push_back(static_cast<std::int32_t>(constants_of(t, n)));
      for_each_tuple(radix, [&](std::size_t flat, const std::vector<std::int32_t>& args) {
        v[flat] = g.marginal(r, q, args);
      });
    }
  } catch (const mln::GroundingTooLarge&) {
    throw;  // a refusal of the input (--max-ground-clauses), not an impossible state
  } catch (const mln::MlnError& e) {
    // A hard rule cannot hold under this evidence: the state is impossible.
    for (const std::int32_t q : queries_) std::fill(out->values[static_cast<std::size_t>(q)].begin(),
                                                    out->values[static_cast<std::size_t>(q)].end(), 0.0);
    out->possible = false;
    out->log_z = kNegInf;
    out->log_map = kNegInf;
    out->method = std::string("impossible: ") + e.what();
  }
  ++stats_.inferences;
  stats_.inference_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

double SemanticsCore::value(const Outcome& o, std::int32_t predicate, std::span<const std::int32_t> args) const {
  const auto& types = program_->predicates[static_cast<std::size_t>(predicate)].arg_types;
  std::size_t flat = 0;
  for (std::size_t i = 0; i < types.size(); ++i)
    flat = flat * constants_of(types[i], o.constants) + static_cast<std::size_t>(args[i]);
  return o.values[static_cast<std::size_t>(predicate)][flat];
}

bool SemanticsCore::holds(const Outcome& o, const Condition& c, std::span<const std::int32_t> binding) const {
  std::array<std::int32_t, 8> small{};
  std::vector<std::int32_t> large;
  std::span<std::int32_t> args;
  if (c.vars.size() <= small.size()) {
    args = std::span<std::int32_t>(small.data(), c.vars.size());
  } else {
    large.resize(c.vars.size());
    args = large;
  }
  for (std::size_t i = 0; i < c.vars.size(); ++i) args[i] = binding[static_cast<std::size_t>(c.vars[i])];
  const double v = value(o, c.predicate, args);
  bool ok = v > 0.5;
  if (c.probability) {
    switch (c.cmp) {
      case Cmp::gt: ok = v > c.threshold; break;
      case Cmp::ge: ok = v >= c.threshold; break;
      case Cmp::lt: ok = v < c.threshold; break;
      case Cmp::le: ok = v <= c.threshold; break;
    }
  }
  return c.negated ? !ok : ok;
}

const std::string& SemanticsCore::constant_name(std::int32_t type, std::int32_t index,
                                                const std::vector<std::string>& names) const {
  const auto fixed = static_cast<std::int32_t>(constants_of(type, 0));
  if (index < fixed) return base_domain_.constants(type)[static_cast<std::size_t>(index)];
  return names.at(static_cast<std::size_t>(index - fixed));
}

void SemanticsCore::check_names(const Outcome& o, const std::vector<std::string>& names) const {
  if (names.size() != o.constants)
    throw std::invalid_argument("semantics: " + std::to_string(names.size()) + " names for " +
                                std::to_string(o.constants) + " run-time constants");
}

nlohmann::ordered_json SemanticsCore::queries_json(const Outcome& o, const std::vector<std::string>& names) const {
  check_names(o, names);
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const std::int32_t q : queries_) {
    const mln::Predicate& pred = program_->predicates[static_cast<std::size_t>(q)];
    std::vector<std::int32_t> radix;
    for (const std::int32_t t : pred.arg_types) radix.push_back(static_cast<std::int32_t>(constants_of(t, o.constants)));
    nlohmann::ordered_json atoms = nlohmann::ordered_json::object();
    const auto& v = o.values[static_cast<std::size_t>(q)];
    for_each_tuple(radix, [&](std::size_t flat, const std::vector<std::int32_t>& args) {
      std::string key;
      for (std::size_t i = 0; i < args.size(); ++i) {
        if (i) key += ',';
        key += constant_name(pred.arg_types[i], args[i], names);
      }
      atoms[key] = round6(v[flat]);
    });
    out[pred.name] = std::move(atoms);
  }
  return out;
}

std::string SemanticsCore::evidence_db(const Outcome& o, const std::vector<std::string>& names) const {
  check_names(o, names);
  std::string db = "// evidence of " + std::to_string(o.constants) + " run-time constants (closed world)\n";
  for (std::size_t p = 0; p < program_->predicates.size(); ++p) {
    const mln::Predicate& pred = program_->predicates[p];
    if (pred.query) continue;
    std::vector<std::int32_t> radix;
    for (const std::int32_t t : pred.arg_types) radix.push_back(static_cast<std::int32_t>(constants_of(t, o.constants)));
    const auto& v = o.values[p];
    for_each_tuple(radix, [&](std::size_t flat, const std::vector<std::int32_t>& args) {
      if (v[flat] <= 0.5) db += '!';
      db += pred.name;
      db += '(';
      for (std::size_t i = 0; i < args.size(); ++i) {
        if (i) db += ',';
        db += constant_name(pred.arg_types[i], args[i], names);
      }
      db += ")\n";
    });
  }
  return db;
}

}  // namespace ksmc::runtime::domain
