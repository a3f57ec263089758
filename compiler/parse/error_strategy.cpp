#include "compiler/parse/error_strategy.h"

#include <cctype>
#include <cstdio>
#include <string>
#include <vector>

#include "KsmParser.h"
#include "compiler/diag/utf8.h"

namespace ksmc::compiler::parse {

namespace {

using P = ksmc_grammar::KsmParser;

// What the parser was reading, for messages such as "unexpected 'x' in formula".
std::string context_name(antlr4::ParserRuleContext* ctx) {
  if (ctx == nullptr) return "the file";
  switch (ctx->getRuleIndex()) {
    case P::RuleFile: return "the file";
    case P::RuleItem: return "declaration";
    case P::RuleExternKind: return "extern declaration";
    case P::RulePredSig:
    case P::RulePredArg: return "predicate declaration";
    case P::RuleUnitDef: return "unit definition";
    case P::RuleQualName: return "name";
    case P::RuleParam:
    case P::RuleParamRange:
    case P::RuleBound:
    case P::RuleRowSum: return "parameter declaration";
    case P::RuleTypeRef:
    case P::RuleDim: return "type";
    case P::RuleMoveSpec: return "extern declaration";
    case P::RuleModelSlot: return "model contract";
    case P::RuleRuleName: return "rule name";
    case P::RuleRuleHead: return "rule weight";
    case P::RuleRuleBody:
    case P::RuleFormula:
    case P::RuleImplication:
    case P::RuleDisjunction:
    case P::RuleConjunction:
    case P::RuleUnary: return "formula";
    case P::RuleAtom: return "atom";
    case P::RuleModelVar: return "model variable";
    case P::RulePriorForm:
    case P::RuleCondition: return "prior";
    case P::RuleKernelParams:
    case P::RuleKparam: return "kernel parameters";
    case P::RuleScheduleRow:
    case P::RuleRangeEnd:
    case P::RuleScheduleEntry: return "schedule";
    case P::RuleCall:
    case P::RuleArg: return "call";
    case P::RuleExpr: return "expression";
    case P::RuleNumber: return "number";
    default: return "input";
  }
}

std::string token_kind_name(antlr4::Parser* parser, std::size_t type) {
  if (type == antlr4::Token::EOF) return "end of file";
  switch (type) {
    case P::NUMBER: return "a number";
    case P::IDENT: return "a name";
    case P::STRING: return "a string";
    default: break;
  }
  const std::string lit = parser->getVocabulary().getLiteralName(type);
  return lit.empty() ? parser->getVocabulary().getDisplayName(type) : lit;
}

std::string describe(const antlr4::Token* t) {
  if (t == nullptr || t->getType() == antlr4::Token::EOF) return "end of file";
  std::string text = t->getText();
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return "'" + text + "'";
}

std::string expected_list(antlr4::Parser* parser, const antlr4::misc::IntervalSet& set) {
  std::vector<std::string> names;
  for (const ssize_t type : set.toList()) {
    if (type < 0) continue;  // epsilon
    names.push_back(token_kind_name(parser, static_cast<std::size_t>(type)));
  }
  if (names.empty() || names.size() > 6) return "";
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += (i + 1 == names.size()) ? " or " : ", ";
    out += names[i];
  }
  return out;
}

// Token type of a literal such as "';'" (looked up so that grammar edits cannot break it).
std::size_t literal_type(antlr4::Parser* parser, const std::string& literal) {
  const antlr4::dfa::Vocabulary& v = parser->getVocabulary();
  for (std::size_t i = 1; i <= v.getMaxTokenType(); ++i) {
    if (v.getLiteralName(i) == literal) return i;
  }
  return 0;
}

bool only(const antlr4::misc::IntervalSet& set, std::size_t type) {
  return type != 0 && set.size() == 1 && set.contains(type);
}

}  // namespace

ast::Loc FriendlyErrorStrategy::loc_of(const antlr4::Token* t) const {
  if (t == nullptr) return ast::Loc{file_, 1, 1, 0};
  return ast::Loc{file_, static_cast<int>(t->getLine()), static_cast<int>(t->getCharPositionInLine()) + 1,
                  t->getStartIndex()};
}

ast::Loc FriendlyErrorStrategy::loc_after(const antlr4::Token* t) const {
  ast::Loc loc = loc_of(t);
  if (t == nullptr || t->getType() == antlr4::Token::EOF) return loc;
  const std::string text = t->getText();
  if (text.find('\n') != std::string::npos) return loc;  // multi-line token: point at its start
  int cps = 0;
  for (std::size_t i = 0; i < text.size(); ++cps) {
    const std::size_t n = diag::utf8_sequence_length(text, i);
    i += n == 0 ? 1 : n;
  }
  loc.col += cps;
  return loc;
}

void FriendlyErrorStrategy::emit(const ast::Loc& loc, std::string message) {
  diags_.error(loc, std::move(message));
  if (diags_.errors_in(file_) >= max_errors_) {
    diags_.error(ast::Loc{file_, 0, 0, 0}, "too many syntax errors; giving up on this file");
    throw antlr4::ParseCancellationException("too many errors");
  }
}

