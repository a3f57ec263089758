// Config validation: the fixture (= domains/tabletop.ksm) is read into the right
// parameters; anything the kit does not implement is a ConfigError naming file:line.
#include <catch2/catch.hpp>

#include <string>

#include "stdlib/tabletop/kit/domain_spec.h"
#include "stdlib/tabletop/kit/kit_config.h"
#include "tests/tabletop_kit/binding.h"
#include "tests/tabletop_kit/config_fixture.h"

namespace kit = ksmc::stdlib::tabletop::kit;
namespace rd = ksmc::runtime::domain;
using namespace ksmc::tests::tabletop_kit;

namespace {

std::string config_error(const rd::DomainConfig& c) {
  try {
    (void)kit::read_kit_config(c);
  } catch (const rd::ConfigError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("the .ksm configuration becomes the kit's parameters") {
  const kit::KitConfig k = kit::read_kit_config(tabletop_config());
  CHECK(k.evidence.stable_tol_rad == Approx(10.0 * 3.14159265358979323846 / 180.0));
  CHECK(k.evidence.contact_eps == 0.004);
  CHECK(k.evidence.intersect_eps == 0.005);
  CHECK(k.hover_eps == 0.004);
  CHECK(k.likelihood.sigma_px == 1.0);
  CHECK(k.likelihood.robust);
  CHECK(k.likelihood.outlier_px == 5.0);
  CHECK(k.prior_quantity == kit::PriorQuantity::map);
  REQUIRE(k.kernels.size() == 1);
  CHECK(k.kernels[0].name == "refine");
  CHECK(k.kernels[0].sigma_t == 0.001);
  CHECK(k.kernels[0].sigma_r == Approx(0.5 * 3.14159265358979323846 / 180.0));
  CHECK(k.kernels[0].candidates == 20);
  CHECK(k.kernels[0].current_competes);
  REQUIRE(k.schedule.size() == 1);
  CHECK(k.schedule[0].probabilities.at(0).first == "refine");
  const kit::KitConfig s = kit::read_kit_config(tabletop_config(seed_tolerances()));
  CHECK(s.evidence.stable_tol_rad == Approx(3.0 * 3.14159265358979323846 / 180.0));
  CHECK(s.evidence.intersect_eps == 0.004);
  CHECK_FALSE(s.likelihood.robust);
}

TEST_CASE("unknown calls are ConfigErrors naming file:line") {
  SECTION("extract") {
    auto c = tabletop_config();
    c.extract[1].call.name = "obb.touch";
    const std::string e = config_error(c);
    CHECK(e.find("domains/tabletop.ksm:66") != std::string::npos);
    CHECK(e.find("obb.touch") != std::string::npos);
  }
  SECTION("extract for an unknown predicate") {
    auto c = tabletop_config();
    c.extract[0].predicate = "upright";
    CHECK(config_error(c).find("domains/tabletop.ksm:65") != std::string::npos);
  }
  SECTION("likelihood") {
    auto c = tabletop_config();
    c.likelihood[0].name = "keypoints.cauchy";
    const std::string e = config_error(c);
    CHECK(e.find("domains/tabletop.ksm:73") != std::string::npos);
    CHECK(e.find("keypoints.cauchy") != std::string::npos);
  }
  SECTION("prior") {
    auto c = tabletop_config();
    c.prior[0].call.name = "rect_penalty";
    CHECK(config_error(c).find("domains/tabletop.ksm:72") != std::string::npos);
  }
  SECTION("kernel source") {
    auto c = tabletop_config();
    c.kernels[0].sources[0].name = "pose.jump";
    const std::string e = config_error(c);
    CHECK(e.find("domains/tabletop.ksm:76") != std::string::npos);
    CHECK(e.find("pose.jump") != std::string::npos);
  }
  SECTION("kernel that is not its own reverse") {
    auto c = tabletop_config();
    c.kernels[0].reverse = "other";
    CHECK(config_error(c).find("domains/tabletop.ksm:76") != std::string::npos);
  }
}

TEST_CASE("bad parameters and missing items are ConfigErrors") {
  SECTION("negative eps") {
    auto c = tabletop_config();
    c.extract[1].call.args.back().value = rd::Value::num(-1.0);
    CHECK(config_error(c).find("domains/tabletop.ksm:66") != std::string::npos);
  }
  SECTION("hover eps different from contact eps") {
    auto c = tabletop_config();
    c.extract[4].call.args.back().value = rd::Value::num(0.01);
    const std::string e = config_error(c);
    CHECK(e.find("domains/tabletop.ksm:69") != std::string::npos);
  }
  SECTION("a non-integer candidate count") {
    auto c = tabletop_config();
    c.kernels[0].sources[0].args.back().value = rd::Value::num(2.5);
    CHECK(config_error(c).find("domains/tabletop.ksm:76") != std::string::npos);
  }
  SECTION("missing extractor") {
    auto c = tabletop_config();
    c.extract.erase(c.extract.begin() + 3);
    const std::string e = config_error(c);
    CHECK(e.find("domains/tabletop.ksm") == 0);
    CHECK(e.find("higher") != std::string::npos);
  }
  SECTION("unknown model variable") {
    auto c = tabletop_config();
    c.model.push_back({"colour", true, "object", "vec3", false});
    CHECK(config_error(c).find("colour") != std::string::npos);
  }
  SECTION("schedule naming an unknown kernel") {
    auto c = tabletop_config();
    c.schedule[0].probabilities = {{"jump", 1.0}};
    CHECK(config_error(c).find("jump") != std::string::npos);
  }
  SECTION("a pose argument indexed by the wrong variable") {
    auto c = tabletop_config();
    c.extract[1].call.args[2].value = idx("pose", "a");
    CHECK(config_error(c).find("pose_b") != std::string::npos);
  }
}

TEST_CASE("domain_spec reports a configuration error when the binary loads") {
  auto c = tabletop_config();
  c.likelihood[0].name = "keypoints.cauchy";
  const auto bad = kit::domain_spec(c, tabletop_binding());
  ksmc::runtime::cli::DomainInput in;
  in.inputs = {std::filesystem::path(KSMC_SOURCE_DIR) / "examples/tabletop/stack.json"};
  in.flags.set("input-format", "scene", false);
  try {
    (void)bad.load(in);
    FAIL("no ConfigError");
  } catch (const rd::ConfigError& e) {
    CHECK(std::string(e.what()).find("domains/tabletop.ksm:73") != std::string::npos);
  }
  const auto spec = kit::domain_spec(tabletop_config(), tabletop_binding());
  CHECK(spec.name == "tabletop");
  CHECK(static_cast<bool>(spec.load));
}
