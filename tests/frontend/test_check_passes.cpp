// One section per check pass: each pass runs alone (after the symbol table) on snippets
// that must and must not trigger it.
#include <catch2/catch.hpp>

#include <string>

#include "tests/frontend/support.h"

using ksmc::tests::frontend::compile;
using ksmc::tests::frontend::contains;

namespace {
const std::string kTT = "include \"../../stdlib/tabletop.ksm\";\n";
const std::string kIn = "include \"../../stdlib/indoor.ksm\";\n";
const std::string kTypes = "type object;\nevidence stable(object), contact(object, object);\nquery hidden(object);\n";
}  // namespace

TEST_CASE("symbols: duplicated names", "[frontend][check]") {
  auto out = compile("type t;\ntype t;\nevidence p(t);\nquery p(t);\nquantity q [u = 1, u = 2];\n", {"symbols"});
  CHECK(contains(out.errors, "2:6: duplicate type 't' (first declared at"));
  CHECK(contains(out.errors, "4:7: duplicate predicate 'p'"));
  CHECK(contains(out.errors, "duplicate unit 'u'"));
  CHECK(compile("type t;\nevidence p(t);\n", {"symbols"}).errors.empty());
  // A user file may not redeclare a stdlib name.
  CHECK(contains(compile(kTT + "value se3;\n", {"symbols"}).errors, "duplicate type 'se3'"));
}

TEST_CASE("names: undeclared types, predicates and kernels", "[frontend][check]") {
  auto out = compile("type object;\nevidence p(objekt);\nhard q(x).\nschedule { { K: 1.0 }; }\n", {"names"});
  CHECK(contains(out.errors, "2:12: undeclared type 'objekt'; did you mean 'object'?"));
  CHECK(contains(out.errors, "3:6: undeclared predicate 'q'"));
  CHECK(contains(out.errors, "4:14: undeclared kernel 'K'"));
  CHECK(compile("type t;\nevidence p(t);\nhard p(x).\n", {"names"}).errors.empty());
}

TEST_CASE("arity: argument counts and constant types", "[frontend][check]") {
  auto out = compile("type c = {Red};\ntype s = {Box};\nquery has(s, c);\nhard has(Box).\nhard has(Red, Red).\n", {"arity"});
  CHECK(contains(out.errors, "4:6: predicate 'has' takes 2 arguments, but 1 was given"));
  CHECK(contains(out.errors, "5:10: argument 1 of 'has' must be of type 's', but constant 'Red' is of type 'c'"));
  CHECK(compile("type c = {Red};\ntype s = {Box};\nquery has(s, c);\nhard has(Box, Red).\n", {"arity"}).errors.empty());
}

TEST_CASE("variable-types: one type per variable and scope", "[frontend][check]") {
  auto out = compile("type a;\ntype b;\nevidence p(a), q(b);\nhard p(x) => q(x).\nhard p(x) => p(x).\n", {"variable-types"});
  REQUIRE(out.errors.size() == 1);
  CHECK(out.errors[0].find("4:16: variable 'x' is used as 'b' here but as 'a' at") == 0);
  // The same name in two rules is two variables.
  CHECK(compile("type a;\ntype b;\nevidence p(a), q(b);\nhard p(x).\nhard q(x).\n", {"variable-types"}).errors.empty());
}

TEST_CASE("weights: prob range, hard weights, missing weights", "[frontend][check]") {
  const std::string d = "type t;\nevidence p(t);\n";
  CHECK(contains(compile(d + "prob 1: p(x).\n", {"weights"}).errors, "probability 1 is outside (0, 1)"));
  CHECK(contains(compile(d + "prob -0.2: p(x).\n", {"weights"}).errors, "probability -0.2 is outside (0, 1)"));
  CHECK(contains(compile(d + "hard w 2: p(x).\n", {"weights"}).errors, "a hard rule cannot have a weight"));
  CHECK(contains(compile(d + "p(x).\n", {"weights"}).errors, "rule has no weight"));
  CHECK(compile(d + "prob 0.999: p(x).\nw -3: p(x).\nhard p(x).\n", {"weights"}).errors.empty());
}

