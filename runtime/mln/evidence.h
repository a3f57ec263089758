// Evidence: a value (unknown / false / true) per ground atom of every predicate,
// stored densely (flat index = mixed radix of the argument constant indices), and
// the Alchemy/pracmln `.db` reader that fills it.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/mln/program.h"

namespace ksmc::runtime::mln {

class Evidence {
 public:
  static constexpr std::int8_t kUnknown = -1;

  Evidence(const Program& program, const Domain& domain);

  // Flat index of p(args) (args = constant indices per argument).
  std::int64_t flat_index(std::int32_t predicate, std::span<const std::int32_t> args) const;
  std::int64_t num_atoms(std::int32_t predicate) const { return static_cast<std::int64_t>(values_[predicate].size()); }
  const std::vector<std::int32_t>& radix(std::int32_t predicate) const { return radix_[predicate]; }

  void set(std::int32_t predicate, std::span<const std::int32_t> args, bool value) {
    values_[predicate][flat_index(predicate, args)] = value ? 1 : 0;
  }
  void set_flat(std::int32_t predicate, std::int64_t flat, std::int8_t value) { values_[predicate][flat] = value; }
  std::int8_t get_flat(std::int32_t predicate, std::int64_t flat) const { return values_[predicate][flat]; }
  std::int8_t get(std::int32_t predicate, std::span<const std::int32_t> args) const {
    return values_[predicate][flat_index(predicate, args)];
  }
  // Resets every atom to unknown (keeps the shape).
  void clear();

 private:
  std::vector<std::vector<std::int8_t>> values_;
  std::vector<std::vector<std::int32_t>> radix_;
};

struct DbOptions {
  // Query atoms may be listed only for predicates with query_evidence_allowed.
  // When true, any query atom may be given.
  bool allow_all_query_evidence = false;
};

// Parses `.db` text (`contact(A,B)`, `!stable(C)`, one ground atom per line, `//`
// comments, blank lines) into `evidence`. Errors are MlnError "file:line: message".
// Constants must already be in `domain`; every type used by a predicate must have
// at least one constant.
void parse_db(std::string_view text, const std::string& filename, const Program& program,
              const Domain& domain, Evidence& evidence, const DbOptions& options = {});
// Adds every constant named in `.db` text to `domain` (Alchemy-style domains taken
// from the evidence); checks syntax, predicate names and arities on the way.
void collect_db_constants(std::string_view text, const std::string& filename, const Program& program,
                          Domain& domain);
// Whole-file checks of `.db` text that no single line can make (NUL bytes: a binary or
// UTF-16 file); an MlnError "file:line: ..." otherwise nothing.
void check_db_text(std::string_view text, const std::string& filename);
// Reads a whole file; a missing file is an MlnError naming it.
std::string read_text_file(const std::string& path);
// Reads the file and calls parse_db; a missing file is an MlnError naming it.
void read_db_file(const std::string& path, const Program& program, const Domain& domain,
                  Evidence& evidence, const DbOptions& options = {});

}  // namespace ksmc::runtime::mln
