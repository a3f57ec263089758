// Conversion of a rule's formula to clausal form (conjunctive normal form).
//
// Implications and equivalences are rewritten, negations pushed to the atoms (negation
// normal form), `!exists x: F` becomes a universally quantified `!F`, and disjunctions are
// distributed over conjunctions. An `exists` in positive position survives as existential
// variables of the clause it ends up in; the grounder expands it into a disjunction over
// the variable's domain. An existential whose body needs more than one clause cannot be
// expanded that way and is reported.
#pragma once

#include <string>
#include <vector>

#include "compiler/ast/ast.h"

namespace ksmc::compiler::lower {

struct CnfLiteral {
  const ast::Atom* atom = nullptr;
  bool negated = false;
  // Per argument: the variable name after renaming (existentials and variables of a
  // negated existential get fresh names), or the constant's name.
  std::vector<std::string> args;
};

struct CnfClause {
  std::vector<CnfLiteral> literals;
  std::vector<std::string> existential;  // names of existential variables used in this clause
};

struct CnfResult {
  std::vector<CnfClause> clauses;
  std::string error;  // non-empty: the formula cannot be lowered (message for the user)
  ast::Loc error_loc;
};

// `is_constant(name)` tells constants of enumerated types from variables.
template <class IsConstant>
CnfResult to_cnf(const ast::Formula& f, const IsConstant& is_constant);

// Non-template entry used by the implementation.
CnfResult to_cnf_impl(const ast::Formula& f, const std::vector<std::string>& constants);

template <class IsConstant>
CnfResult to_cnf(const ast::Formula& f, const IsConstant& is_constant) {
  // Collect constant names appearing in the formula so the implementation stays non-generic.
  std::vector<std::string> constants;
  std::vector<const ast::Formula*> stack{&f};
  while (!stack.empty()) {
    const ast::Formula* g = stack.back();
    stack.pop_back();
    if (g->kind == ast::Formula::Kind::Atom) {
      for (const auto& a : g->atom.args)
        if (is_constant(a.name)) constants.push_back(a.name);
    }
    for (const auto& c : g->children) stack.push_back(&c);
  }
  return to_cnf_impl(f, constants);
}

}  // namespace ksmc::compiler::lower
