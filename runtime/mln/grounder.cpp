#include "runtime/mln/grounder.h"

#include <algorithm>

#include "runtime/io/cancel.h"
#include "runtime/mln/error.h"
#include "runtime/mln/forced_atoms.h"
#include "runtime/mln/ground_bound.h"

namespace ksmc::runtime::mln {
namespace {

// A literal with its arguments resolved: variable index (>= 0) or constant -(c+1).
struct ResolvedLiteral {
  std::int32_t predicate;
  bool negated;
  std::vector<std::int32_t> arg;
  std::vector<std::int64_t> stride;
  std::vector<std::int32_t> exist_vars;  // existential variables used by this literal
};

std::string binding_text(const Clause& c, const Domain& domain, const std::vector<std::int32_t>& value) {
  std::string out;
  for (std::size_t v = 0; v < c.variables.size(); ++v) {
    if (c.variables[v].existential) continue;
    out += (out.empty() ? "" : ", ") + c.variables[v].name + "=" + domain.constants(c.variables[v].type)[value[v]];
  }
  return out;
}

class Grounder {
 public:
  Grounder(const Program& p, const Domain& d, const Evidence& e, Grounding& g)
      : program_(p), domain_(d), evidence_(e), g_(g) {}

  // Query index, exactly-one blocks and free atoms: everything but the clauses.
  void prepare() {
    program_.validate();
    check_ground_bound(program_, domain_, evidence_);
    index_query_atoms();
    fold_blocks();
    assign_atoms();
  }

  void run() {
    prepare();
    for (std::size_t c = 0; c < program_.clauses.size(); ++c) ground_clause(static_cast<std::int32_t>(c));
  }

 private:
  void index_query_atoms() {
    auto& ix = g_.index;
    const auto np = program_.predicates.size();
    ix.offset.assign(np, -1);
    g_.radix.resize(np);
    for (std::size_t p = 0; p < np; ++p) {
      g_.radix[p] = evidence_.radix(static_cast<std::int32_t>(p));
      if (!program_.predicates[p].query) continue;
      ix.offset[p] = ix.num_query_atoms;
      ix.num_query_atoms += evidence_.num_atoms(static_cast<std::int32_t>(p));
    }
    ix.fixed.assign(static_cast<std::size_t>(ix.num_query_atoms), Evidence::kUnknown);
    for (std::size_t p = 0; p < np; ++p) {
      if (ix.offset[p] < 0) continue;
      const auto n = evidence_.num_atoms(static_cast<std::int32_t>(p));
      for (std::int64_t f = 0; f < n; ++f)
        ix.fixed[ix.offset[p] + f] = evidence_.get_flat(static_cast<std::int32_t>(p), f);
    }
  }

  // Value of p at flat index: 0/1 if known (evidence closed world or fixed query atom), -1 if free.
  std::int8_t known(std::int32_t p, std::int64_t flat) const {
    const auto off = g_.index.offset[p];
    if (off < 0) return evidence_.get_flat(p, flat) == 1 ? 1 : 0;
    return g_.index.fixed[off + flat];
  }

  void fold_block(const std::vector<std::pair<std::int32_t, std::int64_t>>& members, const std::string& what) {
    int on = 0;
    std::vector<std::int64_t> free_q;
    for (const auto& [p, flat] : members) {
      const auto v = known(p, flat);
      if (v == 1) ++on;
      else if (v < 0) free_q.push_back(g_.index.offset[p] + flat);
    }
    if (on > 1) throw MlnError(what + ": the evidence makes more than one atom true");
    if (on == 1) {
      for (auto q : free_q) g_.index.fixed[q] = 0;
      return;
    }
    if (free_q.empty()) throw MlnError(what + ": the evidence makes every atom false");
    if (free_q.size() == 1) {
      g_.index.fixed[free_q[0]] = 1;
      return;
    }
    blocks_.push_back(free_q);
  }

  std::string member_list(const std::vector<std::pair<std::int32_t, std::int64_t>>& members) const {
    std::string out;
    for (const auto& [p, flat] : members) out += (out.empty() ? "" : ", ") + ground_name(p, flat);
    return out;
  }

