// `ksmc import-mln FILE.mln`: translates an Alchemy / pracmln rule base into a .ksm domain
// file that `ksmc infer`, `ksmc check` and the rest of the tool chain read.
//
// Supported: predicate declarations (`Smokes(person)`, `p(x, t!)`), type declarations
// with named constants (`person = {Anna, Bob}`), a weight before a formula (soft), a
// formula ending in a period (hard), a formula with neither (weight to be learned:
// written as `w 0`), the connectives `! ^ v => <=>`, `EXIST x, y F`, parentheses, `//`
// and `/* */` comments, lowercase variables and capitalised constants.
// Anything else (`#include`, functions, `FORALL`, `=`, `+x` / `*` operators, numeric or
// string constants, integer-range types, a weight on a hard formula) is a located error
// naming the construct. Which predicates are query predicates is Alchemy's run-time `-q`
// choice: give it as `--query P,Q` (the others become closed-world evidence); without
// it every predicate is a query predicate (open world, evidence may still fix atoms).
//
// Weights: ksmc splits a formula's weight equally over its CNF clauses, as Alchemy does
// (docs/mln.md, "Weight semantics"). With `per_formula` (pracmln's semantics: the weight
// counts once when the whole formula holds), a soft formula of several CNF clauses is
// written as an auxiliary query predicate equivalent to it, carrying the weight:
//   query holds_1(person);  hard holds_1(x) <=> (F).  w 1.5: holds_1(x).
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace ksmc::compiler::alchemy {

struct ImportResult {
  std::string ksm;                   // the .ksm text (empty on errors)
  std::vector<std::string> errors;   // "FILE:line:col: error: message"
};

// `path` names the file in messages and gives the domain name (its stem).
ImportResult import_mln(const std::string& text, const std::string& path, const std::vector<std::string>& queries,
                        bool per_formula = false);

// The command: reads `path`, writes the .ksm to `out_path` (stdout when empty).
// Returns 0, 1 on errors in the file (all reported), 2 on bad usage.
int run_import(const std::vector<std::string>& files, const std::vector<std::string>& queries,
               const std::string& out_path, std::ostream& out, std::ostream& err, bool per_formula = false);

}  // namespace ksmc::compiler::alchemy
