// runtime/cli/work_estimate: the up-front line for large inputs and the --max-memory-mb refusal;
// runtime/cli/stage_log: the phase lines it turns on.
#include <catch2/catch.hpp>

#include <sstream>
#include <stdexcept>
#include <string>

#include "runtime/cli/domain_spec.h"
#include "runtime/cli/stage_log.h"
#include "runtime/cli/work_estimate.h"

using namespace ksmc::runtime::cli;

TEST_CASE("work estimates: figures in words", "[cli][work_estimate]") {
  CHECK(format_memory(240.4) == "240 MB");
  CHECK(format_memory(14200) == "14.2 GB");
  CHECK(format_duration(40) == "40 s");
  CHECK(format_duration(780) == "13 min");
  CHECK(format_duration(7560) == "2.1 h");
}

TEST_CASE("work estimates: small runs are quiet, large ones say their cost, too large are refused", "[cli][work_estimate]") {
  std::ostringstream err;
  const WorkEstimate small{"small.pgm", "a 600 x 400 map", 84, 2};
  check_work(small, kDefaultMaxMemoryMb, false, err);
  CHECK(err.str().empty());

  const WorkEstimate big{"big.pgm", "a 10000 x 10000 map", 3875, 840};
  check_work(big, kDefaultMaxMemoryMb, false, err);
  CHECK(err.str() == "big.pgm: a 10000 x 10000 map: about 14 min and 3.9 GB of memory (estimate)\n");
  std::ostringstream quiet;
  check_work(big, kDefaultMaxMemoryMb, true, quiet);
  CHECK(quiet.str().empty());

  const WorkEstimate huge{"huge.pgm", "a 20000 x 20000 map", 15275, 12000};
  try {
    check_work(huge, kDefaultMaxMemoryMb, true, quiet);
    FAIL("no refusal");
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()) ==
          "huge.pgm: a 20000 x 20000 map needs about 15.3 GB of memory (estimate), above --max-memory-mb 8192 (raise it to "
          "run anyway)");
  }
  CHECK_NOTHROW(check_work(huge, 16000, true, quiet));
}

TEST_CASE("stage lines: only runs estimated at 10 s or more print them, never under --quiet", "[cli][work_estimate]") {
  std::ostringstream err;
  StageLog stages("indoor", err, false);
  DomainInput in;
  in.stages = &stages;
  stage(in, "before any estimate");
  check_work(WorkEstimate{"small.pgm", "a 600 x 400 map", 84, 2}, in);
  stage(in, "after a small estimate");
  CHECK(err.str().empty());
  check_work(WorkEstimate{"mid.pgm", "a 3600 x 2400 map", 400, 12}, in);  // 12 s: no estimate line, stages on
  stage(in, "classifying solid interiors");
  const std::string out = err.str();
  CHECK(out.rfind("indoor: ", 0) == 0);
  CHECK(out.find(" s: classifying solid interiors\n") != std::string::npos);
  CHECK(out.find("after a small") == std::string::npos);

  std::ostringstream quiet_err;
  StageLog quiet("indoor", quiet_err, true);
  DomainInput q;
  q.stages = &quiet;
  q.quiet = true;
  check_work(WorkEstimate{"big.pgm", "a 10000 x 10000 map", 3875, 840}, q);
  stage(q, "classifying solid interiors");
  CHECK_FALSE(quiet.enabled());
  CHECK(quiet_err.str().empty());
}