  void fold_blocks() {
    std::vector<std::pair<std::int32_t, std::int64_t>> members;
    for (const auto& grp : program_.groups) {
      const auto p0 = grp.predicates[0];
      const auto n = evidence_.num_atoms(p0);
      for (std::int64_t f = 0; f < n; ++f) {
        members.clear();
        for (auto p : grp.predicates) members.emplace_back(p, f);
        fold_block(members, grp.loc.str() + ": exactly-one group `" + grp.text + "` over " + member_list(members));
      }
    }
    for (std::size_t pi = 0; pi < program_.predicates.size(); ++pi) {
      const auto& p = program_.predicates[pi];
      if (p.exclusive_arg < 0) continue;
      const auto p32 = static_cast<std::int32_t>(pi);
      const auto& r = evidence_.radix(p32);
      std::int64_t inner = 1;
      for (std::size_t i = static_cast<std::size_t>(p.exclusive_arg) + 1; i < r.size(); ++i) inner *= r[i];
      const std::int64_t k = r[p.exclusive_arg];
      const std::int64_t n = evidence_.num_atoms(p32);
      for (std::int64_t f = 0; f < n; ++f) {
        if ((f / inner) % k != 0) continue;  // one block per binding of the other arguments
        members.clear();
        for (std::int64_t v = 0; v < k; ++v) members.emplace_back(p32, f + v * inner);
        fold_block(members, "exclusive argument of '" + p.name + "' over " + member_list(members));
      }
    }
  }

  void assign_atoms() {
    auto& ix = g_.index;
    auto& net = g_.network;
    ix.atom.assign(static_cast<std::size_t>(ix.num_query_atoms), -1);
    std::vector<std::string> labels;
    for (const auto& p : program_.predicates) labels.push_back(p.name);
    net.set_label_names(std::move(labels));
    std::vector<std::string> origins;
    for (const auto& c : program_.clauses) origins.push_back(c.describe());
    net.set_origin_names(std::move(origins));
    for (std::size_t p = 0; p < program_.predicates.size(); ++p) {
      if (ix.offset[p] < 0) continue;
      const auto n = evidence_.num_atoms(static_cast<std::int32_t>(p));
      for (std::int64_t f = 0; f < n; ++f) {
        const auto q = ix.offset[p] + f;
        if (ix.fixed[q] >= 0) continue;
        ix.atom[q] = net.add_atom(static_cast<std::int32_t>(p));
        ix.query_of_atom.push_back(q);
      }
    }
    std::vector<AtomId> atoms;
    for (const auto& b : blocks_) {
      atoms.clear();
      for (auto q : b) atoms.push_back(ix.atom[q]);
      net.add_exactly_one(atoms);
    }
  }

  std::string ground_name(std::int32_t p, std::int64_t flat) const {
    const auto& pred = program_.predicates[p];
    const auto& r = evidence_.radix(p);
    std::vector<std::int32_t> args(r.size());
    for (std::size_t i = r.size(); i-- > 0;) {
      args[i] = static_cast<std::int32_t>(flat % r[i]);
      flat /= r[i];
    }
    std::string out = pred.name + "(";
    for (std::size_t i = 0; i < args.size(); ++i)
      out += (i ? "," : "") + domain_.constants(pred.arg_types[i])[args[i]];
    return out + ")";
  }

