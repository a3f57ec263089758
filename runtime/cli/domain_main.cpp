#include "runtime/cli/domain_main.h"

#include <algorithm>
#include <exception>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <unistd.h>

#include "runtime/cli/checked_flags.h"
#include "runtime/cli/file_hash.h"
#include "runtime/cli/input_adapter.h"
#include "runtime/cli/interrupt.h"
#include "runtime/cli/progress.h"
#include "runtime/cli/run_outputs.h"
#include "runtime/cli/stage_log.h"
#include "runtime/cli/work_estimate.h"
#include "runtime/domain/config_error.h"
#include "runtime/io/atomic_file.h"
#include "runtime/mln/ground_bound.h"
#include "runtime/report/page.h"

namespace ksmc::runtime::cli {

namespace {

// Counts are parsed as text and checked by parse_count (CLI11 would wrap "-5" to 2^64-5).
struct CommonFlags {
  std::string seed = "1";
  std::string iterations;  // a count, or "auto"
  std::string max_iterations = "1000000";
  std::string plateau_window = "5000";
  std::string plateau_gain;  // "" = the domain's (DomainSetup::plateau_gain)
  std::string chains = "1";
  std::string threads = "0";
  std::string out;
  std::string samples = "0";
  std::string thin = "1";
  std::string burn_in;  // "" = half the iterations
  bool trace = false;
  std::string trace_every = "0";
  std::string max_input_mb = std::to_string(kDefaultMaxInputMb);
  std::string max_ground_clauses = std::to_string(mln::kDefaultMaxGroundClauses);
  std::string max_memory_mb = std::to_string(kDefaultMaxMemoryMb);
  bool quiet = false;
  std::string evidence_out;
  std::vector<std::string> inputs;
};

// The checked values of CommonFlags.
struct Counts {
  std::uint64_t seed = 1;
  std::uint64_t iterations = 0;  // with auto: the cap (--max-iterations)
  bool iterations_auto = false;
  std::uint64_t plateau_window = 0;
  std::optional<double> plateau_gain;
  unsigned chains = 1;
  unsigned threads = 0;
  std::uint64_t samples = 0;
  std::uint64_t thin = 1;
  std::optional<std::uint64_t> burn_in;
  std::uint64_t trace_every = 0;
  std::uint64_t max_input_bytes = 0;
  std::uint64_t max_ground_clauses = 0;
  std::uint64_t max_memory_mb = 0;
};

// The plateau flags, given on the command line or not (they apply to --iterations auto only).
struct PlateauFlagsGiven {
  bool max_iterations = false, window = false, gain = false;
};

Counts check_counts(const CommonFlags& cf, const PlateauFlagsGiven& given) {
  Counts c;
  c.seed = parse_count("--seed", cf.seed);
  c.iterations_auto = cf.iterations == "auto";
  if (c.iterations_auto) {
    c.iterations = parse_count("--max-iterations", cf.max_iterations, 1);
    c.plateau_window = parse_count("--plateau-window", cf.plateau_window, 1);
    if (!cf.plateau_gain.empty()) c.plateau_gain = parse_amount("--plateau-gain", cf.plateau_gain);
  } else {
    try {
      c.iterations = parse_count("--iterations", cf.iterations, 1);
    } catch (const UsageError& e) {
      throw UsageError(std::string(e.what()) + ", or auto (until the plateau)");
    }
    for (const auto& [on, flag] : {std::pair{given.max_iterations, "--max-iterations"},
                                   std::pair{given.window, "--plateau-window"}, std::pair{given.gain, "--plateau-gain"}}) {
      if (on) throw UsageError(fmt::format("{} applies to --iterations auto only (here --iterations {})", flag, cf.iterations));
    }
  }
  c.chains = static_cast<unsigned>(parse_count("--chains", cf.chains, 1, 4096));
  c.threads = static_cast<unsigned>(parse_count("--threads", cf.threads, 0, 4096));
  c.samples = parse_count("--samples", cf.samples);
  c.thin = parse_count("--thin", cf.thin, 1);
  if (!cf.burn_in.empty()) c.burn_in = parse_count("--burn-in", cf.burn_in);
  c.trace_every = parse_count("--trace-every", cf.trace_every);
  const std::uint64_t mb = parse_count("--max-input-mb", cf.max_input_mb, 1);
  c.max_input_bytes = mb > kCountMax / 1000000 ? kCountMax : mb * 1000000;
  c.max_ground_clauses = parse_count("--max-ground-clauses", cf.max_ground_clauses, 1);
  c.max_memory_mb = parse_count("--max-memory-mb", cf.max_memory_mb, 1);
  if (c.burn_in && *c.burn_in > c.iterations) {
    throw UsageError(fmt::format("--burn-in {} exceeds --iterations {}", *c.burn_in, c.iterations));
  }
  return c;
}

// The iterations a chain is expected to run: the count, or with auto 20 plateau windows (lab_b's
// plateau is known after 10-20), at most the cap. For work estimates and the trace spacing.
std::uint64_t expected_iterations(const Counts& c) {
  if (!c.iterations_auto) return c.iterations;
  return c.plateau_window > c.iterations / 20 ? c.iterations : 20 * c.plateau_window;
}

// Holds the domain flag values while CLI11 parses (std::map: stable addresses).
struct DomainFlagStorage {
  std::map<std::string, std::string> text;
  std::map<std::string, bool> toggles;
  std::map<std::string, std::vector<std::string>> words;  // flags of arity > 1
  std::map<std::string, CLI::Option*> options;
};

void add_domain_flags(CLI::App& app, const DomainSpec& spec, DomainFlagStorage& st) {
  for (const DomainFlag& f : spec.flags) {
    const std::string long_name = "--" + f.name;
    CLI::Option* opt = nullptr;
    if (f.kind == DomainFlag::Kind::toggle) {
      opt = app.add_flag(long_name, st.toggles[f.name], f.help);
    } else if (f.arity > 1) {
      opt = app.add_option(long_name, st.words[f.name], f.help)->expected(f.arity)->allow_extra_args(false);
    } else {
      std::string& value = st.text[f.name];
      value = f.default_value;
      opt = app.add_option(long_name, value, f.help);
      if (!f.default_value.empty()) opt->default_str(f.default_value);
      if (f.kind == DomainFlag::Kind::integer) opt->type_name("INT");
      if (f.kind == DomainFlag::Kind::real) opt->type_name("NUMBER");
      if (f.kind == DomainFlag::Kind::path) opt->type_name("PATH");
    }
    if (f.required) opt->required();
    opt->group(spec.name + " options");
    st.options[f.name] = opt;
  }
}

FlagValues collect_domain_flags(const DomainSpec& spec, const DomainFlagStorage& st) {
  FlagValues v;
  for (const DomainFlag& f : spec.flags) {
    const bool given = st.options.at(f.name)->count() > 0;
    if (f.kind == DomainFlag::Kind::toggle) {
      v.set(f.name, st.toggles.at(f.name) ? "true" : "false", given);
      continue;
    }
    if (f.arity > 1 && given) {
      v.set_words(f.name, st.words.at(f.name), given);
      continue;
    }
    std::string value = st.text.count(f.name) ? st.text.at(f.name) : f.default_value;
    if (!given && f.default_value.empty()) continue;
    v.set(f.name, value, given);
    // Check the kind now, so a bad value is a usage error before any work.
    if (f.kind == DomainFlag::Kind::integer) (void)v.integer(f.name);
    if (f.kind == DomainFlag::Kind::real) (void)v.real(f.name);
  }
  return v;
}

int usage_error(const CliStreams& io, const DomainSpec& spec, const std::string& msg) {
  io.err << spec.name << ": error: " << msg << "\nRun with --help for more information.\n";
  return kExitUsage;
}

// A message that already names its place ("map.pgm: error: ...", "scene.json:3: error: ...")
// is printed as it is, like a compiler's; any other gets the program's name.
int failure(const CliStreams& io, const DomainSpec& spec, const std::string& msg) {
  if (msg.find(": error: ") != std::string::npos) io.err << msg << '\n';
  else io.err << spec.name << ": error: " << msg << '\n';
  return kExitError;
}

// Whether `e` is, or carries (std::throw_with_nested, e.g. the engine's "chain N: ..."), a
// runtime::domain::ConfigError.
bool is_config_error(const std::exception& e) {
  if (dynamic_cast<const domain::ConfigError*>(&e)) return true;
  try {
    std::rethrow_if_nested(e);
  } catch (const std::exception& inner) {
    return is_config_error(inner);
  } catch (...) {
  }
  return false;
}

// An error of load / run / output: a ConfigError is an internal error (the kit cannot run
// what `ksmc check` accepted, runtime/domain/binding.h), anything else bad input (exit 1).
int failure(const CliStreams& io, const DomainSpec& spec, const std::exception& e) {
  if (!is_config_error(e)) return failure(io, spec, std::string(e.what()));
  io.err << spec.name << ": internal error: " << e.what() << " (ksmc check accepted this domain file; please report it)\n";
  return kExitInternal;
}

// A failure after a signal: the computation gave up (io::Cancelled, or an error caused by
// stopping early) before there was a state to write. The previous outputs are untouched.
int failure_or_interrupted(const CliStreams& io, const DomainSpec& spec, const std::exception& e) {
  if (!InterruptGuard::interrupted()) return failure(io, spec, e);
  io.err << spec.name << ": interrupted by " << InterruptGuard::signal_name()
         << " before a state existed; nothing written (any earlier outputs are untouched)\n";
  return InterruptGuard::exit_code();
}

// report.html (runtime/report) from what the folder holds; a report that cannot be drawn is
// a warning, the run's results stand.
void write_report(OutputDir& out, const nlohmann::json& summary, const DomainSpec& spec, const CliStreams& io) {
  try {
    const std::filesystem::path& t = out.target();
    const std::string name = (t.filename().empty() ? t.parent_path().filename() : t.filename()).string();
    out.write("report.html", report::report_html(out.dir(), summary, name));
  } catch (const std::exception& e) {
    io.err << spec.name << ": warning: report.html not written: " << e.what() << '\n';
  }
}

}  // namespace

int run_domain_main(int argc, const char* const* argv, const DomainSpec& spec) {
  const CliStreams io{std::cout, std::cerr, ::isatty(STDERR_FILENO) == 1};
  return run_domain_main(argc, argv, spec, io);
}

int run_domain_main(int argc, const char* const* argv, const DomainSpec& spec, const CliStreams& io) {
  CommonFlags cf;
  cf.iterations = spec.default_iterations_auto ? "auto" : std::to_string(spec.default_iterations);
  cf.out = spec.name + "_out";
  DomainFlagStorage dst;
  std::vector<std::string> adapter_values(input_adapters().size());  // "" = flag not given

  CLI::App app(spec.description, spec.name);
  struct {
    CLI::Option *max_iterations = nullptr, *window = nullptr, *gain = nullptr;
  } plateau_options;
  try {
    app.set_version_flag("--version", fmt::format("{} {} (ksmc {})", spec.name, spec.version, ksmc_version()));
    app.add_option("inputs", cf.inputs, spec.inputs_help)->type_name("INPUT");
    app.add_option("--seed", cf.seed, "random seed; same seed, same result")->capture_default_str();
    app.add_option("--iterations", cf.iterations,
                   "iterations per chain, or auto: each chain runs until its plateau (the best log posterior gains at "
                   "most --plateau-gain over --plateau-window iterations), at most --max-iterations")
        ->capture_default_str();
    plateau_options.max_iterations =
        app.add_option("--max-iterations", cf.max_iterations, "with --iterations auto: the most iterations a chain runs")
            ->capture_default_str();
    plateau_options.window =
        app.add_option("--plateau-window", cf.plateau_window, "with --iterations auto: the window of the plateau test")
            ->capture_default_str();
    plateau_options.gain = app.add_option("--plateau-gain", cf.plateau_gain,
                                          "with --iterations auto: the largest gain (nats) over the window that counts "
                                          "as none (default: the domain's unit, 0 = strict)");
    app.add_option("--chains", cf.chains, "independent chains (1 to 4096)")->capture_default_str();
    app.add_option("--threads", cf.threads, "threads for the chains (0 = one per core)")->capture_default_str();
    app.add_option("--out", cf.out, "output folder (created if missing)")->type_name("DIR")->capture_default_str();
    app.add_option("--samples", cf.samples, "posterior samples to store per chain (samples.jsonl)")->capture_default_str();
    app.add_option("--thin", cf.thin, "iterations between stored samples")->capture_default_str();
    app.add_option("--burn-in", cf.burn_in, "iterations before samples are taken (default: half)");
    app.add_flag("--trace", cf.trace, "write trace.csv (log posterior and acceptance rate per chain)");
    app.add_option("--trace-every", cf.trace_every, "iterations between trace rows (default: iterations/1000; implies --trace)");
    app.add_option("--max-input-mb", cf.max_input_mb, "largest input file read, in MB")->capture_default_str();
    app.add_option("--max-ground-clauses", cf.max_ground_clauses,
                   "refuse a Markov logic grounding estimated above this many clauses")->capture_default_str();
    app.add_option("--max-memory-mb", cf.max_memory_mb,
                   "refuse an input whose estimated memory is above this many MB")->capture_default_str();
    app.add_flag("--quiet,-q", cf.quiet, "no progress display, no estimate line");
    app.add_option("--evidence-out", cf.evidence_out,
                   "write the best state's evidence as an Alchemy .db (replay with ksmc infer --evidence)")
        ->type_name("FILE");
    add_domain_flags(app, spec, dst);
    for (std::size_t i = 0; i < input_adapters().size(); ++i) {
      const InputAdapter& a = input_adapters()[i];
      app.add_option("--" + a.flag, adapter_values[i], a.help)->type_name(a.value_name);
    }
  } catch (const CLI::Error& e) {
    return failure(io, spec, fmt::format("bad flag table of domain '{}': {}", spec.name, e.what()));
  }

  FlagValues domain_flags;
  Counts counts;
  try {
    app.parse(argc, argv);
    // An input adapter's flag (e.g. --bag) stands for one positional input.
    const std::size_t given = cf.inputs.size() + static_cast<std::size_t>(std::count_if(
                                  adapter_values.begin(), adapter_values.end(), [](const std::string& v) { return !v.empty(); }));
    if (given < spec.min_inputs || given > spec.max_inputs) {
      throw UsageError(spec.min_inputs == spec.max_inputs
                           ? fmt::format("expected {} {}, got {}", spec.min_inputs, spec.inputs_help, given)
                           : fmt::format("expected {} to {} {}, got {}", spec.min_inputs, spec.max_inputs,
                                         spec.inputs_help, given));
    }
    counts = check_counts(cf, PlateauFlagsGiven{plateau_options.max_iterations->count() > 0,
                                                plateau_options.window->count() > 0,
                                                plateau_options.gain->count() > 0});
    domain_flags = collect_domain_flags(spec, dst);
  } catch (const CLI::CallForHelp&) {
    io.out << app.help();
    return kExitOk;
  } catch (const CLI::CallForAllHelp&) {
    io.out << app.help("", CLI::AppFormatMode::All);
    return kExitOk;
  } catch (const CLI::CallForVersion&) {
    io.out << app.version() << '\n';
    return kExitOk;
  } catch (const CLI::ParseError& e) {
    return usage_error(io, spec, e.what());
  } catch (const UsageError& e) {
    return usage_error(io, spec, e.what());
  }

  // Input adapters write their input into scratch folders, removed when the run ends.
  std::vector<std::filesystem::path> scratch;
  struct ScratchGuard {
    std::vector<std::filesystem::path>& dirs;
    ~ScratchGuard() {
      std::error_code ec;
      for (const auto& d : dirs) std::filesystem::remove_all(d, ec);
    }
  } scratch_guard{scratch};
  try {
    for (std::size_t i = 0; i < adapter_values.size(); ++i) {
      if (adapter_values[i].empty()) continue;
      const auto dir = std::filesystem::temp_directory_path() /
                       fmt::format("ksmc-{}-{}-{}", input_adapters()[i].flag, ::getpid(), scratch.size());
      std::filesystem::remove_all(dir);
      std::filesystem::create_directories(dir);
      scratch.push_back(dir);
      cf.inputs.push_back(input_adapters()[i].to_input(adapter_values[i], dir).string());
    }
  } catch (const std::exception& e) {
    return failure(io, spec, e.what());
  }

  StageLog stages(spec.name, io.err, cf.quiet);  // phase lines of large runs (stage_log.h)
  DomainInput input;
  input.stages = &stages;
  for (const auto& p : cf.inputs) input.inputs.emplace_back(p);
  input.flags = domain_flags;
  input.seed = counts.seed;
  input.chains = counts.chains;
  input.threads = counts.threads;
  input.iterations = expected_iterations(counts);
  input.max_memory_mb = counts.max_memory_mb;
  input.quiet = cf.quiet;
  input.out_dir = cf.out;

  // From here on SIGINT, SIGTERM and SIGHUP only request cancellation (interrupt.h).
  InterruptGuard guard;
  mln::set_max_ground_clauses(counts.max_ground_clauses);
  DomainSetup setup;
  try {
    for (const auto& p : input.inputs) check_input_file(p, counts.max_input_bytes);
    setup = spec.load(input);
    if (!cf.evidence_out.empty() && !setup.evidence_db)
      throw UsageError(fmt::format("--evidence-out: domain '{}' has no evidence to write", spec.name));
  } catch (const UsageError& e) {
    return usage_error(io, spec, e.what());
  } catch (const std::exception& e) {
    return failure_or_interrupted(io, spec, e);
  }

  std::unique_ptr<mcmc::Engine> engine;
  std::optional<OutputDir> out;
  RunInfo info;
  try {
    engine = std::make_unique<mcmc::Engine>(setup.model_factory, setup.kernels, setup.schedule);
    for (const auto& p : input.inputs) info.inputs.push_back(hash_file(p));
    for (const auto& p : setup.extra_inputs) info.inputs.push_back(hash_file(p));
    out.emplace(input.out_dir);
  } catch (const std::exception& e) {
    return failure(io, spec, e);
  }

  mcmc::EngineConfig cfg;
  cfg.iterations = counts.iterations;
  cfg.seed = counts.seed;
  cfg.chains = counts.chains;
  cfg.threads = counts.threads;
  // A run of fixed length samples its second half; a run until the plateau keeps the last
  // samples (its length is not known in advance).
  cfg.burn_in = counts.burn_in.value_or(counts.iterations_auto ? 0 : counts.iterations / 2);
  cfg.samples = counts.samples;
  cfg.thin = counts.thin;
  cfg.keep_last_samples = counts.iterations_auto;
  if (counts.iterations_auto) {
    cfg.stop_at_plateau = mcmc::PlateauCriterion{counts.plateau_window, counts.plateau_gain.value_or(setup.plateau_gain)};
  }
  if (counts.trace_every != 0) cf.trace = true;  // --trace-every implies --trace
  if (cf.trace) {
    cfg.trace_every =
        counts.trace_every != 0 ? counts.trace_every : std::max<std::uint64_t>(1, expected_iterations(counts) / 1000);
  }
  ProgressPrinter printer(io.err, io.tty);
  if (!cf.quiet) cfg.progress = [&printer](const mcmc::Progress& p) { printer(p); };

  cfg.cancel = &InterruptGuard::flag();
  if (cfg.stop_at_plateau) {
    stages(fmt::format("building the model{} and sampling until the plateau (best gains at most {:.3g} nats over {} "
                       "iterations; at most {} iterations)",
                       cfg.chains > 1 ? " of each chain" : "", cfg.stop_at_plateau->min_gain,
                       cfg.stop_at_plateau->window, cfg.iterations));
  } else {
    stages(fmt::format("building the model{} and sampling {} iterations", cfg.chains > 1 ? " of each chain" : "",
                       cfg.iterations));
  }
  mcmc::RunResult result;
  try {
    result = engine->run(cfg);
  } catch (const std::exception& e) {
    return failure_or_interrupted(io, spec, e);
  }
  // The run has stopped: writing the outputs (which may run inference again) is not
  // cancelled by the request that stopped it, nor by further signals.
  const io::CancelShield shield;
  const bool interrupted = result.cancelled || InterruptGuard::interrupted();
  if (interrupted) {
    io.err << spec.name << ": interrupted by " << InterruptGuard::signal_name() << " after " << result.iterations
           << " iterations; writing the outputs of the best state so far\n";
    info.interrupted = InterruptGuard::signal_name();
  }

  if (cfg.stop_at_plateau && !interrupted) {
    for (const mcmc::ChainResult& c : result.chains) {
      if (c.plateau) continue;
      io.err << fmt::format("{}: warning: chain {} reached no plateau within {} iterations (best log posterior still "
                            "gaining more than {:.3g} nats per {} iterations); raise --max-iterations for a settled "
                            "result\n",
                            spec.name, c.chain, c.iterations, cfg.stop_at_plateau->min_gain, cfg.stop_at_plateau->window);
    }
  }

  stages("writing the outputs");
  info.domain_name = spec.name;
  info.domain_version = spec.version;
  info.config = cfg;
  info.plateau_gain_what = counts.plateau_gain ? "given (--plateau-gain)" : setup.plateau_gain_what;
  info.domain_extra = setup.summary_extra.is_object() ? setup.summary_extra : nlohmann::json::object();
  try {
    if (setup.write_results || !cf.evidence_out.empty()) {
      std::unique_ptr<mcmc::Model> best = setup.model_factory(static_cast<unsigned>(result.best_chain));
      best->restore(result.best().best_state);
      if (setup.write_results) setup.write_results(result, *best, *out);
      if (!cf.evidence_out.empty()) {
        // Inside the output folder it joins the folder's other files (written as a whole);
        // elsewhere it is a file of its own, written atomically.
        const std::filesystem::path db = std::filesystem::weakly_canonical(std::filesystem::absolute(cf.evidence_out));
        const std::filesystem::path folder = std::filesystem::weakly_canonical(std::filesystem::absolute(out->target()));
        if (db.parent_path() == folder) {
          out->write(db.filename().string(), setup.evidence_db(*best));
        } else {
          runtime::io::write_file_atomic(cf.evidence_out, setup.evidence_db(*best));
        }
      }
    }
    out->write("best_state.json", best_state_json(result).dump(2) + "\n");
    if (cfg.trace_every != 0) out->write("trace.csv", trace_csv(result));
    if (cfg.samples != 0) out->write("samples.jsonl", samples_jsonl(result));
    write_report(*out, make_summary(result, engine->schedule(), info), spec, io);
    info.outputs = out->manifest();
    out->write("summary.json", make_summary(result, engine->schedule(), info).dump(2) + "\n");
    out->commit();  // the whole folder at once
  } catch (const std::exception& e) {
    if (is_config_error(e)) return failure(io, spec, e);
    return failure(io, spec, fmt::format("{} (nothing written: any earlier outputs in {} are untouched)", e.what(),
                                         out->target().string()));
  }
  if (!cf.quiet) {
    io.err << fmt::format("{}: best log posterior {} (chain {}, iteration {}); outputs in {}\n", spec.name,
                          result.best().best_log_posterior, result.best_chain, result.best().best_iteration,
                          out->target().string());
  }
  return interrupted ? InterruptGuard::exit_code() : kExitOk;
}

}  // namespace ksmc::runtime::cli
