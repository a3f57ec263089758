// Large inputs say their cost up front (issue 16): a kit estimates the time and memory of a
// run from the size of its input (map cells, cloud points, scene objects) as soon as it
// knows that size and before the expensive work, and calls check_work. A large estimate
// is printed as one line on stderr; one above --max-memory-mb is refused (exit 1) with the
// figure and the flag that raises it:
//   big.pgm: a 20000 x 20000 map needs about 14.0 GB of memory (estimate), above
//   --max-memory-mb 8192 (raise it to run anyway)
// The per-unit constants live in each kit, each with a comment saying how it was measured
// (docs/reliability.md, "Bounded work").
#pragma once

#include <cstdint>
#include <ostream>
#include <string>

namespace ksmc::runtime::cli {

struct DomainInput;

// Default of --max-memory-mb (8 GiB: a laptop or a CI runner still has room beside it).
inline constexpr std::uint64_t kDefaultMaxMemoryMb = 8192;

struct WorkEstimate {
  std::string input;      // the file named in the line ("big.pgm")
  std::string what;       // "a 20000 x 20000 map", "1000000 points", "1000 objects"
  double memory_mb = 0;   // peak resident memory of the whole run
  double seconds = 0;     // wall time of the whole run at its flags (iterations, chains)
};

// Estimates at or above these are printed (smaller runs stay quiet).
inline constexpr double kAnnounceSeconds = 30.0;
inline constexpr double kAnnounceMemoryMb = 1024.0;
// Runs estimated at this or longer print their stage lines (stage_log.h).
inline constexpr double kStageSeconds = 10.0;

// "about 3.5 GB" / "about 240 MB"; "about 13 min" / "about 40 s" / "about 2.1 h".
std::string format_memory(double mb);
std::string format_duration(double seconds);

// Throws std::runtime_error (exit 1) when e.memory_mb > max_memory_mb; otherwise prints
// "<input>: <what>: about <time> and <memory> (estimate; --quiet hides this)" to `err`
// when the estimate is large and `quiet` is false. Returns whether it is large.
bool check_work(const WorkEstimate& e, std::uint64_t max_memory_mb, bool quiet, std::ostream& err);

// The same with the limit, --quiet and stderr of a domain run; an estimate of kStageSeconds
// or a large one also turns on the run's stage lines (stage_log.h).
void check_work(const WorkEstimate& e, const DomainInput& in);

}  // namespace ksmc::runtime::cli
