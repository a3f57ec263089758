// Parse stage: pre-scan limits (bad input never crashes or hangs), friendly syntax errors,
// and the shape of the AST built from the CST.
#include <catch2/catch.hpp>

#include <chrono>
#include <string>

#include "tests/frontend/support.h"

using ksmc::tests::frontend::contains;
using ksmc::tests::frontend::parse_only;
namespace ast = ksmc::compiler::ast;

TEST_CASE("10 MB of nested parentheses gives one located error quickly", "[frontend][prescan]") {
  const std::string text = "hard " + std::string(10u << 20, '(');
  const auto t0 = std::chrono::steady_clock::now();
  const auto out = parse_only(text);
  const auto secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  REQUIRE_FALSE(out.loaded);
  REQUIRE(out.errors.size() == 1);
  CHECK(out.errors[0].rfind("1:262: nesting too deep", 0) == 0);
  CHECK(secs < 5.0);
}

TEST_CASE("deep negation and exists chains are refused before parsing", "[frontend][prescan]") {
  CHECK(contains(parse_only("hard " + std::string(100000, '!') + "p(x).").errors, "nesting too deep"));
  std::string ex = "hard ";
  for (int i = 0; i < 1000; ++i) ex += "exists x: ";
  CHECK(contains(parse_only(ex + "p(x).").errors, "nesting too deep"));
  // 200 levels are fine.
  const auto ok = parse_only("hard " + std::string(200, '(') + "p(x)" + std::string(200, ')') + ".");
  CHECK(ok.loaded);
  CHECK(ok.errors.empty());
}

TEST_CASE("long => chains are bounded by the builder", "[frontend][build]") {
  std::string chain = "hard p(x)";
  for (int i = 0; i < 5000; ++i) chain += " => p(x)";
  const auto out = parse_only(chain + ".");
  REQUIRE_FALSE(out.loaded);
  CHECK(contains(out.errors, "formula nested too deeply"));
  // Long ^ / v chains are flat (n-ary) and fine.
  std::string conj = "hard p(x)";
  for (int i = 0; i < 5000; ++i) conj += " ^ p(x)";
  const auto flat = parse_only(conj + ".");
  REQUIRE(flat.loaded);
  const auto& rule = std::get<ast::Rule>(flat.program.modules[0].items[0].node);
  CHECK(rule.formula.kind == ast::Formula::Kind::And);
  CHECK(rule.formula.children.size() == 5001);
}

TEST_CASE("encoding problems are located errors", "[frontend][prescan]") {
  auto bad = parse_only(std::string("type t;\n  \xff"));
  REQUIRE(bad.errors.size() == 1);
  CHECK(bad.errors[0] == "2:3: invalid UTF-8 byte 0xFF (source files must be UTF-8)");
  auto nul = parse_only(std::string("type t;\0", 8));
  REQUIRE(nul.errors.size() == 1);
  CHECK(nul.errors[0].find("NUL byte") != std::string::npos);
  // Overlong encodings and surrogates are invalid too.
  CHECK(contains(parse_only("type t; // \xc0\xaf").errors, "invalid UTF-8 byte 0xC0"));
  CHECK(contains(parse_only("type t; // \xed\xa0\x80").errors, "invalid UTF-8 byte 0xED"));
  // Valid multi-byte text in comments is fine.
  CHECK(parse_only("type t; // caf\xc3\xa9 \xe2\x82\xac").errors.empty());
}

TEST_CASE("oversized files are refused", "[frontend][prescan]") {
  std::string big;
  while (big.size() <= (8u << 20)) big += "type t;\n";
  const auto out = parse_only(big);
  REQUIRE(out.errors.size() == 1);
  CHECK(out.errors[0].find("file too large") != std::string::npos);
}

TEST_CASE("syntax errors are worded for people", "[frontend][parse]") {
  CHECK(parse_only("type object\nquery q(object);").errors ==
        std::vector<std::string>{"1:12: expected ';' after declaration, found 'query'"});
  CHECK(parse_only("type t;\nhard p(x)").errors ==
        std::vector<std::string>{"2:10: expected '.' at the end of the rule, found end of file"});
  CHECK(parse_only("type t; $").errors == std::vector<std::string>{"1:9: unexpected character '$'"});
  CHECK(parse_only("type t; @").errors == std::vector<std::string>{"1:10: unexpected end of file in rule name; expected a name"});
  CHECK(parse_only("type t;\n\"abc").errors == std::vector<std::string>{"2:1: unterminated string literal"});
  CHECK(parse_only("/* x").errors == std::vector<std::string>{"1:1: unterminated comment: '/*' without '*/'"});
  // One error per statement, however confused the parser gets.
  CHECK(parse_only("hard p(x) ^ ^ ^ ^ q(x).").errors.size() == 1);
}

TEST_CASE("the AST keeps operator structure, numbers and units", "[frontend][build]") {
  const auto out = parse_only(
      "hard a(x) => b(x) => c(x).\n"
      "hard a(x) <=> b(x) <=> c(x).\n"
      "w -1.5: exists y, z: !a(y) v b(z).\n"
      "extract p(o) = f.g(pose[o], eps = 4 mm, n = 3, r = 2.5e-1, s = \"q\\\"x\", l = [[1, 2]], t = {A, B}, on = true);\n");
  REQUIRE(out.loaded);
  const auto& items = out.program.modules[0].items;
  REQUIRE(items.size() == 4);
  const auto& imp = std::get<ast::Rule>(items[0].node).formula;
  REQUIRE(imp.kind == ast::Formula::Kind::Implies);
  CHECK(imp.children[0].kind == ast::Formula::Kind::Atom);
  CHECK(imp.children[1].kind == ast::Formula::Kind::Implies);  // right-assoc
  const auto& iff = std::get<ast::Rule>(items[1].node).formula;
  REQUIRE(iff.kind == ast::Formula::Kind::Iff);
  CHECK(iff.children[0].kind == ast::Formula::Kind::Iff);  // left-assoc
  const auto& r3 = std::get<ast::Rule>(items[2].node);
  REQUIRE(r3.weight);
  CHECK(r3.weight->value == -1.5);
  CHECK(r3.formula.kind == ast::Formula::Kind::Exists);
  CHECK(r3.formula.vars.size() == 2);
  CHECK(r3.formula.children[0].kind == ast::Formula::Kind::Or);
  CHECK(r3.source_text == "w -1.5: exists y, z: !a(y) v b(z).");
  const auto& ex = std::get<ast::ExtractDecl>(items[3].node);
  REQUIRE(ex.call.args.size() == 8);
  CHECK(ex.call.args[0].value.kind == ast::Expr::Kind::Index);
  CHECK(ex.call.args[1].value.number.unit == "mm");
  CHECK(ex.call.args[1].value.number.value == 4.0);
  CHECK(ex.call.args[2].value.number.integral);
  CHECK_FALSE(ex.call.args[3].value.number.integral);
  CHECK(ex.call.args[3].value.number.value == Approx(0.25));
  CHECK(ex.call.args[4].value.text == "q\"x");
  CHECK(ex.call.args[5].value.items[0].kind == ast::Expr::Kind::List);
  CHECK(ex.call.args[6].value.kind == ast::Expr::Kind::Set);
  CHECK(ex.call.args[7].value.kind == ast::Expr::Kind::Bool);
}
