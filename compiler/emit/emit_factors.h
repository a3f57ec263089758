// `ksmc emit`: generated C++ for the Markov logic part of a domain, `<domain>_factors.h`
// and `<domain>_factors.cpp`.
//
// The generated code includes the one runtime header, rebuilds the clause program (names,
// weights, source locations) and grounds every clause with its own specialised function:
// nested loops over the clause's variables, evidence literals tested at the shallowest loop
// that binds their variables (a satisfied soft clause adds its weight for every skipped
// grounding), query literals folded against fixed atoms. Each function carries the rule's
// text and file:line. Output depends only on the IR: byte-identical across runs, and a
// weight edit in the domain file changes one line (the rule's weight constant).
#pragma once

#include <string>

#include "compiler/lower/mln_ir.h"

namespace ksmc::compiler::emit {

struct GeneratedFile {
  std::string name;  // file name, e.g. "tabletop_factors.h"
  std::string text;
};

struct FactorsOutput {
  GeneratedFile header;
  GeneratedFile source;
};

FactorsOutput emit_factors(const lower::MlnIr& ir);

// A C++ identifier made from a domain-file name ("falseEst" stays, "a-b" becomes "a_b").
std::string cpp_identifier(const std::string& name);
// A C++ string literal with escapes.
std::string cpp_string(const std::string& s);

}  // namespace ksmc::compiler::emit
