// libFuzzer target: the Alchemy-style evidence reader (.db) of runtime/mln: constants
// collected from the text, then every atom parsed against a small fixed program with
// evidence, query and exclusive-argument predicates. MlnError is the expected answer to
// bad input; anything else (crash, sanitizer report, other exception) is a bug.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "runtime/mln/error.h"
#include "runtime/mln/evidence.h"
#include "runtime/mln/program.h"

namespace {

ksmc::runtime::mln::Program make_program() {
  using namespace ksmc::runtime::mln;
  Program p;
  const auto obj = p.add_type("obj");
  const auto place = p.add_type("place");
  p.add_predicate(Predicate{"Big", {obj}, false, false, -1});
  p.add_predicate(Predicate{"On", {obj, obj}, true, false, -1});
  p.add_predicate(Predicate{"Near", {obj, obj}, true, true, -1});
  p.add_predicate(Predicate{"At", {obj, place}, true, true, 1});
  return p;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ksmc::runtime::mln;
  static const Program program = make_program();
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    Domain domain;
    collect_db_constants(text, "fuzz.db", program, domain);
    Evidence evidence(program, domain);
    parse_db(text, "fuzz.db", program, domain, evidence);
  } catch (const MlnError&) {
  }
  return 0;
}
