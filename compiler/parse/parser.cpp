#include "compiler/parse/parser.h"

#include <antlr4-runtime.h>

#include "KsmLexer.h"
#include "KsmParser.h"
#include "compiler/parse/error_strategy.h"
#include "compiler/parse/prescan.h"

namespace ksmc::compiler::parse {

ParsedFile::ParsedFile() = default;
ParsedFile::~ParsedFile() {
  // The tree is owned by the parser; destroy in reverse construction order.
  parser.reset();
  tokens.reset();
  lexer.reset();
  input.reset();
}

std::unique_ptr<ParsedFile> parse_text(int file, const std::string& text, diag::DiagEngine& diags) {
  auto out = std::make_unique<ParsedFile>();
  out->file = file;
  if (!prescan(file, text, diags)) return out;

  out->input = std::make_unique<antlr4::ANTLRInputStream>(text);
  out->lexer = std::make_unique<ksmc_grammar::KsmLexer>(out->input.get());
  out->lexer->removeErrorListeners();  // ERRCHAR makes the lexer total; the parser reports it
  out->tokens = std::make_unique<antlr4::CommonTokenStream>(out->lexer.get());
  out->parser = std::make_unique<ksmc_grammar::KsmParser>(out->tokens.get());
  out->parser->removeErrorListeners();

  // Two-stage parsing: the fast SLL prediction mode with a bail-out strategy first; only
  // when that fails (a syntax error, or a rare SLL conflict) parse again with full LL and
  // the friendly error strategy, which then reports the errors.
  auto* interp = out->parser->getInterpreter<antlr4::atn::ParserATNSimulator>();
  interp->setPredictionMode(antlr4::atn::PredictionMode::SLL);
  out->parser->setErrorHandler(std::make_shared<antlr4::BailErrorStrategy>());
  const int before = diags.errors_in(file);
  try {
    out->tree = out->parser->file();
  } catch (const antlr4::ParseCancellationException&) {
    out->tree = nullptr;
  }
  if (out->tree == nullptr) {
    out->tokens->seek(0);
    out->parser->reset();
    interp->setPredictionMode(antlr4::atn::PredictionMode::LL);
    out->parser->setErrorHandler(std::make_shared<FriendlyErrorStrategy>(file, diags));
    try {
      out->tree = out->parser->file();
    } catch (const antlr4::ParseCancellationException&) {
      out->tree = nullptr;
    }
  }
  out->ok = out->tree != nullptr && diags.errors_in(file) == before;
  return out;
}

void clear_prediction_caches() {
  antlr4::ANTLRInputStream input(std::string{});
  ksmc_grammar::KsmLexer lexer(&input);
  antlr4::CommonTokenStream tokens(&lexer);
  ksmc_grammar::KsmParser parser(&tokens);
  auto* interp = parser.getInterpreter<antlr4::atn::ParserATNSimulator>();
  interp->clearDFA();
  interp->getSharedContextCache().clear();
  lexer.getInterpreter<antlr4::atn::LexerATNSimulator>()->clearDFA();
}

}  // namespace ksmc::compiler::parse
