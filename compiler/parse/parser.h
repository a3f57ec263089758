// ANTLR wiring: runs the pre-scan, the generated lexer and parser, and routes syntax errors
// through the friendly error strategy (error_strategy.h) into the diagnostics engine.
#pragma once

#include <memory>
#include <string>

#include "compiler/diag/diagnostics.h"

namespace antlr4 {
class ANTLRInputStream;
class CommonTokenStream;
}  // namespace antlr4
namespace ksmc_grammar {
class KsmLexer;
class KsmParser;
}  // namespace ksmc_grammar

namespace ksmc::compiler::parse {

// Owns every ANTLR object the concrete syntax tree points into.
struct ParsedFile {
  ParsedFile();
  ~ParsedFile();
  ParsedFile(const ParsedFile&) = delete;
  ParsedFile& operator=(const ParsedFile&) = delete;

  int file = -1;
  std::unique_ptr<antlr4::ANTLRInputStream> input;
  std::unique_ptr<ksmc_grammar::KsmLexer> lexer;
  std::unique_ptr<antlr4::CommonTokenStream> tokens;
  std::unique_ptr<ksmc_grammar::KsmParser> parser;
  void* tree = nullptr;  // ksmc_grammar::KsmParser::FileContext*, owned by `parser`
  bool ok = false;       // no pre-scan or syntax error
};

// Parses the text of file `file` (registered in the SourceManager behind `diags`).
std::unique_ptr<ParsedFile> parse_text(int file, const std::string& text, diag::DiagEngine& diags);

// Drops ANTLR's process-wide prediction caches (lexer and parser DFA, shared prediction
// contexts). They only grow: every input that takes a new prediction path adds states, so
// a long-lived process parsing many distinct sources may call it now and then. (Under
// fuzzing the growth is ASan's, not this: docs/reliability.md.) Parsing stays correct
// afterwards; the caches refill. Not while another thread parses.
void clear_prediction_caches();

}  // namespace ksmc::compiler::parse
