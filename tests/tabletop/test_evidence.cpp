// Scene → ground evidence atoms, and incremental re-extraction after one object moves.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include "stdlib/tabletop/evidence.h"
#include "tests/tabletop/evidence_atoms.h"
#include "tests/tabletop/tabletop_test_util.h"

using namespace ksmc::stdlib::tabletop;
using ksmc::tests::tabletop::atoms;
using ksmc::tests::tabletop::GroundAtom;
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
  const auto got = atoms(ev);
  CHECK(ev.ids == std::vector<std::string>{"table", "a", "b", "c"});
  const std::vector<GroundAtom> expected = {
      {"table", {"table"}},          {"stable", {"table"}},         {"stable", {"a"}},
      {"stable", {"b"}},             {"stable", {"c"}},             {"hover", {"c"}},
      {"contact", {"table", "a"}},   {"contact", {"a", "table"}},   {"contact", {"a", "b"}},
      {"contact", {"b", "a"}},       {"higher", {"a", "table"}},    {"higher", {"b", "table"}},
      {"higher", {"b", "a"}},        {"higher", {"c", "table"}},    {"higher", {"c", "a"}},
      {"higher", {"c", "b"}},
  };
  CHECK(got == expected);
  CHECK_FALSE(has(got, "hover", {"a"}));
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
    const auto before = atoms(ev);
    const auto k = static_cast<std::size_t>(step % 8);
    s.objects[k].pose.t += Vector3d(0.05 * u(rng), 0.05 * u(rng), 0.02 * u(rng));
    s.objects[k].pose.q = (Eigen::Quaterniond(rot(5 * u(rng), Vector3d(u(rng), u(rng), u(rng) + 2))) *
                           s.objects[k].pose.q).normalized();
    update_evidence(ev, s, k);
    const Evidence full = extract_evidence(s);
    REQUIRE(atoms(ev) == atoms(full));
    if (atoms(ev) != before) ++changed;
  }
  // The walk must actually change relations for the comparison to mean something.
  CHECK(changed >= 15);
}
