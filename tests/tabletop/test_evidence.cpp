// Scene → ground evidence atoms, and incremental re-extraction after one object moves.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include "stdlib/tabletop/evidence.h"
#include "stdlib/tabletop/evidence_db.h"
#include "tests/tabletop/tabletop_test_util.h"

using namespace ksmc::stdlib::tabletop;
using ksmc::tests::tabletop::object;
using ksmc::tests::tabletop::rot;
using Eigen::Vector3d;

namespace {

bool has(const std::vector<GroundAtom>& atoms, const std::string& pred, std::vector<std::string> args) {
  return std::find(atoms.begin(), atoms.end(), GroundAtom{pred, std::move(args)}) != atoms.end();
}

Scene stack_scene() {
  Scene s;
  s.camera = {600, 600, 320, 240, 640, 480};
  s.objects.push_back(object("a", Vector3d(0, 0, 0.02), Vector3d(0.2, 0.15, 0.04)));
  s.objects.push_back(object("b", Vector3d(0, 0, 0.07), Vector3d(0.1, 0.1, 0.06)));
  s.objects.push_back(object("c", Vector3d(0.4, 0, 0.2), Vector3d(0.05, 0.05, 0.05)));
  return s;
}

}  // namespace

TEST_CASE("evidence atoms of a small stack with a hovering box", "[evidence]") {
  const Evidence ev = extract_evidence(stack_scene());
  const auto atoms = ev.atoms();
  CHECK(ev.ids == std::vector<std::string>{"table", "a", "b", "c"});
  const std::vector<GroundAtom> expected = {
      {"table", {"table"}},          {"stable", {"table"}},         {"stable", {"a"}},
      {"stable", {"b"}},             {"stable", {"c"}},             {"hover", {"c"}},
      {"contact", {"table", "a"}},   {"contact", {"a", "table"}},   {"contact", {"a", "b"}},
      {"contact", {"b", "a"}},       {"higher", {"a", "table"}},    {"higher", {"b", "table"}},
      {"higher", {"b", "a"}},        {"higher", {"c", "table"}},    {"higher", {"c", "a"}},
      {"higher", {"c", "b"}},
  };
  CHECK(atoms == expected);
  CHECK_FALSE(has(atoms, "hover", {"a"}));
}

TEST_CASE("incremental re-extraction equals full extraction", "[evidence]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Scene s;
  s.camera = {600, 600, 320, 240, 640, 480};
  for (int i = 0; i < 8; ++i)
    s.objects.push_back(object("o" + std::to_string(i), Vector3d(0.15 * u(rng), 0.15 * u(rng), 0.05 + 0.05 * u(rng)),
                               Vector3d(0.08, 0.06, 0.1), rot(10 * u(rng), Vector3d(u(rng), u(rng), 1))));
  Evidence ev = extract_evidence(s);
  int changed = 0;
  for (int step = 0; step < 40; ++step) {
    const auto before = ev.atoms();
    const auto k = static_cast<std::size_t>(step % 8);
    s.objects[k].pose.t += Vector3d(0.05 * u(rng), 0.05 * u(rng), 0.02 * u(rng));
    s.objects[k].pose.q = (Eigen::Quaterniond(rot(5 * u(rng), Vector3d(u(rng), u(rng), u(rng) + 2))) *
                           s.objects[k].pose.q).normalized();
    update_evidence(ev, s, k);
    const Evidence full = extract_evidence(s);
    REQUIRE(ev.atoms() == full.atoms());
    if (ev.atoms() != before) ++changed;
  }
  // The walk must actually change relations for the comparison to mean something.
  CHECK(changed >= 15);
}

TEST_CASE("evidence as closed-world .db text", "[evidence]") {
  Scene s = stack_scene();
  const Evidence ev = extract_evidence(s);
  const std::string db = evidence_db(ev);
  // 3 unary predicates × 4 bodies + 3 binary predicates × 16 pairs, plus the comment line.
  CHECK(std::count(db.begin(), db.end(), '\n') == 1 + 3 * 4 + 3 * 16);
  CHECK(db.find("\ntable(table)\n") != std::string::npos);
  CHECK(db.find("\n!table(a)\n") != std::string::npos);
  CHECK(db.find("\nhover(c)\n") != std::string::npos);
  CHECK(db.find("\n!hover(b)\n") != std::string::npos);
  CHECK(db.find("\ncontact(b, a)\n") != std::string::npos);
  CHECK(db.find("\n!contact(a, a)\n") != std::string::npos);
  CHECK(db.find("\nhigher(c, b)\n") != std::string::npos);
  CHECK(db.find("\n!higher(b, c)\n") != std::string::npos);
  // Every true atom of atoms() appears positively, and nothing else does.
  std::size_t positives = 0;
  std::size_t pos = 0;
  while ((pos = db.find('\n', pos)) != std::string::npos) {
    ++pos;
    if (pos < db.size() && db[pos] != '!' && db[pos] != '/') ++positives;
  }
  CHECK(positives == ev.atoms().size());
  s.objects[0].id = "a b";
  CHECK_THROWS_WITH(evidence_db(extract_evidence(s)), Catch::Contains("id \"a b\" is not a valid .db constant"));
}
