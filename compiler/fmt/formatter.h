// `ksmc fmt`: the canonical layout of a module, comments kept.
//
// Layout: one declaration per line (model and schedule blocks one member per line, kernels
// with several sources one source per line), single spaces around operators, at most one
// blank line kept where the source had blank lines. Comments before a declaration stay
// before it, comments at the end of a declaration's last line stay there, comments inside
// a one-line declaration move above it. fmt is idempotent and parse(fmt(x)) == parse(x).
#pragma once

#include <string>

#include "compiler/ast/ast.h"

namespace ksmc::compiler::fmt {

std::string format_module(const ast::Module& m);

}  // namespace ksmc::compiler::fmt
