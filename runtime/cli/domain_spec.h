// What a domain binary supplies to the common CLI (run_domain_main, domain_main.h).
//
// Generated <domain>_main.cpp:
//   int main(int argc, char** argv) {
//     return ksmc::runtime::cli::run_domain_main(argc, argv, indoor_domain_spec());
//   }
// where indoor_domain_spec() names the domain, registers its own flags and gives `load`,
// which reads the input file(s) and returns the model factory, kernels, schedule and
// result writer.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "runtime/cli/work_estimate.h"
#include "runtime/io/staged_dir.h"
#include "runtime/mcmc/engine.h"

namespace ksmc::runtime::cli {

class StageLog;  // stage_log.h

// A command-line mistake: reported with the usage hint, exit code 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A domain-specific flag, e.g. {"lut", "3x3 likelihood table (JSON)", "", Kind::path}.
struct DomainFlag {
  enum class Kind { text, integer, real, path, toggle };
  std::string name;           // long name without dashes
  std::string help;
  std::string default_value;  // "" = none (toggles default to false)
  Kind kind = Kind::text;
  bool required = false;
  // Text flags only: the number of words the flag takes (--path X1,Y1 X2,Y2 takes 2); the
  // words reach FlagValues::text joined by single spaces.
  int arity = 1;
};

// Values of the domain flags after parsing (defaults filled in), checked by kind.
class FlagValues {
 public:
  bool has(const std::string& name) const;    // given, or has a default
  bool given(const std::string& name) const;  // given on the command line
  const std::string& text(const std::string& name) const;  // throws UsageError if absent
  // The words of a flag of arity > 1 as given (a word may hold spaces: a file path); a flag
  // of arity 1 gives its one value. Throws UsageError if absent.
  std::vector<std::string> words(const std::string& name) const;
  long long integer(const std::string& name) const;
  double real(const std::string& name) const;
  bool toggle(const std::string& name) const;

  void set(const std::string& name, std::string value, bool given);
  // A flag of arity > 1: its words; text() gives them joined by single spaces.
  void set_words(const std::string& name, std::vector<std::string> words, bool given);

 private:
  std::map<std::string, std::string> values_;
  std::map<std::string, std::vector<std::string>> words_;
  std::set<std::string> given_;
};

// Everything `load` needs from the command line.
struct DomainInput {
  std::vector<std::filesystem::path> inputs;  // positional arguments, as given
  FlagValues flags;
  std::uint64_t seed = 1;
  unsigned chains = 1;
  unsigned threads = 0;            // --threads (0 = one per core)
  std::uint64_t iterations = 0;    // per chain; with --iterations auto the expected count (for estimates)
  std::uint64_t max_memory_mb = kDefaultMaxMemoryMb;  // --max-memory-mb: kits refuse estimates above it
  bool quiet = false;              // --quiet: no estimate line, no progress
  std::filesystem::path out_dir;
  StageLog* stages = nullptr;      // the driver's; check_work enables it for large inputs
};

// A kit enters a phase of its preparation (reading, front end, model construction): one
// progress line for large inputs (stage_log.h), nothing otherwise.
void stage(const DomainInput& in, std::string_view what);

// The output folder of a run, written as a whole (runtime/io/staged_dir.h): files go into
// a staging folder beside the target (dir()), and commit() renames it into place, so the
// target holds either the previous complete outputs or the new ones, never a mix, and no
// stale file of an earlier run. Destroyed uncommitted (error, exception), it leaves the
// previous outputs untouched. Kits writing files themselves must write under dir().
class OutputDir {
 public:
  explicit OutputDir(std::filesystem::path dir);  // checks the target; throws naming the folder
  void write(const std::string& name, std::string_view data);
  void write(const std::string& name, std::span<const unsigned char> data);
  std::filesystem::path path_of(const std::string& name) const { return staged_->staging() / name; }
  const std::filesystem::path& dir() const noexcept { return staged_->staging(); }  // where to write now
  const std::filesystem::path& target() const noexcept { return target_; }          // as given (--out)
  const std::vector<std::string>& written() const noexcept { return written_; }
  // Every file now in the folder (domain files included), with size and SHA-256.
  std::vector<io::StagedDir::Entry> manifest(std::string_view skip = {}) const { return staged_->manifest(skip); }
  void commit() { staged_->commit(); }

 private:
  std::filesystem::path target_;
  std::shared_ptr<io::StagedDir> staged_;
  std::vector<std::string> written_;
};

// What `load` returns.
struct DomainSetup {
  mcmc::ModelFactory model_factory;
  mcmc::KernelList kernels;
  mcmc::Schedule schedule;
  // Further files the result depends on (e.g. the PGM named by a map YAML): hashed into
  // summary.json next to the positional inputs.
  std::vector<std::filesystem::path> extra_inputs;
  // Writes the domain's results (world.json, images, ...). `best` is a fresh model of the
  // best chain restored to the best state. Optional.
  std::function<void(const mcmc::RunResult&, mcmc::Model& best, OutputDir& out)> write_results;
  nlohmann::json summary_extra = nlohmann::json::object();  // copied under "domain" in summary.json
  // The evidence of `best` (the best state) as Alchemy `.db` text, written by
  // `--evidence-out FILE` (kits: runtime::domain::Semantics::evidence_db). Optional: without
  // it, --evidence-out is a usage error.
  std::function<std::string(mcmc::Model& best)> evidence_db;
  // The default --plateau-gain of --iterations auto (runtime/mcmc/plateau.h): gains of the best
  // log posterior at most this large over the window count as none. 0 = strict. A kit sets a
  // unit of its own (indoor: one cell, stdlib/indoor/likelihood.h one_cell_gain) and names it.
  double plateau_gain = 0.0;
  std::string plateau_gain_what = "strict: no gain at all";
};

struct DomainSpec {
  std::string name;         // "indoor"
  std::string version;      // the domain's own version
  std::string description;  // one line for --help
  std::string inputs_help = "input file";
  std::size_t min_inputs = 1;
  std::size_t max_inputs = 1;
  std::uint64_t default_iterations = 10000;
  // --iterations defaults to auto (until each chain's plateau, at most --max-iterations)
  // instead of default_iterations.
  bool default_iterations_auto = false;
  std::vector<DomainFlag> flags;
  // Loads the input. Throw std::exception on bad input with a message naming the file
  // and the place ("map.yaml:3: resolution must be positive"): exit code 1. A
  // runtime::domain::ConfigError (here, in the models or while writing) is an internal
  // error: exit code 3.
  std::function<DomainSetup(const DomainInput&)> load;
};

}  // namespace ksmc::runtime::cli
