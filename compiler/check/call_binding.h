// Binding of a call's arguments to the parameters of the `extern` it names: positional
// arguments first, then named ones, defaults filled in. Shared by the contract checks and the
// domain IR lowering, so both see the same value for every parameter.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "compiler/ast/ast.h"
#include "compiler/check/symbols.h"

namespace ksmc::compiler::check {

struct BoundArg {
  const ast::Param* param = nullptr;
  const ast::Expr* value = nullptr;  // nullptr: missing (the calls pass reported it)
  bool defaulted = false;            // the value is the parameter's default
};

// One entry per declared parameter, in signature order.
std::vector<BoundArg> bind_call(const ast::Call& call, const ast::ExternDecl& decl);

// The scale of `unit` to its quantity's base unit (1 for no or an unknown unit).
double unit_scale(const SymbolTable& symbols, const std::string& unit);

// A number in base units.
double base_value(const SymbolTable& symbols, const ast::Number& n);

// The domain type whose run-time constants the model's collections range over (the kit's
// constant type): the index type of `x[T]` or the same-named type of `x[]`; empty if none.
std::string constant_type(const ast::Module& main, const SymbolTable& symbols);

// The `extern model(...)` the domain must match: the one declared in the module that
// declares the domain's likelihood, else the only one; nullptr when there is none.
const ast::ModelContractDecl* model_contract(const ast::Program& program, const SymbolTable& symbols);

}  // namespace ksmc::compiler::check
