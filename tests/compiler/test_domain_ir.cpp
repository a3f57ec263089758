// The typed domain IR: arguments bound once in signature order, defaults filled in and
// marked, units converted, names resolved.
#include <catch2/catch.hpp>

#include <cmath>
#include <regex>
#include <sstream>

#include "compiler/driver/pipeline.h"
#include "compiler/emit/emit_model.h"

namespace {

using namespace ksmc::compiler;

struct Lowered {
  driver::PipelineResult r;
  std::string diagnostics;
};

Lowered lower_domain_text(const std::string& text, driver::Goal goal = driver::Goal::Lower) {
  Lowered out;
  diag::SourceManager sources;
  diag::DiagEngine diags(sources);
  build::LoadOptions options;
  options.include_dirs.push_back(KSMC_SOURCE_DIR);
  out.r = driver::run_pipeline("test.ksm", options, sources, diags, goal, &text);
  std::ostringstream ss;
  diags.flush(ss);
  out.diagnostics = ss.str();
  return out;
}

const std::string kIndoor =
    "domain d;\ninclude \"stdlib/indoor.ksm\";\ntype unit;\ntype side = {Left, Right};\n"
    "evidence RoLi(unit), MulDoor(unit);\nquery Room(unit), Hall(unit), SaLe(unit, unit);\n"
    "hard exactly one of Room(u), Hall(u).\nprob 0.9: RoLi(u) => Room(u).\nprob 0.7: MulDoor(u) => Hall(u).\n"
    "prob 0.6: Room(a) ^ Room(b) => SaLe(a, b).\n"
    "model world { unit[] : rect sampled; door[] : segment sampled; }\n"
    "extract RoLi(u) = geom.room_like(unit[u], big_ratio = 2.5, big_size = 800 cm);\n"
    "extract MulDoor(u) = geom.multi_door(unit[u], door);\n"
    "prior rect_penalty(tol = 2 deg);\n"
    "prior for a, b where P(SaLe(a, b)) >= 0.25: gaussian(wall_length_diff(unit[a], unit[b]));\n"
    "likelihood grid.occupancy(lut = [[0.8, 0.1, 0.1], [0.1, 0.8, 0.1], [0.1, 0.1, 0.8]], lenient_types = {Hall});\n"
    "kernel pair GROW / SHRINK = detect.wbu(), detect.fsu(after = 10);\n"
    "kernel SWAP reverse SWAP = move.interchange(), partner.inverse_distance();\n"
    "schedule { [0, 10): { GROW: 0.5, SHRINK: 0.5 }; [10, inf): { GROW: 0.25, SHRINK: 0.25, SWAP: 0.5 }; }\n";

}  // namespace

TEST_CASE("domain IR: calls bound in signature order with defaults and base units") {
  const auto l = lower_domain_text(kIndoor);
  INFO(l.diagnostics);
  REQUIRE(l.r.ok);
  const lower::DomainIr& ir = l.r.domain;
  CHECK(ir.kit == "indoor");
  CHECK(ir.constant_type == "unit");
  REQUIRE(ir.extracts.size() == 2);
  const lower::CallIr& c = ir.extracts[0].call;
  CHECK(c.block == "geom.room_like");
  CHECK(c.per_binding);
  REQUIRE(c.args.size() == 4);
  CHECK(c.args[0].value.kind == lower::ValueIr::Kind::Element);
  CHECK(c.args[0].value.type == "rect");
  CHECK(c.args[0].value.slot == 0);
  CHECK(c.args[1].param == "big_size");
  CHECK(c.args[1].value.real == Approx(8.0));
  CHECK_FALSE(c.args[1].defaulted);
  CHECK(c.args[2].value.real == 2.5);
  CHECK(c.args[3].param == "corridor_width");
  CHECK(c.args[3].value.real == 0.0);
  CHECK(c.args[3].defaulted);
  const lower::CallIr& m = ir.extracts[1].call;
  CHECK(m.args[1].value.kind == lower::ValueIr::Kind::Collection);
  CHECK(m.args[2].value.kind == lower::ValueIr::Kind::Int);
  CHECK(m.args[2].value.integer == 2);
  CHECK(m.args[2].defaulted);
  REQUIRE(ir.priors.size() == 2);
  CHECK_FALSE(ir.priors[0].conditional);
  CHECK(ir.priors[0].call.args[1].value.real == Approx(2 * M_PI / 180));
  const lower::PriorIr& p = ir.priors[1];
  CHECK(p.conditional);
  CHECK(p.function == "prior_SaLe_gaussian");
  CHECK(p.var_types == std::vector<std::string>{"unit", "unit"});
  REQUIRE(p.conditions.size() == 1);
  CHECK(p.conditions[0].op == ">=");
  CHECK(p.conditions[0].threshold == 0.25);
  CHECK(p.call.args[0].value.kind == lower::ValueIr::Kind::Call);
  CHECK(p.call.args[0].value.call->block == "wall_length_diff");
  CHECK(p.call.args[1].value.real == Approx(0.3));
  REQUIRE(ir.likelihoods.size() == 1);
  CHECK(ir.likelihoods[0].call.args[1].value.preds == std::vector<std::string>{"Hall"});
  CHECK(ir.likelihoods[0].call.args[2].defaulted);
  REQUIRE(ir.kernels.size() == 2);
  CHECK(ir.kernels[0].forward_move == "birth");
  CHECK(ir.kernels[0].reverse_move == "death");
  CHECK(ir.kernels[0].sources[1].args[0].value.integer == 10);
  CHECK(ir.kernels[1].forward_move == "interchange");
  CHECK(ir.kernels[1].reverse == "SWAP");
  REQUIRE(ir.schedule.size() == 2);
  CHECK(ir.schedule[1].forever);
  CHECK(ir.schedule[1].probabilities[2] == std::pair<std::string, double>{"SWAP", 0.5});
}

