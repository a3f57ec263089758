// An ANTLR error strategy that words syntax errors for people ("expected ';' after
// declaration", "unexpected 'foo' in formula") instead of ANTLR's token dumps, and reports
// them to the diagnostics engine with the location of the offending token (or, for a missing
// terminator, the place right after the previous token).
#pragma once

#include <antlr4-runtime.h>

#include <optional>

#include "compiler/diag/diagnostics.h"

namespace ksmc::compiler::parse {

class FriendlyErrorStrategy : public antlr4::DefaultErrorStrategy {
 public:
  FriendlyErrorStrategy(int file, diag::DiagEngine& diags, int max_errors = 20)
      : file_(file), diags_(diags), max_errors_(max_errors) {}

 protected:
  void reportNoViableAlternative(antlr4::Parser* parser, const antlr4::NoViableAltException& e) override;
  void reportInputMismatch(antlr4::Parser* parser, const antlr4::InputMismatchException& e) override;
  void reportFailedPredicate(antlr4::Parser* parser, const antlr4::FailedPredicateException& e) override;
  void reportUnwantedToken(antlr4::Parser* parser) override;
  void reportMissingToken(antlr4::Parser* parser) override;

 private:
  void report_unexpected(antlr4::Parser* parser, antlr4::Token* offending);
  void emit(const ast::Loc& loc, std::string message);
  // One error per statement: false when no statement end was passed since the last error.
  bool fresh_statement(antlr4::Parser* parser, const antlr4::Token* at);
  ast::Loc loc_of(const antlr4::Token* t) const;
  ast::Loc loc_after(const antlr4::Token* t) const;

  int file_;
  diag::DiagEngine& diags_;
  int max_errors_;
  std::optional<std::size_t> last_error_token_;
};

}  // namespace ksmc::compiler::parse
