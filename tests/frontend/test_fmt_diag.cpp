// The diagnostics engine (format, order, de-duplication) and the formatter (comments kept,
// idempotent, AST preserved).
#include <catch2/catch.hpp>

#include <sstream>

#include "compiler/ast/dump.h"
#include "compiler/diag/diagnostics.h"
#include "compiler/fmt/formatter.h"
#include "tests/frontend/support.h"

namespace diag = ksmc::compiler::diag;
namespace ast = ksmc::compiler::ast;
using ksmc::tests::frontend::parse_only;

TEST_CASE("diagnostics are sorted, de-duplicated and show line and caret", "[frontend][diag]") {
  diag::SourceManager sources;
  const int f = sources.add("dir/x.ksm", "type t;\n\tquery caf\xc3\xa9(t) q;\n");
  diag::DiagEngine d(sources);
  d.warning(ast::Loc{f, 2, 17, 0}, "second");
  d.error(ast::Loc{f, 1, 6, 0}, "first");
  d.warning(ast::Loc{f, 2, 17, 0}, "second");
  d.error(ast::Loc{}, "no place");
  CHECK(d.error_count() == 2);
  std::ostringstream out;
  d.flush(out);
  CHECK(out.str() ==
        "ksmc: error: no place\n"
        "dir/x.ksm:1:6: error: first\n"
        "type t;\n"
        "     ^\n"
        "dir/x.ksm:2:17: warning: second\n"
        "\tquery caf\xc3\xa9(t) q;\n"
        "\t               ^\n");
}

TEST_CASE("source lines are printed safely", "[frontend][diag]") {
  CHECK(diag::printable_line("a\x01z\tq\x7f") == "a?z\tq?");
  CHECK(diag::printable_line("bad \xff byte") == "bad ? byte");
  CHECK(diag::printable_line("ok \xc3\xa9") == "ok \xc3\xa9");
}

namespace {
std::string dump_of(const std::string& text) {
  const auto out = parse_only(text);
  REQUIRE(out.loaded);
  std::ostringstream ss;
  ast::dump(out.program.modules[0], ss);
  return ss.str();
}
std::string fmt_of(const std::string& text) {
  const auto out = parse_only(text);
  REQUIRE(out.loaded);
  return ksmc::compiler::fmt::format_module(out.program.modules[0]);
}
}  // namespace

TEST_CASE("fmt keeps comments, is idempotent and preserves the AST", "[frontend][fmt]") {
  const std::string src =
      "// head\n"
      "type   t ;  // trailing\n"
      "\n\n\n"
      "evidence p(t),q( t );\n"
      "hard p(x) ^ /* inside */ (q(x) v !p(x)) => !(p(x) ^ q(x)).\n"
      "model m {\n  a[t]:real fixed; // a\n  /* before b */ b : real sampled;\n  // end\n}\n"
      "kernel pair A/B = x.y(1 m), x.z;\n"
      "// tail\n";
  const std::string once = fmt_of(src);
  CHECK(once ==
        "// head\n"
        "type t;  // trailing\n"
        "\n"
        "evidence p(t), q(t);\n"
        "/* inside */\n"
        "hard p(x) ^ (q(x) v !p(x)) => !(p(x) ^ q(x)).\n"
        "model m {\n  a[t] : real fixed;  // a\n  /* before b */\n  b : real sampled;\n  // end\n}\n"
        "kernel pair A / B =\n    x.y(1 m),\n    x.z;\n"
        "// tail\n");
  CHECK(fmt_of(once) == once);
  CHECK(dump_of(once) == dump_of(src));
}

TEST_CASE("fmt parenthesises exactly what the AST needs", "[frontend][fmt]") {
  for (const std::string r : {"hard (a(x) => b(x)) => c(x).", "hard a(x) => (b(x) => c(x)).", "hard (a(x) <=> b(x)) <=> c(x).",
                              "hard a(x) ^ (b(x) ^ c(x)).", "hard !!a(x).", "hard !(exists y: a(y)) v (exists z: b(z)).",
                              "hard exists y: a(y) ^ b(y) => c(y)."}) {
    INFO(r);
    const std::string f = fmt_of(r + "\n");
    CHECK(f == r + "\n");
    CHECK(dump_of(f) == dump_of(r));
  }
}

TEST_CASE("fmt: the short schedule form prints as one rangeless row", "[frontend][fmt]") {
  CHECK(fmt_of("schedule { a: 0.5, b: 0.5 }\n") == "schedule {\n  { a: 0.5, b: 0.5 };\n}\n");
  CHECK(dump_of("schedule { a: 0.5, b: 0.5 }\n") == dump_of("schedule { { a: 0.5, b: 0.5 }; }\n"));
  CHECK(fmt_of("schedule { {} }\n") == "schedule {\n  {};\n}\n");
  CHECK(dump_of(fmt_of("schedule { {} }\n")) == dump_of("schedule { {} }\n"));
}
