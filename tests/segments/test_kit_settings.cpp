#include <catch2/catch.hpp>

#include "segments_model.h"  // generated
#include "stdlib/segments/kit/kit.h"
#include "stdlib/segments/kit/settings.h"

using namespace ksmc::stdlib::segments::kit;
namespace dom = ksmc::runtime::domain;

namespace {
std::string config_error(const dom::DomainConfig& c) {
  try {
    read_settings(c);
  } catch (const dom::ConfigError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("the example domain's config is read in base units", "[segments][kit]") {
  const SegmentsSettings s = read_settings(ksmc_generated::segments::domain_config());
  CHECK(s.collection == "line");
  REQUIRE(s.extracts.size() == 5);
  CHECK(s.extracts[0].predicate == "touching");
  CHECK(s.extracts[0].relation == Relation::Touching);
  CHECK(s.extracts[0].param == Approx(0.30));
  CHECK(s.extracts[4].arity == 1);
  CHECK(s.mln_prior);
  CHECK(s.complexity);
  REQUIRE(s.terms.size() == 3);
  CHECK(s.terms[0].measure == Measure::EndpointGap);
  CHECK(s.terms[0].conditions.at(0).predicate == "Corner");
  CHECK(s.terms[1].measure == Measure::CornerAngleError);
  CHECK(s.likelihood.sigma == Approx(0.02));
  REQUIRE(s.kernels.size() == 5);
  CHECK(s.kernels[0].kind == KernelKind::Birth);
  CHECK(s.kernels[1].kind == KernelKind::Death);
  CHECK(s.kernels[2].kind == KernelKind::Split);
  CHECK(s.kernels[3].kind == KernelKind::Merge);
  CHECK(s.kernels[4].kind == KernelKind::Jitter);
  CHECK(s.schedule.size() == 2);
  CHECK(s.ransac.inlier_dist == Approx(0.03));
}

TEST_CASE("calls the kit does not implement name their file:line", "[segments][kit]") {
  dom::DomainConfig c = ksmc_generated::segments::domain_config();
  SECTION("extractor") {
    c.extract[1].call.name = "seg.crossing";
    c.extract[1].call.where = "x.ksm:7";
    CHECK(config_error(c) == "x.ksm:7: seg.crossing: the segments kit does not implement this extractor");
  }
  SECTION("prior") {
    c.prior[0].call.name = "overlap_penalty";
    c.prior[0].call.where = "x.ksm:9";
    CHECK(config_error(c) == "x.ksm:9: overlap_penalty: the segments kit does not implement this prior");
  }
  SECTION("likelihood") {
    c.likelihood[0].name = "grid.occupancy";
    c.likelihood[0].where = "x.ksm:11";
    CHECK(config_error(c) == "x.ksm:11: grid.occupancy: the segments kit does not implement this likelihood");
  }
  SECTION("proposal source") {
    c.kernels[0].sources[0].name = "detect.hough";
    c.kernels[0].sources[0].where = "x.ksm:13";
    CHECK(config_error(c) == "x.ksm:13: detect.hough: the segments kit does not implement this proposal source");
  }
  SECTION("bad parameter") {
    c.likelihood[0].args[1].value = dom::Value::num(1.5);
    CHECK(config_error(c).find(": points.gaussian: background must be in (0, 1)") != std::string::npos);
  }
  SECTION("measure function") {
    c.prior[2].call.args[0].value.text = "wall_length_diff";
    CHECK(config_error(c).find("does not implement the function 'wall_length_diff'") != std::string::npos);
  }
  SECTION("model") {
    c.model[0].value_type = "rect";
    CHECK(config_error(c).find("segment sampled") != std::string::npos);
  }
  SECTION("domain_spec checks the config too") {
    c.extract[0].call.name = "seg.crossing";
    CHECK_THROWS_AS(domain_spec(c, ksmc_generated::segments::mln_binding()), dom::ConfigError);
  }
}