bool FriendlyErrorStrategy::fresh_statement(antlr4::Parser* parser, const antlr4::Token* at) {
  const std::size_t here = at != nullptr ? at->getTokenIndex() : 0;
  const std::optional<std::size_t> last = last_error_token_;
  last_error_token_ = here;
  if (!last) return true;
  antlr4::TokenStream* ts = parser->getTokenStream();
  for (std::size_t i = *last; i < here && i < ts->size(); ++i) {
    const std::string text = ts->get(i)->getText();
    if (text == ";" || text == "." || text == "}") return true;
  }
  return false;
}

void FriendlyErrorStrategy::report_unexpected(antlr4::Parser* parser, antlr4::Token* t) {
  if (!fresh_statement(parser, t)) return;
  if (t != nullptr && t->getType() == P::ERRCHAR) {
    const std::string text = t->getText();
    const auto c = text.empty() ? 0U : static_cast<unsigned char>(text[0]);
    if (c < 0x20 || c == 0x7F) {
      char buf[16];
      std::snprintf(buf, sizeof buf, "U+%04X", c);
      emit(loc_of(t), std::string("unexpected character ") + buf);
    } else {
      emit(loc_of(t), "unexpected character '" + text + "'");
    }
    return;
  }
  antlr4::ParserRuleContext* ctx = parser->getContext();
  const antlr4::misc::IntervalSet expected = parser->getExpectedTokens();
  const std::string list = expected_list(parser, expected);
  if (ctx != nullptr && ctx->getRuleIndex() == P::RuleFile) {
    emit(loc_of(t), "expected a declaration, found " + describe(t));
    return;
  }
  // A missing terminator is reported right after the previous token: when it is the only
  // choice, or when it is one choice and the offending token starts a new line.
  const std::size_t semi_type = literal_type(parser, "';'");
  const std::size_t dot_type = literal_type(parser, "'.'");
  antlr4::Token* prev = parser->getTokenStream()->LT(-1);
  const bool new_line = t != nullptr && prev != nullptr && t->getLine() > prev->getLine();
  const bool want_semi = only(expected, semi_type) || (new_line && expected.contains(semi_type));
  const bool want_dot = only(expected, dot_type) || (new_line && expected.contains(dot_type));
  if (want_semi || want_dot) {
    const bool semi = want_semi;
    emit(loc_after(prev), semi ? "expected ';' after " + context_name(ctx) + ", found " + describe(t)
                               : "expected '.' at the end of the rule, found " + describe(t));
    return;
  }
  std::string msg = "unexpected " + describe(t) + " in " + context_name(ctx);
  if (!list.empty()) msg += "; expected " + list;
  // A keyword where a name was expected: say so.
  if (t != nullptr && expected.contains(static_cast<std::size_t>(P::IDENT))) {
    const std::string text = t->getText();
    const std::string lit = parser->getVocabulary().getLiteralName(t->getType());
    if (!text.empty() && std::isalpha(static_cast<unsigned char>(text[0])) != 0 && lit == "'" + text + "'") {
      msg += " ('" + text + "' is a reserved word)";
    }
  }
  emit(loc_of(t), std::move(msg));
}

void FriendlyErrorStrategy::reportNoViableAlternative(antlr4::Parser* parser, const antlr4::NoViableAltException& e) {
  report_unexpected(parser, e.getOffendingToken());
}

void FriendlyErrorStrategy::reportInputMismatch(antlr4::Parser* parser, const antlr4::InputMismatchException& e) {
  report_unexpected(parser, e.getOffendingToken());
}

void FriendlyErrorStrategy::reportFailedPredicate(antlr4::Parser* parser, const antlr4::FailedPredicateException& e) {
  report_unexpected(parser, e.getOffendingToken());
}

void FriendlyErrorStrategy::reportUnwantedToken(antlr4::Parser* parser) {
  if (inErrorRecoveryMode(parser)) return;
  beginErrorCondition(parser);
  report_unexpected(parser, parser->getCurrentToken());
}

void FriendlyErrorStrategy::reportMissingToken(antlr4::Parser* parser) {
  if (inErrorRecoveryMode(parser)) return;
  beginErrorCondition(parser);
  antlr4::Token* t = parser->getCurrentToken();
  if (!fresh_statement(parser, t)) return;
  const antlr4::misc::IntervalSet expected = getExpectedTokens(parser);
  antlr4::Token* prev = parser->getTokenStream()->LT(-1);
  const std::string what = expected_list(parser, expected);
  if (only(expected, literal_type(parser, "'.'"))) {
    emit(loc_after(prev), "expected '.' at the end of the rule, found " + describe(t));
  } else {
    if (only(expected, literal_type(parser, "';'"))) {
      emit(loc_after(prev), "expected ';' after " + context_name(parser->getContext()) + ", found " + describe(t));
    } else {
      emit(loc_of(t), "missing " + (what.empty() ? std::string("input") : what) + " before " + describe(t));
    }
  }
}

}  // namespace ksmc::compiler::parse
