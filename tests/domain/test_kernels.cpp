// runtime/domain kernels: KernelDecl list + ScheduleRow list -> kernels and mcmc::Schedule,
// every refusal a ConfigError.
#include <catch2/catch.hpp>

#include <memory>
#include <string>
#include <vector>

#include "runtime/domain/kernels.h"

namespace dom = ksmc::runtime::domain;
namespace mcmc = ksmc::runtime::mcmc;

namespace {

enum class Move { grow, shrink, wiggle };
struct Source {
  double scale = 1.0;
};
using Decl = dom::KernelDecl<Move, Source>;

class Named final : public mcmc::Kernel {
 public:
  Named(std::string n, std::string r, Move m) : name_(std::move(n)), reverse_(std::move(r)), move_(m) {}
  std::string_view name() const override { return name_; }
  std::string_view reverse_name() const override { return reverse_; }
  mcmc::Proposal propose(mcmc::Model&, mcmc::Rng&) const override { return mcmc::Proposal::declined(); }
  Move move() const { return move_; }

 private:
  std::string name_, reverse_;
  Move move_;
};

std::vector<Decl> decls() {
  return {{"UP", "DOWN", Move::grow, {{2.0}}, "kernel pair UP / DOWN"},
          {"DOWN", "UP", Move::shrink, {{2.0}}, "kernel pair UP / DOWN"},
          {"W", "W", Move::wiggle, {{0.5}}, "kernel W reverse W"}};
}

std::vector<dom::ScheduleRow> rows() {
  return {{0, 100, {{"UP", 0.7}, {"DOWN", 0.1}, {"W", 0.2}}},
          {100, dom::ScheduleRow::kForever, {{"UP", 0.2}, {"DOWN", 0.2}, {"W", 0.6}}}};
}

auto make = [](const Decl& d) { return std::make_shared<const Named>(d.name, d.reverse, d.move); };

}  // namespace

TEST_CASE("kernels: declarations and rows become the engine's kernels and schedule", "[domain][kernels]") {
  const dom::KernelTable t = dom::make_kernels(decls(), rows(), make);
  REQUIRE(t.kernels.size() == 3);
  CHECK(dynamic_cast<const Named&>(*t.kernels[1]).move() == Move::shrink);
  CHECK(t.schedule.kernel_count() == 3);
  CHECK(t.schedule.reverse_of(0) == 1);
  CHECK(t.schedule.reverse_of(2) == 2);
  CHECK(t.schedule.row_count() == 2);
  CHECK(t.schedule.row_end(1) == mcmc::kForever);
  CHECK(t.schedule.probability(0, 0) == Approx(0.7));
}

TEST_CASE("kernels: what the schedule cannot run is a ConfigError", "[domain][kernels]") {
  auto d = decls();
  d.push_back(d.front());
  CHECK_THROWS_AS(dom::make_kernels(d, rows(), make), dom::ConfigError);  // UP twice
  d = decls();
  d[2].reverse = "NOPE";
  CHECK_THROWS_AS(dom::make_kernels(d, rows(), make), dom::ConfigError);
  CHECK_THROWS_AS(dom::make_kernels(decls(), {}, make), dom::ConfigError);
  CHECK_THROWS_AS(dom::make_kernels(std::vector<Decl>{}, rows(), make), dom::ConfigError);
  auto r = rows();
  r[0].end = 50;  // gap [50, 100)
  CHECK_THROWS_AS(dom::make_kernels(decls(), r, make), dom::ConfigError);
  r = rows();
  r[1].probabilities = {{"UP", 1.0}};  // UP without DOWN
  CHECK_THROWS_WITH(dom::make_kernels(decls(), r, make), Catch::Contains("schedule"));
  r = rows();
  r[0].begin = -1;
  CHECK_THROWS_AS(dom::make_kernels(decls(), r, make), dom::ConfigError);
  const auto misnamed = [](const Decl& x) { return std::make_shared<const Named>(x.name + "_", x.reverse, x.move); };
  CHECK_THROWS_AS(dom::make_kernels(decls(), rows(), misnamed), dom::ConfigError);
}
