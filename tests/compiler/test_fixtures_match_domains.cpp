// The Markov logic tests (tests/mln) and benchmarks build the table-top and indoor knowledge
// bases by hand; this test lowers domains/tabletop.ksm and domains/indoor.ksm and requires
// the same predicates, groups and clauses (literals up to variable renaming, weights), so
// those tests exercise exactly the rule bases the domain files declare.
#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "tests/compiler/lower_fixture.h"
#include "tests/mln/indoor_kb.h"
#include "tests/mln/tabletop_kb.h"

namespace mln = ksmc::runtime::mln;

namespace {

std::string read(const std::string& path) {
  std::ifstream f(path);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

// A clause as text with variables renamed by first appearance, literals sorted.
std::string canonical(const mln::Program& p, const mln::Clause& c) {
  std::map<std::int32_t, int> rename;
  std::vector<std::string> lits;
  for (const auto& l : c.literals) {
    std::string s = (l.negated ? "!" : "") + p.predicates[static_cast<std::size_t>(l.predicate)].name + "(";
    for (const auto& t : l.args) {
      if (!t.is_variable) {
        s += t.constant + ",";
        continue;
      }
      auto it = rename.emplace(t.variable, static_cast<int>(rename.size())).first;
      s += (c.variables[static_cast<std::size_t>(t.variable)].existential ? "E" : "V") + std::to_string(it->second) + ",";
    }
    lits.push_back(s + ")");
  }
  // Renaming depends on literal order; sort, rename again in sorted order for a stable key.
  std::sort(lits.begin(), lits.end());
  std::string key = c.hard ? "hard:" : "soft:";
  for (const auto& l : lits) key += l + " v ";
  return key;
}

std::multimap<std::string, double> clauses_of(const mln::Program& p) {
  std::multimap<std::string, double> out;
  for (const auto& c : p.clauses) out.emplace(canonical(p, c), c.hard ? 0.0 : c.weight);
  return out;
}

void require_same(const mln::Program& fixture, const mln::Program& lowered) {
  REQUIRE(fixture.predicates.size() == lowered.predicates.size());
  for (std::size_t i = 0; i < fixture.predicates.size(); ++i) {
    CHECK(fixture.predicates[i].name == lowered.predicates[i].name);
    CHECK(fixture.predicates[i].query == lowered.predicates[i].query);
    CHECK(fixture.predicates[i].arg_types.size() == lowered.predicates[i].arg_types.size());
  }
  REQUIRE(fixture.groups.size() == lowered.groups.size());
  const auto a = clauses_of(fixture);
  const auto b = clauses_of(lowered);
  REQUIRE(a.size() == b.size());
  auto ia = a.begin();
  auto ib = b.begin();
  for (; ia != a.end(); ++ia, ++ib) {
    INFO(ia->first << "  vs  " << ib->first);
    CHECK(ia->first == ib->first);
    CHECK(ia->second == Approx(ib->second).epsilon(1e-12));
  }
}

}  // namespace

TEST_CASE("the hand-built table-top KB of tests/mln is domains/tabletop.ksm") {
  const std::string path = std::string(KSMC_SOURCE_DIR) + "/domains/tabletop.ksm";
  auto lowered = ksmc::tests::lower_text(read(path), path);
  INFO(lowered.diagnostics);
  REQUIRE(lowered.ok);
  ksmc::tests::mln::TabletopKb kb;
  require_same(kb.program, lowered.ir.program);
}

TEST_CASE("the hand-built indoor KB of tests/mln is domains/indoor.ksm") {
  const std::string path = std::string(KSMC_SOURCE_DIR) + "/domains/indoor.ksm";
  auto lowered = ksmc::tests::lower_text(read(path), path);
  INFO(lowered.diagnostics);
  REQUIRE(lowered.ok);
  ksmc::tests::mln::IndoorKb kb;
  require_same(kb.program, lowered.ir.program);
}