TEST_CASE("extract: evidence targets over distinct variables, once", "[frontend][check]") {
  const std::string d = kTT + kTypes;
  CHECK(contains(compile(d + "extract hidden(o) = scene.is_table(o);\n", {"extract"}).errors, "'hidden' is a query predicate"));
  CHECK(contains(compile(d + "extract contact(a, a) = scene.is_table(a);\n", {"extract"}).errors, "appears twice"));
  CHECK(contains(compile(d + "extract stable(o) = scene.is_table(o);\nextract stable(o) = scene.is_table(o);\n", {"extract"}).errors,
                 "already has an extractor"));
  CHECK(compile(d + "extract stable(o) = scene.is_table(o);\n", {"extract"}).errors.empty());
}

TEST_CASE("calls: stdlib signatures, parameters and unit dimensions", "[frontend][check]") {
  const std::string d = kTT + kTypes + "model m { pose[object] : se3 sampled; size[object] : vec3 fixed; }\n";
  auto calls = [&](const std::string& s) { return compile(d + s, {"calls"}).errors; };
  CHECK(contains(calls("extract stable(o) = obb.stabel(pose[o], size[o]);\n"), "unknown extractor 'obb.stabel'; did you mean 'obb.stable'?"));
  CHECK(contains(calls("prior obb.hover;\n"), "'obb.hover' is an extractor, not a prior"));
  CHECK(contains(calls("extract stable(o) = obb.stable(pose[o], size[o], tol = 3 mm);\n"),
                 "parameter 'tol' of 'obb.stable' expects an angle (rad, deg), got a length (mm)"));
  CHECK(contains(calls("extract stable(o) = obb.stable(pose[o], size[o], tol = 3);\n"),
                 "expects an angle (rad, deg), got a number without unit"));
  CHECK(contains(calls("extract stable(o) = obb.stable(pose[o]);\n"), "missing argument for parameter 'size' of 'obb.stable'"));
  CHECK(contains(calls("extract stable(o) = obb.stable(pose[o], size[o], tool = 3 deg);\n"),
                 "unknown parameter 'tool' of 'obb.stable'; did you mean 'tol'?"));
  CHECK(contains(calls("extract stable(o) = obb.stable(size[o], pose[o]);\n"),
                 "parameter 'pose' of 'obb.stable' expects a value of type 'se3', got a value of type 'vec3'"));
  CHECK(contains(calls("extract stable(o) = obb.stable(pose[o], size[o], tol = 3 km);\n"), "unknown unit 'km'"));
  CHECK(contains(calls("likelihood keypoints.gaussian(sigma = 1 px, sigma = 1 px);\n"), "is given twice"));
  CHECK(contains(calls("likelihood keypoints.gaussian(1 px, true, 2 px, 3 mm, 1 deg, false, 3);\n"), "too many arguments"));
  CHECK(calls("extract stable(o) = obb.stable(pose[o], size[o], tol = 3 deg);\nlikelihood keypoints.gaussian(2 px, robust = true);\n").empty());
  // Index variables must have the collection's index type.
  CHECK(contains(compile(kIn + "type unit;\ntype k;\nevidence R(unit), B(k);\nmodel w { unit[] : rect sampled; }\n"
                         "extract B(x) = geom.room_like(unit[x]);\n", {"calls"}).errors,
                 "'unit' is indexed by 'unit', but 'x' is of type 'k'"));
  // Prior conditions need query predicates and thresholds in [0, 1].
  const auto p = compile(kIn + "type unit;\nevidence Adj(unit, unit);\nmodel w { unit[] : rect sampled; }\n"
                         "prior for a, b where P(Adj(a, b)) > 2: gaussian(wall_length_diff(unit[a], unit[b]));\n", {"calls"});
  CHECK(contains(p.errors, "P(...) needs a query predicate; 'Adj' is evidence"));
  CHECK(contains(p.errors, "probability threshold 2 is outside [0, 1]"));
}

TEST_CASE("kernels: every kernel has a consistent reverse", "[frontend][check]") {
  CHECK(contains(compile(kIn + "kernel A = detect.wbu();\n", {"kernels"}).errors, "kernel 'A' has no reverse"));
  // A kernel and another kernel as its reverse are one pair declaration.
  CHECK(contains(compile(kIn + "kernel A reverse B = detect.wbu();\n", {"kernels"}).errors,
                 "kernel 'A' names another kernel 'B' as its reverse; declare the two together: 'kernel pair A / B = ...;'"));
  CHECK(compile(kIn + "kernel pair A / B = detect.wbu();\nkernel S reverse S;\n", {"kernels"}).errors.empty());
}

