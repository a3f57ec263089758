// The segments kit reads the generated binding of examples/segments/segments.ksm by values
// and moves, never by name: priors, likelihood, each kernel direction's move and source
// parameters; the blocks compute what stdlib/segments.ksm documents; the binary writes
// "queries" and --evidence-out; a binding the program does not fit is an internal error.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "kit_fixture.h"
#include "runtime/cli/domain_main.h"
#include "runtime/mln/evidence.h"
#include "segments_factors.h"  // generated
#include "stdlib/segments/kit/kit.h"

namespace fs = std::filesystem;
namespace seg = ksmc::stdlib::segments;
namespace blk = ksmc::stdlib::segments::blocks;
namespace cli = ksmc::runtime::cli;
using segments_test::binding;

namespace {

struct Run {
  int code;
  std::string err;
};

Run run(const blk::Binding& b, const fs::path& out, std::vector<std::string> extra = {}) {
  std::vector<std::string> args{"segments", std::string(KSMC_SOURCE_DIR) + "/examples/segments/room.txt", "--out",
                                out.string(), "--quiet", "--iterations", "600", "--seed", "2"};
  args.insert(args.end(), extra.begin(), extra.end());
  std::vector<const char*> argv;
  for (const auto& a : args) argv.push_back(a.c_str());
  std::ostringstream o, e;
  const int code = cli::run_domain_main(static_cast<int>(argv.size()), argv.data(), seg::kit::domain_spec(b),
                                        cli::CliStreams{o, e, false});
  return {code, e.str()};
}

std::string slurp(const fs::path& p) {
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("the kit reads priors, likelihood and kernels from the binding's values", "[segments][kit]") {
  const seg::kit::ModelParams m = seg::kit::model_params(binding());
  CHECK(m.likelihood.sigma == Approx(0.02));
  CHECK(m.likelihood.background == Approx(0.01));
  REQUIRE(m.priors.size() == 2);
  CHECK(std::get<blk::Complexity>(m.priors[0]).per_metre == Approx(40.0));
  CHECK(m.mln_prior);
  const std::vector<blk::Move> moves{blk::Move::birth, blk::Move::death, blk::Move::split, blk::Move::merge,
                                     blk::Move::jitter};
  REQUIRE(binding().kernels.size() == moves.size());
  for (std::size_t k = 0; k < moves.size(); ++k) CHECK(seg::kit::kernel_params(binding().kernels[k]).move == moves[k]);
  // Both directions of a pair share their sources' parameters, defaults filled in.
  const auto death = seg::kit::kernel_params(binding().kernels[1]);
  CHECK(death.detects);
  CHECK(death.ransac.inlier_dist == Approx(0.03));
  CHECK(death.ransac.candidates == 300);
  CHECK(death.birth.explained == Approx(0.03));
  CHECK(death.death.explain == Approx(0.05));
  const auto merge = seg::kit::kernel_params(binding().kernels[3]);
  CHECK_FALSE(merge.detects);
  CHECK(merge.merge.angle_scale == Approx(10.0 * M_PI / 180.0));
  CHECK(merge.split.gap_weight == Approx(20.0));
}

TEST_CASE("blocks compute what stdlib/segments.ksm documents", "[segments][blocks]") {
  const seg::Scene lines(std::make_shared<const std::vector<seg::Vec2>>(), {});
  const blk::Scene s(lines);
  const seg::Segment a{{0, 0}, {2, 0}}, b{{2.1, 0}, {2.1, 3}}, c{{0, 0.05}, {1, 0.05}};
  CHECK(blk::seg::touching(s, a, b, 0.15));
  CHECK_FALSE(blk::seg::touching(s, a, b, 0.05));
  CHECK(blk::seg::perpendicular(s, a, b, 0.1));
  CHECK(blk::seg::parallel(s, a, c, 0.01));
  CHECK(blk::seg::close(s, a, c, 0.1));
  CHECK(blk::seg::short_(s, seg::Segment{{0, 0}, {0.3, 0}}, 0.4));
  CHECK(blk::endpoint_gap(s, a, b) == Approx(0.1));
  CHECK(blk::gaussian(s, 0.1, 0.05) == Approx(-2.0));
  CHECK(blk::gaussian_angle(s, 0.0, 0.05) == 0.0);
  // Jitter probabilities above 1 in sum are scaled to 1; below, kept.
  const auto j = std::get<blk::EndpointJitter>(blk::move::endpoint_jitter(0.02, 0.75, 0.05, 0.75)).jitter;
  CHECK(j.shift_prob == Approx(0.5));
  CHECK(j.shift_prob + j.slide_prob == Approx(1.0));
  const auto k = std::get<blk::EndpointJitter>(blk::move::endpoint_jitter(0.02, 0.2, 0.05, 0.4)).jitter;
  CHECK(k.slide_prob == 0.4);
}

TEST_CASE("segments.json carries every query marginal; --evidence-out replays in Markov logic", "[segments][kit]") {
  const fs::path dir = fs::temp_directory_path() / "ksmc_segments_binding";
  fs::remove_all(dir);
  const Run r = run(binding(), dir / "out", {"--evidence-out", (dir / "best.db").string()});
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(slurp(dir / "out" / "segments.json"));
  const auto& q = j.at("queries");
  const std::size_t n = j.at("segments").size();
  REQUIRE(n > 0);
  CHECK(q.size() == 3);  // Corner, SameWall, Spurious
  CHECK(q.at("Corner").size() == n * n);
  CHECK(q.at("Spurious").size() == n);
  for (const auto& seg : j.at("segments")) {
    const std::string name = "line" + std::to_string(seg.at("id").get<std::uint64_t>());
    CHECK(q.at("Spurious").at(name).get<double>() == Approx(seg.at("probabilities").at("Spurious").get<double>()).margin(1e-6));
  }
  // The .db names the same constants and holds every evidence atom.
  const auto& program = ksmc_generated::segments::program();
  ksmc::runtime::mln::Domain d = ksmc_generated::segments::make_domain();
  const std::string db = slurp(dir / "best.db");
  ksmc::runtime::mln::collect_db_constants(db, "best.db", program, d);
  CHECK(static_cast<std::size_t>(d.size(ksmc_generated::segments::kType_line)) == n);
  std::size_t lines = 0;
  for (char ch : db) lines += ch == '\n';
  CHECK(lines == 1 + 4 * n * n + n);  // header, four binary and one unary evidence predicate
  fs::remove_all(dir);
}

TEST_CASE("a binding the knowledge base does not fit is an internal error, exit 3", "[segments][kit]") {
  blk::Binding b = binding();
  b.extractors.push_back({ksmc_generated::segments::kPred_Corner, b.extractors[0].eval, "extract Corner(a, b) = ..."});
  const fs::path dir = fs::temp_directory_path() / "ksmc_segments_internal";
  const Run r = run(b, dir);
  CHECK(r.code == 3);
  CHECK(r.err.find("segments: internal error: semantics: an extractor computes query predicate") != std::string::npos);
  fs::remove_all(dir);
}
