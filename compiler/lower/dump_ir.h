// `ksmc --dump-ir`: the lowered program as stable text (one line per type, predicate,
// group and clause; weights printed round-trip exact).
#pragma once

#include <ostream>
#include <string>
#include <string_view>

#include "compiler/lower/mln_ir.h"

namespace ksmc::compiler::lower {

void dump_ir(const MlnIr& ir, std::ostream& out);

// Shortest decimal spelling that reads back to the same double ("inf" for +inf).
std::string format_weight(double w);

// Source text on one line: runs of white space (newlines included) become one space.
std::string one_line(std::string_view text);

// `!contact(a, b) v hidden(o)` for a clause of the program.
std::string clause_text(const runtime::mln::Program& program, const runtime::mln::Clause& c);

}  // namespace ksmc::compiler::lower