TEST_CASE("kernel moves: the sources make one move that fits the kernel", "[frontend][check]") {
  auto moves = [&](const std::string& k) { return compile(kIn + k, {"kernel-moves"}).errors; };
  CHECK(moves("kernel pair A / B = detect.wbu(), detect.fsu(), detect.rpb();\n").empty());
  CHECK(moves("kernel pair A / B = move.interchange(), partner.inverse_distance();\n").empty());  // self-reverse as a pair
  CHECK(moves("kernel I reverse I = move.interchange(), partner.inverse_distance();\n").empty());
  CHECK(contains(moves("kernel pair A / B = detect.wbu(), move.wall_shift();\n"), "the sources of a kernel make one move"));
  CHECK(contains(moves("kernel I reverse I = detect.wbu();\n"), "makes the pair move birth / death"));
  CHECK(contains(moves("kernel pair A / B = detect.wbu(), partner.inverse_distance();\n"),
                 "serves merge, interchange, not the move birth / death"));
}

TEST_CASE("schedule: ranges and probabilities", "[frontend][check]") {
  const std::string d = kIn + "kernel pair A / B;\nkernel pair C / D;\n";
  auto sched = [&](const std::string& s) { return compile(d + "schedule {\n" + s + "}\n", {"schedule"}).errors; };
  CHECK(contains(sched("[0, 10): { A: 0.5, B: 0.45 };\n[10, inf): { A: 0.5, B: 0.5 };\n"),
                 "the probabilities of schedule row [0, 10) sum to 0.95, not 1"));
  CHECK(contains(sched("[0, 10): { A: 0.5, B: 0.5 };\n[20, inf): { A: 0.5, B: 0.5 };\n"), "must start where the previous row ends (10)"));
  CHECK(contains(sched("[5, inf): { A: 0.5, B: 0.5 };\n"), "the first schedule row must start at iteration 0"));
  CHECK(contains(sched("[0, 10): { A: 0.5, B: 0.5 };\n"), "the last schedule row must end at inf"));
  CHECK(contains(sched("{ A: 0.5, C: 0.5 };\n"), "kernel 'A' is scheduled in row without its reverse 'B'"));
  CHECK(contains(sched("{ A: 0.5, A: 0.5 };\n"), "kernel 'A' appears twice"));
  // Within the 1e-9 tolerance: 0.1 + 0.2 + 0.7 is not exactly 1 in binary.
  CHECK(sched("[0, 1000): { A: 0.1, B: 0.2, C: 0.35, D: 0.35 };\n[1000, inf): { A: 0.125, B: 0.125, C: 0.375, D: 0.375 };\n").empty());
  CHECK(contains(sched("{ A: 0.5, B: 0.4999999 };\n"), "sum to 0.9999999, not 1"));
}

TEST_CASE("usage: unused declarations are warnings", "[frontend][check]") {
  auto out = compile(kTT + "type object;\ntype spare;\nevidence stable(object);\nquery hidden(object), lost(object);\n"
                     "hard stable(o) => !hidden(o).\nmodel m { pose[object] : se3 sampled; size[object] : vec3 fixed; }\n"
                     "extract stable(o) = obb.stable(pose[o], pose[o]);\n",
                     {"usage"});
  CHECK(out.errors.empty());
  CHECK(contains(out.warnings, "type 'spare' is declared but never used"));
  CHECK(contains(out.warnings, "query predicate 'lost' is not used in any rule"));
  CHECK(contains(out.warnings, "model variable 'size' is never used"));
  CHECK_FALSE(contains(out.warnings, "'pose'"));
  CHECK_FALSE(contains(out.warnings, "'stable'"));
  // Nothing to say about the stdlib's own declarations.
  CHECK(compile(kTT, {"usage"}).warnings.empty());
}

TEST_CASE("the shipped domain files check clean", "[frontend][check]") {
  for (const char* f : {"domains/indoor.ksm", "domains/tabletop.ksm"}) {
    const auto out = compile("include \"../../" + std::string(f) + "\";\n");
    INFO(f << "\n" << out.rendered);
    CHECK(out.errors.empty());
  }
}
