// A stable, location-free text dump of a module's AST (`ksmc --dump-ast`): one
// S-expression per item. Two files have the same dump iff they have the same AST, which is
// how the fmt round-trip test compares parse(fmt(x)) with parse(x).
#pragma once

#include <ostream>

#include "compiler/ast/ast.h"

namespace ksmc::compiler::ast {

void dump(const Module& m, std::ostream& out);

}  // namespace ksmc::compiler::ast
