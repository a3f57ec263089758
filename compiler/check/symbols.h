// The symbol table of a program: every declared name, in ordered maps so that iteration
// (and thus diagnostics and any output derived from it) is deterministic.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "compiler/ast/ast.h"

namespace ksmc::compiler::check {

struct TypeSym {
  enum class Kind { Domain, Value, Quantity };
  Kind kind = Kind::Domain;
  ast::Loc loc;
  int module = 0;
  const ast::TypeDecl* domain = nullptr;       // Domain
  const ast::QuantityDecl* quantity = nullptr; // Quantity
};

struct PredicateSym {
  const ast::PredSig* decl = nullptr;
  bool query = false;
  int module = 0;
};

struct UnitSym {
  std::string quantity;
  double scale = 1.0;
  ast::Loc loc;
};

struct ConstantSym {
  std::string type;
  ast::Loc loc;
};

struct ExternSym {
  const ast::ExternDecl* decl = nullptr;
  int module = 0;
};

struct ModelVarSym {
  const ast::ModelVar* decl = nullptr;
  // Type of the index: the declared index type, or for a variable-size collection the
  // domain type of the same name (its elements are that type's constants), else empty.
  std::string element_type;
  int module = 0;
};

struct KernelSym {
  const ast::KernelDecl* decl = nullptr;
  ast::Ident name;
  std::optional<ast::Ident> reverse;
  int module = 0;
};

// Kinds of `extern` declarations and the place where each may be called.
inline const std::vector<std::string>& extern_kinds() {
  static const std::vector<std::string> kinds{"extractor", "prior", "likelihood", "proposal", "function", "output"};
  return kinds;
}

struct SymbolTable {
  std::map<std::string, TypeSym> types;  // domain types, value types, quantities
  std::map<std::string, PredicateSym> predicates;
  std::map<std::string, UnitSym> units;
  std::map<std::string, ConstantSym> constants;
  std::map<std::string, ExternSym> externs;
  std::map<std::string, ModelVarSym> model_vars;
  std::map<std::string, KernelSym> kernels;  // both directions of a pair
  std::vector<const ast::ScheduleDecl*> schedules;
  // `extern model(...)` declarations with the module declaring each.
  std::vector<std::pair<const ast::ModelContractDecl*, int>> model_contracts;
  std::string domain;
  // Name of every rule of the main module (RuleNamesPass).
  std::map<const ast::Rule*, std::string> rule_names;

  [[nodiscard]] const PredicateSym* predicate(const std::string& n) const {
    auto it = predicates.find(n);
    return it == predicates.end() ? nullptr : &it->second;
  }
  [[nodiscard]] const TypeSym* type(const std::string& n) const {
    auto it = types.find(n);
    return it == types.end() ? nullptr : &it->second;
  }
  [[nodiscard]] bool is_domain_type(const std::string& n) const {
    const TypeSym* t = type(n);
    return t != nullptr && t->kind == TypeSym::Kind::Domain;
  }
};

}  // namespace ksmc::compiler::check
