// The evidence .db text is read back by runtime/mln's own parser, atom for atom.
#include <catch2/catch.hpp>

#include "runtime/mln/evidence.h"
#include "runtime/mln/program.h"
#include "stdlib/tabletop/evidence_db.h"
#include "stdlib/tabletop/scene_io.h"

namespace mln = ksmc::runtime::mln;
namespace tt = ksmc::stdlib::tabletop;

TEST_CASE("runtime/mln parse_db reads the table-top evidence exactly", "[mln_bridge]") {
  const tt::Scene scene =
      tt::load_scene(std::filesystem::path(KSMC_SOURCE_DIR) / "examples/tabletop/seed_example.json").scene;
  const tt::Evidence ev = tt::extract_evidence(scene);
  const std::string db = tt::evidence_db(ev);

  mln::Program program;
  const auto object = program.add_type("object");
  for (const char* name : {"stable", "table", "hover"}) program.add_predicate({name, {object}, false, false, -1});
  for (const char* name : {"contact", "intersect", "higher"})
    program.add_predicate({name, {object, object}, false, false, -1});
  program.validate();
  mln::Domain domain(program.types.size());
  mln::collect_db_constants(db, "seed.db", program, domain);
  REQUIRE(domain.size(object) == static_cast<std::int32_t>(ev.size()));
  mln::Evidence parsed(program, domain);
  mln::parse_db(db, "seed.db", program, domain, parsed);

  auto idx = [&](std::size_t body) { return *domain.find(object, ev.ids[body]); };
  auto value = [&](const char* pred, std::vector<std::int32_t> args) {
    return parsed.get(*program.find_predicate(pred), args);
  };
  for (std::size_t a = 0; a < ev.size(); ++a) {
    CHECK(value("table", {idx(a)}) == (ev.is_table[a] ? 1 : 0));
    CHECK(value("stable", {idx(a)}) == (ev.stable[a] ? 1 : 0));
    CHECK(value("hover", {idx(a)}) == (ev.hover[a] ? 1 : 0));
    for (std::size_t b = 0; b < ev.size(); ++b) {
      CHECK(value("contact", {idx(a), idx(b)}) == (a != b && ev.contact[a][b] ? 1 : 0));
      CHECK(value("intersect", {idx(a), idx(b)}) == (a != b && ev.intersect[a][b] ? 1 : 0));
      CHECK(value("higher", {idx(a), idx(b)}) == (a != b && ev.higher[a][b] ? 1 : 0));
    }
  }
}
