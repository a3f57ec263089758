// Variable scopes of a module: each rule, extract declaration, prior and kernel is one
// scope. Atom arguments that name a declared constant are constants; all others are
// variables, universally quantified over the scope unless bound by `exists` (rules) or
// `for` (priors). Variable types are inferred from the predicate argument types.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "compiler/ast/ast.h"
#include "compiler/check/symbols.h"

namespace ksmc::compiler::check {

struct Scope {
  enum class Kind { Rule, Extract, Prior, Kernel, Output };
  Kind kind = Kind::Rule;
  const ast::Item* item = nullptr;
  std::vector<const ast::Atom*> atoms;    // every atom, in source order
  std::vector<const ast::Ident*> binders; // `exists` / `for` variables
  std::vector<const ast::Call*> calls;    // top-level calls (extractor, prior, kernel sources)
  std::map<std::string, std::string> declared;  // kernel parameters: name -> type
};

std::vector<Scope> collect_scopes(const ast::Module& m);

struct VarType {
  std::string type;  // empty when unknown (undeclared predicate)
  ast::Loc loc;      // first typed occurrence
};

// Infers the variable types of a scope. `conflict(var, first, second_type, second_loc)` is
// called for each occurrence that disagrees with the first typed one.
using ConflictFn = std::function<void(const std::string& var, const VarType& first, const std::string& type,
                                      const ast::Loc& loc)>;
std::map<std::string, VarType> infer_variable_types(const Scope& scope, const SymbolTable& symbols,
                                                    const ConflictFn& conflict = {});

// Visits every atom of a formula (iteratively bounded by the builder's depth limit).
void for_each_atom(const ast::Formula& f, const std::function<void(const ast::Atom&)>& fn);

}  // namespace ksmc::compiler::check
