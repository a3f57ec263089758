// Grounder (folding, indexing, blocks, existentials) and the .db reader's errors.
#include <catch2/catch.hpp>

#include <random>

#include "runtime/mln/error.h"
#include "runtime/mln/exact.h"
#include "runtime/mln/grounder.h"
#include "tests/mln/tabletop_kb.h"

using namespace ksmc::runtime::mln;
using ksmc::tests::mln::TabletopKb;

namespace {

Domain objects(const TabletopKb& kb, std::initializer_list<const char*> names) {
  Domain d(kb.program.types.size());
  for (auto n : names) d.add(kb.object, n);
  return d;
}

std::string db_error(const TabletopKb& kb, const Domain& d, const std::string& text) {
  Evidence ev(kb.program, d);
  try {
    parse_db(text, "scene.db", kb.program, d, ev);
  } catch (const MlnError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE(".db parser: accepted syntax", "[mln][db]") {
  TabletopKb kb;
  const auto d = objects(kb, {"Table", "A", "B"});
  Evidence ev(kb.program, d);
  parse_db("// comment\n\n  contact(A,B)  // trailing\r\ncontact( B , A )\n! stable(A)\nstable(B)", "s.db", kb.program,
           d, ev);
  const std::int32_t ab[] = {1, 2}, ba[] = {2, 1}, a[] = {1}, b[] = {2}, t[] = {0};
  CHECK(ev.get(kb.contact, ab) == 1);
  CHECK(ev.get(kb.contact, ba) == 1);
  CHECK(ev.get(kb.stable, a) == 0);
  CHECK(ev.get(kb.stable, b) == 1);
  CHECK(ev.get(kb.stable, t) == Evidence::kUnknown);
}

TEST_CASE(".db parser: errors name file and line", "[mln][db]") {
  TabletopKb kb;
  const auto d = objects(kb, {"Table", "A", "B"});
  CHECK(db_error(kb, d, "stable(A)\ncontact(A,B\n") ==
        "scene.db:2: malformed ground atom 'contact(A,B': expected name(arg, ...) or !name(arg, ...)");
  CHECK(db_error(kb, d, "stable A\n") ==
        "scene.db:1: malformed ground atom 'stable A': expected name(arg, ...) or !name(arg, ...)");
  CHECK(db_error(kb, d, "\n\nstabel(A)\n") == "scene.db:3: unknown predicate 'stabel'");
  CHECK(db_error(kb, d, "contact(A)\n") == "scene.db:1: 'contact' takes 2 arguments, got 1");
  CHECK(db_error(kb, d, "stable(A, B)\n") == "scene.db:1: 'stable' takes 1 argument, got 2");
  CHECK(db_error(kb, d, "stable(C)\n") ==
        "scene.db:1: unknown constant 'C' of type 'object' (argument 1 of 'stable')");
  CHECK(db_error(kb, d, "// x\nhidden(A)\n") ==
        "scene.db:2: 'hidden' is a query predicate; its atoms cannot be given as evidence");
  CHECK(db_error(kb, d, "stable(A)\n!stable(A)\n") ==
        "scene.db:2: '!stable(A)' contradicts line 1 (the same atom given true and false)");
  CHECK(db_error(kb, d, "contact(A,)\n") == "scene.db:1: malformed ground atom 'contact(A,)': bad argument ''");
  const Domain empty(kb.program.types.size());
  CHECK(db_error(kb, empty, "") ==
        "scene.db: type 'object' has no constants (empty domain, needed by 'stable')");
  CHECK_THROWS_WITH(read_db_file("/nonexistent/x.db", kb.program, d, *std::make_unique<Evidence>(kb.program, d)),
                    "/nonexistent/x.db: cannot open evidence file");
}

TEST_CASE("collect_db_constants builds the domain from the evidence", "[mln][db]") {
  TabletopKb kb;
  Domain d;
  collect_db_constants("table(Table)\ncontact(Table, A)\n!stable(B)\n", "s.db", kb.program, d);
  REQUIRE(d.size(kb.object) == 3);
  CHECK(d.constants(kb.object) == std::vector<std::string>{"Table", "A", "B"});
}

TEST_CASE("grounder: unsatisfiable hard rule names the rule, its text, place and binding", "[mln][grounder]") {
  TabletopKb kb;
  const auto d = objects(kb, {"Table", "A", "B"});
  Evidence ev(kb.program, d);
  parse_db("contact(A, B)\n", "s.db", kb.program, d, ev);  // but not contact(B, A)
  CHECK_THROWS_WITH(ground(kb.program, d, ev),
                    "hard rule r4 `contact(o1, o2) => contact(o2, o1)` (tabletop.ksm:13) is unsatisfiable under "
                    "the evidence for o1=A, o2=B");
  Evidence ev2(kb.program, d);
  parse_db("table(A)\n", "s.db", kb.program, d, ev2);  // table not stable
  CHECK_THROWS_WITH(ground(kb.program, d, ev2),
                    "hard rule r9 `table(o1) => stable(o1)` (tabletop.ksm:18) is unsatisfiable under the evidence "
                    "for o1=A");
}

TEST_CASE("grounder: folding, dense indexing and constants", "[mln][grounder]") {
  TabletopKb kb;
  const auto d = objects(kb, {"Table", "A"});
  Evidence ev(kb.program, d);
  parse_db("table(Table)\nstable(Table)\nstable(A)\ncontact(A, Table)\ncontact(Table, A)\nhigher(A, Table)\n", "s.db",
           kb.program, d, ev);
  const auto g = ground(kb.program, d, ev);
  // 4 query predicates x 2 objects, dense in declaration order.
  CHECK(g.index.num_query_atoms == 8);
  const std::int32_t a[] = {1};
  CHECK(g.query_index(kb.supported, a) == 1);
  CHECK(g.query_index(kb.false_est, a) == 7);
  CHECK(g.atom_name(7) == "falseEst(A)");
  // Every clause left mentions only query atoms; hard r10 folds to unit clauses, and the
  // four atoms those fix (r7, r8 on Table; r10 supportive(Table), supported(A)) leave the
  // network as fixed query atoms (fold_forced_atoms).
  CHECK(g.network.num_atoms() == 4);
  std::int32_t hard_units = 0;
  for (std::int32_t c = 0; c < g.network.num_clauses(); ++c)
    if (g.network.is_hard(c) && g.network.clause(c).size() == 1) ++hard_units;
  CHECK(hard_units == 0);
  std::int32_t forced = 0;
  for (std::int64_t q = 0; q < g.index.num_query_atoms; ++q) forced += g.index.atom[q] < 0 ? 1 : 0;
  CHECK(forced == 4);
  // Constant: satisfied soft groundings, e.g. r12 on both stable objects = 2 * log 9,
  // r13 (no hover) = 2 * log 9, r14 (no intersect) = 4 * log 9.
  CHECK(g.network.constant() > 0.0);
  const auto r = exact_inference(g.network);
  const std::int32_t t[] = {0};
  CHECK(g.marginal(r, kb.supportive, t) == 1.0);
  CHECK(g.marginal(r, kb.supported, a) == 1.0);
  CHECK(g.marginal(r, kb.false_est, t) == 0.0);
}

TEST_CASE("grounder: existential variables and exactly-one groups", "[mln][grounder]") {
  Program p;
  const auto u = p.add_type("unit");
  const auto room = p.add_predicate({"Room", {u}, true, false, -1});
  const auto corr = p.add_predicate({"Corr", {u}, true, false, -1});
  const auto adj = p.add_predicate({"Adj", {u, u}, false, false, -1});
  const auto lab = p.add_predicate({"Label", {u, u}, true, true, 1});  // Label(u, v!)
  p.add_group({{room, corr}, "exactly one of Room(u), Corr(u)", {"k.ksm", 2}});
  Clause c;  // Room(a) => exists b: Adj(a, b) ^ ... simplified: !Room(a) v exists b Corr(b)
  c.name = "e1";
  c.text = "Room(a) => exists b: Corr(b)";
  c.loc = {"k.ksm", 3};
  c.variables = {{"a", u, false}, {"b", u, true}};
  c.literals = {{room, true, {Term::var(0)}}, {corr, false, {Term::var(1)}}};
  c.weight = 2.0;
  p.add_clause(c);
  Domain d(1);
  for (auto n : {"U0", "U1", "U2"}) d.add(u, n);
  Evidence ev(p, d);
  const std::int32_t l01[] = {0, 1};
  ev.set(lab, l01, true);  // fixes Label(U0, *) by the exclusive argument
  const auto g = ground(p, d, ev);
  CHECK(g.network.num_blocks() == 3 + 2);  // Room/Corr per unit + Label(U1,*), Label(U2,*)
  // Each grounding of e1 is one clause over 1 + 3 literals.
  std::int32_t four = 0;
  for (std::int32_t k = 0; k < g.network.num_clauses(); ++k) four += g.network.clause(k).size() == 4 ? 1 : 0;
  CHECK(four == 3);
  const std::int32_t l00[] = {0, 0}, l02[] = {0, 2};
  CHECK(g.index.atom[g.query_index(lab, l00)] == -1);
  CHECK(g.index.fixed[g.query_index(lab, l00)] == 0);
  CHECK(g.index.fixed[g.query_index(lab, l02)] == 0);
  (void)adj;
  // A group made impossible by evidence is reported.
  Evidence bad(p, d);
  ev.set(lab, l01, true);
  bad.set(lab, l01, true);
  bad.set(lab, l02, true);
  CHECK_THROWS_WITH(ground(p, d, bad), Catch::Contains("exclusive argument of 'Label'") &&
                                           Catch::Contains("more than one atom true"));
}

TEST_CASE("network builder normalises clauses", "[mln][network]") {
  GroundNetwork net;
  net.add_atoms(3);
  const Lit dup[] = {make_lit(2, false), make_lit(0, true), make_lit(2, false)};
  net.add_clause(dup, 1.25, 7);
  REQUIRE(net.num_clauses() == 1);
  CHECK(std::vector<Lit>(net.clause(0).begin(), net.clause(0).end()) == std::vector<Lit>{1, 4});
  CHECK(net.origin(0) == 7);
  const Lit taut[] = {make_lit(1, false), make_lit(1, true)};
  net.add_clause(taut, 0.5);
  net.add_hard_clause(taut);
  CHECK(net.num_clauses() == 1);
  CHECK(net.constant() == 0.5);
  net.add_clause({}, 3.0);  // never satisfied: dropped
  CHECK(net.num_clauses() == 1);
  CHECK_THROWS_WITH(net.add_hard_clause({}), Catch::Contains("empty hard clause"));
  const Lit out_of_range[] = {make_lit(5, false)};
  CHECK_THROWS_WITH(net.add_clause(out_of_range, 1.0), Catch::Contains("names atom 5"));
  const AtomId blk[] = {0, 1};
  net.add_exactly_one(blk);
  CHECK_THROWS_WITH(net.add_exactly_one(blk), Catch::Contains("two exactly-one blocks"));
  const std::uint8_t s1[] = {1, 0, 1}, s2[] = {1, 1, 0};
  CHECK(net.log_weight(s1) == Approx(0.5 + 1.25));
  CHECK(std::isinf(net.log_weight(s2)));
}

TEST_CASE("grounding is deterministic", "[mln][grounder]") {
  TabletopKb kb;
  const std::string path = std::string(KSMC_SOURCE_DIR) + "/tests/mln/data/scene20.db";
  const auto text = read_text_file(path);
  Domain d;
  collect_db_constants(text, path, kb.program, d);
  Evidence ev(kb.program, d);
  parse_db(text, path, kb.program, d, ev);
  const auto a = ground(kb.program, d, ev);
  const auto b = ground(kb.program, d, ev);
  REQUIRE(a.network.num_clauses() == b.network.num_clauses());
  for (std::int32_t c = 0; c < a.network.num_clauses(); ++c) {
    CHECK(std::vector<Lit>(a.network.clause(c).begin(), a.network.clause(c).end()) ==
          std::vector<Lit>(b.network.clause(c).begin(), b.network.clause(c).end()));
    CHECK(a.network.weight(c) == b.network.weight(c));
  }
  CHECK(a.network.constant() == b.network.constant());
  CHECK(a.index.atom == b.index.atom);
}

TEST_CASE(".db parser: random garbage gives file:line errors, never a crash", "[mln][db]") {
  TabletopKb kb;
  const auto d = objects(kb, {"Table", "A", "B"});
  std::mt19937_64 rng(123);
  const std::string alphabet = "stable(contact,)! AB/\t\r\nTablehover(x)),,((!!//";
  int ok = 0, errors = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::string text;
    const int len = static_cast<int>(rng() % 40);
    for (int i = 0; i < len; ++i) text += alphabet[rng() % alphabet.size()];
    Evidence ev(kb.program, d);
    try {
      parse_db(text, "fuzz.db", kb.program, d, ev);
      ++ok;
    } catch (const MlnError& e) {
      ++errors;
      INFO(text);
      CHECK(std::string(e.what()).rfind("fuzz.db:", 0) == 0);
    }
  }
  CHECK(errors > 100);
  CHECK(ok > 10);
}

TEST_CASE("program validation names the rule", "[mln][program]") {
  TabletopKb kb;
  Clause c;
  c.name = "bad";
  c.text = "stable(o1, o2)";
  c.loc = {"kb.ksm", 40};
  c.variables = {{"o1", kb.object, false}, {"o2", kb.object, false}};
  c.literals = {{kb.stable, false, {Term::var(0), Term::var(1)}}};
  c.weight = 1.0;
  kb.program.add_clause(c);
  CHECK_THROWS_WITH(kb.program.validate(), "bad `stable(o1, o2)` (kb.ksm:40): 'stable' takes 1 argument, got 2");
  CHECK_THROWS_WITH(kb.program.add_type("object"), "program: duplicate type 'object'");
  CHECK_THROWS_WITH(kb.program.add_predicate({"hover", {0}, false, false, -1}), "program: duplicate predicate 'hover'");
}
