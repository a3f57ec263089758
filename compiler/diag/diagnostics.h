// The diagnostics engine: collects located errors and warnings, then prints them sorted by
// location and de-duplicated as
//   path:line:col: error: message
//   <source line>
//   <caret under the column>
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "compiler/ast/ast.h"
#include "compiler/diag/source_manager.h"

namespace ksmc::compiler::diag {

enum class Severity { Warning, Error };

struct Diagnostic {
  Severity severity = Severity::Error;
  ast::Loc loc;  // file < 0: no location ("ksmc: error: ..."); line 0: whole file ("path: error: ...")
  std::string message;
};

class DiagEngine {
 public:
  explicit DiagEngine(const SourceManager& sources) : sources_(sources) {}

  void error(const ast::Loc& loc, std::string message);
  void warning(const ast::Loc& loc, std::string message);

  [[nodiscard]] bool has_errors() const { return errors_ > 0; }
  [[nodiscard]] int error_count() const { return errors_; }
  [[nodiscard]] int warning_count() const { return warnings_; }
  // Too many errors from one file: the parser stops reporting after this many.
  [[nodiscard]] int errors_in(int file) const;
  [[nodiscard]] const std::vector<Diagnostic>& all() const { return diags_; }

  // Prints everything collected so far (sorted, de-duplicated) and clears the list.
  void flush(std::ostream& out);

 private:
  void add(Severity s, const ast::Loc& loc, std::string message);
  const SourceManager& sources_;
  std::vector<Diagnostic> diags_;
  int errors_ = 0;
  int warnings_ = 0;
};

// A source line made printable: control characters become '?' (tabs are kept so that the
// caret line, which copies tabs, stays aligned).
std::string printable_line(std::string_view line);

}  // namespace ksmc::compiler::diag
