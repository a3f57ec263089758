// Rule names: `@name` before a rule, or, unnamed, a name from its content: the predicates
// of its head (the consequent of a top-level implication, else the whole rule; at most
// three) and 4 hex digits of the FNV-1a hash of the rule's normalized formula text (the
// canonical `ksmc fmt` spelling, without the weight), e.g. `supportive_supported_3fa1`.
// A name therefore survives a weight edit, a reformat and the insertion of other rules.
// Two different unnamed formulas whose names collide both take all 8 hex digits.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "compiler/ast/ast.h"

namespace ksmc::compiler::check {

// The formula of a rule in canonical spelling, without weight and final period.
std::string normalized_rule_text(const ast::Rule& r);
// 32-bit FNV-1a.
std::uint32_t fnv1a(std::string_view text);
// `@name`, or the content-derived name; `long_hash` writes all 8 hex digits of the hash
// (used for two different formulas whose 4-digit names collide).
std::string rule_name(const ast::Rule& r, bool long_hash = false);

}  // namespace ksmc::compiler::check
