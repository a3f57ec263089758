// `ksmc infer FILE --evidence E.db`: interpreted Markov logic inference, so a rule author
// can try a knowledge base without compiling a binary. The lowered program is grounded by
// the runtime's generic grounder over the constants of the evidence file and solved by the
// chosen engine; the output lists `pred(args) probability`, sorted, like Alchemy's
// `.result` files.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "compiler/lower/mln_ir.h"

namespace ksmc::compiler::infer {

struct InferRequest {
  std::string evidence_path;
  std::vector<std::string> queries;  // query predicate names; empty: all of them
  std::string method = "auto";       // exact | gibbs | mcsat | map | auto
  std::uint64_t seed = 1;
  std::int64_t burn_in = -1;         // < 0: the engine's default
  std::int64_t samples = -1;         // < 0: the engine's default; 0 is refused
  std::string result_path;           // --result FILE: also write Alchemy's .result format there
  std::int64_t max_ground_clauses = -1;  // < 0: runtime/mln/ground_bound.h's default
};

// A sample or burn-in count from the command line: digits only ("1k", "-3", "" throw
// std::invalid_argument).
std::int64_t parse_count(const std::string& text);

// Returns the process exit code: 0 on success, 1 on bad input (every bad evidence line is
// reported on `err`), 2 on a bad option. Atoms of query predicates may be given in the
// evidence (partial observation): they are fixed, the others inferred.
int run_infer(const lower::MlnIr& ir, const InferRequest& request, std::ostream& out, std::ostream& err);

// Builds the run-time domain of `ir` from evidence text: the enumerated types' constants,
// then every constant named in the file (`type = {A, B}` lines declare constants that
// appear in no atom). Throws runtime::mln::MlnError "file:line: ..." for constants of an
// enumerated type that it does not declare. Returns the text with declaration lines blanked.
std::string build_domain(const lower::MlnIr& ir, const std::string& text, const std::string& path,
                         runtime::mln::Domain& domain);

}  // namespace ksmc::compiler::infer
