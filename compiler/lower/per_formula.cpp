#include "compiler/lower/per_formula.h"

#include <cstdint>
#include <limits>
#include <vector>

namespace ksmc::compiler::lower {
namespace {

namespace mln = ksmc::runtime::mln;

constexpr std::size_t kMaxChoiceClauses = 256;

// The formula's universal variables, in order of first appearance over its clauses.
std::vector<mln::Variable> universal_variables(const mln::Program& p, const std::vector<int>& clauses) {
  std::vector<mln::Variable> out;
  for (int c : clauses)
    for (const auto& v : p.clauses[static_cast<std::size_t>(c)].variables) {
      bool seen = false;
      for (const auto& u : out) seen = seen || u.name == v.name;
      if (!seen) out.push_back(v);
    }
  return out;
}

// Index of variable `v` in clause `c`, added as a universal variable when absent.
std::int32_t variable_in(mln::Clause& c, const mln::Variable& v) {
  for (std::size_t i = 0; i < c.variables.size(); ++i)
    if (c.variables[i].name == v.name) return static_cast<std::int32_t>(i);
  c.variables.push_back(v);
  return static_cast<std::int32_t>(c.variables.size() - 1);
}

// The literal holds[F](v) over clause `c`'s variables.
mln::Literal holds_literal(mln::Clause& c, std::int32_t predicate, const std::vector<mln::Variable>& vars, bool negated) {
  mln::Literal l;
  l.predicate = predicate;
  l.negated = negated;
  for (const auto& v : vars) l.args.push_back(mln::Term::var(variable_in(c, v)));
  return l;
}

// Literal `l` of clause `from`, negated, with its variables renamed into clause `to`.
mln::Literal negated_copy(const mln::Literal& l, const mln::Clause& from, mln::Clause& to) {
  mln::Literal out = l;
  out.negated = !l.negated;
  for (auto& t : out.args)
    if (t.is_variable) t.variable = variable_in(to, from.variables[static_cast<std::size_t>(t.variable)]);
  return out;
}

std::string where(const RuleIr& r) { return r.file + ":" + std::to_string(r.line) + ": error: rule " + r.name; }

}  // namespace

std::string use_per_formula_weights(MlnIr& ir) {
  auto& program = ir.program;
  for (auto& rule : ir.rules) {
    if (rule.kind == RuleIr::WeightKind::Hard || rule.group >= 0 || rule.clauses.size() < 2) continue;
    std::size_t choices = 1;
    for (int c : rule.clauses) {
      const auto& clause = program.clauses[static_cast<std::size_t>(c)];
      for (const auto& v : clause.variables)
        if (v.existential)
          return where(rule) + ": per-formula weights need a formula without `exists` when its CNF has several "
                               "clauses (this one has " + std::to_string(rule.clauses.size()) + ")";
      choices *= clause.literals.size();
      if (choices > kMaxChoiceClauses)
        return where(rule) + ": per-formula weights: the formula's negation has more than " +
               std::to_string(kMaxChoiceClauses) + " clauses; split the formula into rules of one clause each";
    }
    const auto vars = universal_variables(program, rule.clauses);
    mln::Predicate holds;
    holds.name = "holds[" + rule.name + "]";
    holds.query = true;
    holds.auxiliary = true;
    for (const auto& v : vars) holds.arg_types.push_back(v.type);
    const std::int32_t pred = program.add_predicate(std::move(holds));

    const std::vector<int> parts = rule.clauses;
    const mln::Clause first = program.clauses[static_cast<std::size_t>(parts.front())];
    // !holds v C_i: the formula's clauses become hard.
    for (int c : parts) {
      auto& clause = program.clauses[static_cast<std::size_t>(c)];
      clause.hard = true;
      clause.weight = std::numeric_limits<double>::infinity();
      clause.literals.push_back(holds_literal(clause, pred, vars, true));
    }
    // holds v !l_1j1 v ... v !l_kjk: every choice of one literal per clause (mixed radix).
    std::vector<std::size_t> pick(parts.size(), 0);
    for (std::size_t n = 0; n < choices; ++n) {
      mln::Clause c;
      c.name = rule.name + "_holds" + std::to_string(n + 1);
      c.hard = true;
      c.weight = std::numeric_limits<double>::infinity();
      c.text = first.text;
      c.loc = first.loc;
      for (std::size_t i = 0; i < parts.size(); ++i) {
        const auto& from = program.clauses[static_cast<std::size_t>(parts[i])];
        c.literals.push_back(negated_copy(from.literals[pick[i]], from, c));  // the holds literal is last: never picked
      }
      c.literals.push_back(holds_literal(c, pred, vars, false));
      program.add_clause(std::move(c));
      for (std::size_t i = 0; i < parts.size(); ++i) {
        const auto size = program.clauses[static_cast<std::size_t>(parts[i])].literals.size() - 1;
        if (++pick[i] < size) break;
        pick[i] = 0;
      }
    }
    // The formula's weight, once, on holds[F](v).
    mln::Clause soft;
    soft.name = rule.name + "_weight";
    soft.weight = rule.weight;
    soft.text = first.text;
    soft.loc = first.loc;
    soft.literals.push_back(holds_literal(soft, pred, vars, false));
    rule.clauses = {static_cast<int>(program.clauses.size())};
    program.add_clause(std::move(soft));
  }
  return {};
}

}  // namespace ksmc::compiler::lower
