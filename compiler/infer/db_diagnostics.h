// Reading a `.db` evidence file for `ksmc infer` and `ksmc learn` so that every bad line
// is reported, not only the first: the runtime's parser runs one line at a time (its
// messages keep their `file:line:`), and unknown predicates and constants get a
// "did you mean" suggestion from the program's names.
#pragma once

#include <string>
#include <vector>

#include "runtime/mln/evidence.h"
#include "runtime/mln/program.h"

namespace ksmc::compiler::infer {

// " (did you mean 'X'?)" for the candidate closest to `word` (check::suggest); empty when
// none is close.
std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates);

// "E.db:3: message" becomes "E.db:3: error: message", like the compiler's diagnostics;
// a message not about `path` becomes "<tool>: error: message".
std::string with_error_tag(const std::string& message, const std::string& path, const std::string& tool);

// Adds the constants named on the good lines of `text` to `domain` (bad lines are left
// to parse_db_all, which reports them).
void collect_constants_lenient(const std::string& text, const std::string& path,
                               const runtime::mln::Program& program, runtime::mln::Domain& domain);

// Parses every atom line of `text` into `evidence`; returns the error messages
// ("file:line: message", in line order), empty when the file is clean.
std::vector<std::string> parse_db_all(const std::string& text, const std::string& path,
                                      const runtime::mln::Program& program, const runtime::mln::Domain& domain,
                                      runtime::mln::Evidence& evidence,
                                      const runtime::mln::DbOptions& options = {});

}  // namespace ksmc::compiler::infer
