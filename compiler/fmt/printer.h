// Canonical text of AST pieces (no comments): formulas with minimal parentheses, calls,
// expressions, numbers. Used by the formatter and by diagnostics that quote code.
#pragma once

#include <string>

#include "compiler/ast/ast.h"

namespace ksmc::compiler::fmt {

std::string print_number(const ast::Number& n);
std::string print_type(const ast::TypeRef& t);
std::string print_atom(const ast::Atom& a);
std::string print_expr(const ast::Expr& e);
std::string print_call(const ast::Call& c);
std::string print_formula(const ast::Formula& f);
std::string quote_string(const std::string& s);

}  // namespace ksmc::compiler::fmt