  void ground_clause(std::int32_t ci) {
    const Clause& c = program_.clauses[ci];
    const auto nv = c.variables.size();
    std::vector<ResolvedLiteral> lits;
    for (const auto& l : c.literals) {
      ResolvedLiteral rl{l.predicate, l.negated, {}, {}, {}};
      const auto& r = evidence_.radix(l.predicate);
      rl.stride.assign(r.size(), 1);
      for (std::size_t i = r.size(); i-- > 1;) rl.stride[i - 1] = rl.stride[i] * r[i];
      for (std::size_t i = 0; i < l.args.size(); ++i) {
        const auto& t = l.args[i];
        if (t.is_variable) {
          rl.arg.push_back(t.variable);
          if (c.variables[t.variable].existential &&
              std::find(rl.exist_vars.begin(), rl.exist_vars.end(), t.variable) == rl.exist_vars.end())
            rl.exist_vars.push_back(t.variable);
        } else {
          const auto type = program_.predicates[l.predicate].arg_types[i];
          const auto k = domain_.find(type, t.constant);
          if (!k) {
            throw MlnError(c.describe() + ": constant '" + t.constant + "' is not in the domain of type '" +
                           program_.types[type] + "'");
          }
          rl.arg.push_back(-(*k + 1));
        }
      }
      lits.push_back(std::move(rl));
    }
    std::vector<std::int32_t> universal;
    for (std::size_t v = 0; v < nv; ++v)
      if (!c.variables[v].existential) universal.push_back(static_cast<std::int32_t>(v));
    for (std::size_t v = 0; v < nv; ++v)
      if (domain_.size(c.variables[v].type) == 0 && !c.variables[v].existential) return;  // no groundings

    std::vector<std::int32_t> value(nv, 0);
    std::vector<Lit> out;
    auto size_of = [&](std::int32_t v) { return domain_.size(c.variables[v].type); };
    std::uint32_t polls = 0;
    while (true) {
      if ((++polls & 0xFFFF) == 0) io::throw_if_cancelled("grounding");
      out.clear();
      bool satisfied = false;
      for (const auto& rl : lits) {
        // Iterate the existential variables of this literal (none: a single grounding).
        for (auto v : rl.exist_vars) value[v] = 0;
        bool empty_exist = false;
        for (auto v : rl.exist_vars) empty_exist = empty_exist || size_of(v) == 0;
        while (!empty_exist) {
          std::int64_t flat = 0;
          for (std::size_t i = 0; i < rl.arg.size(); ++i) {
            const auto a = rl.arg[i];
            flat += rl.stride[i] * (a >= 0 ? value[a] : -a - 1);
          }
          const auto k = known(rl.predicate, flat);
          if (k >= 0) {
            if ((k == 1) != rl.negated) { satisfied = true; break; }
          } else {
            out.push_back(make_lit(g_.index.atom[g_.index.offset[rl.predicate] + flat], rl.negated));
          }
          std::size_t j = 0;
          for (; j < rl.exist_vars.size(); ++j) {
            const auto v = rl.exist_vars[j];
            if (++value[v] < size_of(v)) break;
            value[v] = 0;
          }
          if (j == rl.exist_vars.size()) break;
        }
        if (satisfied) break;
      }
      if (satisfied) {
        if (!c.hard) g_.network.add_constant(c.weight);
      } else if (out.empty()) {
        if (c.hard) {
          throw MlnError("hard rule " + c.describe() + " is unsatisfiable under the evidence" +
                         (universal.empty() ? std::string() : " for " + binding_text(c, domain_, value)));
        }
      } else if (c.hard) {
        g_.network.add_hard_clause(out, ci);
      } else {
        g_.network.add_clause(out, c.weight, ci);
      }
      // Row-major order (last variable fastest), like nested loops in generated code.
      std::size_t j = universal.size();
      for (; j > 0; --j) {
        const auto v = universal[j - 1];
        if (++value[v] < size_of(v)) break;
        value[v] = 0;
      }
      if (j == 0) break;
    }
  }

  const Program& program_;
  const Domain& domain_;
  const Evidence& evidence_;
  Grounding& g_;
  std::vector<std::vector<std::int64_t>> blocks_;
};

}  // namespace

std::int64_t Grounding::query_index(std::int32_t predicate, std::span<const std::int32_t> args) const {
  const auto off = index.offset.at(static_cast<std::size_t>(predicate));
  if (off < 0) throw MlnError("'" + program->predicates[predicate].name + "' is not a query predicate");
  const auto& r = radix[predicate];
  std::int64_t flat = 0;
  for (std::size_t i = 0; i < r.size(); ++i) flat = flat * r[i] + args[i];
  return off + flat;
}

double Grounding::marginal(const InferenceResult& result, std::int64_t q) const {
  const auto a = index.atom[q];
  if (a < 0) return index.fixed[q] == 1 ? 1.0 : 0.0;
  return result.marginals[a];
}

std::string Grounding::atom_name(std::int64_t q) const {
  std::int32_t p = -1;
  for (std::size_t i = 0; i < index.offset.size() && p < 0; ++i) {
    std::int64_t n = 1;
    for (auto k : radix[i]) n *= k;
    if (index.offset[i] >= 0 && index.offset[i] <= q && q < index.offset[i] + n) p = static_cast<std::int32_t>(i);
  }
  if (p < 0) throw MlnError("query atom index " + std::to_string(q) + " out of range");
  const auto& pred = program->predicates[p];
  std::int64_t flat = q - index.offset[p];
  const auto& r = radix[p];
  std::vector<std::int32_t> args(r.size());
  for (std::size_t i = r.size(); i-- > 0;) {
    args[i] = static_cast<std::int32_t>(flat % r[i]);
    flat /= r[i];
  }
  std::string out = pred.name + "(";
  for (std::size_t i = 0; i < args.size(); ++i) out += (i ? "," : "") + domain->constants(pred.arg_types[i])[args[i]];
  return out + ")";
}

Grounding ground(const Program& program, const Domain& domain, const Evidence& evidence) {
  Grounding g;
  g.program = &program;
  g.domain = &domain;
  Grounder(program, domain, evidence, g).run();
  fold_forced_atoms(g);
  return g;
}

Grounding prepare_grounding(const Program& program, const Domain& domain, const Evidence& evidence) {
  Grounding g;
  g.program = &program;
  g.domain = &domain;
  Grounder(program, domain, evidence, g).prepare();
  return g;
}

}  // namespace ksmc::runtime::mln