TEST_CASE("emitted binding: direct block calls, pair directions share sources") {
  const auto l = lower_domain_text(kIndoor, driver::Goal::Emit);
  INFO(l.diagnostics);
  REQUIRE(l.r.ok);
  REQUIRE(l.r.files.size() == 5);
  const std::string& src = l.r.files[3].text;
  CHECK(src.find("return blk::geom::room_like(s, s.rect(c[0]), 8.0, 2.5, 0.0);") != std::string::npos);
  CHECK(src.find("return blk::geom::multi_door(s, s.rect(c[0]), s.segments(), 2);") != std::string::npos);
  CHECK(src.find("{{true, kPred_SaLe, {0, 1}, dom::Cmp::ge, 0.25, false}}, &prior_SaLe_gaussian") != std::string::npos);
  CHECK(src.find("b.kernels.push_back({\"GROW\", \"SHRINK\", blk::Move::birth, {blk::detect::wbu(1.5, 200), blk::detect::fsu(10, 100)}") !=
        std::string::npos);
  CHECK(src.find("b.kernels.push_back({\"SHRINK\", \"GROW\", blk::Move::death, b.kernels.back().sources") != std::string::npos);
  CHECK(src.find("b.kernels.push_back({\"SWAP\", \"SWAP\", blk::Move::interchange") != std::string::npos);
  CHECK(src.find("b.schedule.push_back({10, dom::ScheduleRow::kForever, {{\"GROW\", 0.25}") != std::string::npos);
  for (const auto& f : l.r.files) CHECK_FALSE(std::regex_search(f.text, std::regex("test\\.ksm:[0-9]")));  // no source lines
}

TEST_CASE("domain IR: a proposal argument indexed by a kernel parameter is not passed") {
  const std::string text =
      "domain t;\ninclude \"stdlib/tabletop.ksm\";\ntype object;\nevidence stable(object);\nquery hidden(object);\n"
      "prob 0.9: stable(o) => !hidden(o).\nmodel m { pose[object] : se3 sampled; size[object] : vec3 fixed; }\n"
      "extract stable(o) = obb.stable(pose[o], size[o]);\nprior mln;\nlikelihood keypoints.gaussian();\n"
      "output scene.decisions(false_est = hidden, hidden = hidden);\n"
      "kernel refine(o: object) reverse refine = pose.perturb(pose[o], candidates = 5);\nschedule { { refine: 1.0 }; }\n";
  const auto l = lower_domain_text(text, driver::Goal::Emit);
  INFO(l.diagnostics);
  REQUIRE(l.r.ok);
  CHECK(l.r.domain.kernels[0].sources[0].args[0].value.kind == lower::ValueIr::Kind::Dropped);
  const std::string& src = l.r.files[3].text;
  CHECK(src.find("blk::pose::perturb(/* pose[o] */ 0.003, 0.03490658503988659, 5)") != std::string::npos);
  CHECK(src.find("b.outputs.push_back(blk::scene::decisions(kPred_hidden, kPred_hidden));") != std::string::npos);
  CHECK(src.find("b.priors.push_back(blk::mln());") != std::string::npos);
}
