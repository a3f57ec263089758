// ksmc — the command line. Each subcommand is one entry of kCommands; a later stage adds
// `emit`, `infer`, `build` and `--dump-ir` by adding entries here.
#include <algorithm>
#include <exception>
#include <filesystem>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "compiler/ast/dump.h"
#include "compiler/build/loader.h"
#include "compiler/driver/build_command.h"
#include "compiler/driver/install_layout.h"
#include "compiler/driver/pipeline.h"
#include "compiler/emit/emit_factors.h"
#include "compiler/emit/emit_model.h"
#include "compiler/fmt/formatter.h"
#include "compiler/alchemy/mln_import.h"
#include "compiler/infer/infer_command.h"
#include "compiler/lower/dump_domain_ir.h"
#include "compiler/learn/learn_command.h"
#include "compiler/lower/dump_ir.h"
#include "compiler/lower/lower_mln.h"
#include "compiler/lower/per_formula.h"
#include "runtime/io/atomic_file.h"

#ifndef KSMC_VERSION
#define KSMC_VERSION "unknown"
#endif

namespace {

using namespace ksmc::compiler;

struct Invocation {
  std::vector<std::string> files;
  build::LoadOptions load;
  bool dump_ast = false;
  bool in_place = false;
  bool check_only = false;  // fmt --check
  bool dump_ir = false;
  bool dump_domain_ir = false;
  std::string out_dir;      // emit --out, build -o
  infer::InferRequest infer;
  learn::LearnRequest learn;
  std::string keep_dir;     // build --keep
  bool verbose = false;     // build --verbose
  bool per_formula = false; // infer / learn / import-mln --per-formula
  int jobs = 0;             // build -j
  std::filesystem::path executable;
};

struct Command {
  const char* name;
  const char* usage;
  const char* summary;
  std::function<int(Invocation&)> run;
};

constexpr int kExitOk = 0;
constexpr int kExitErrors = 1;
constexpr int kExitUsage = 2;
constexpr int kExitInternal = 3;

std::string plural(int n, const char* word) { return std::to_string(n) + " " + word + (n == 1 ? "" : "s"); }

int cmd_check(Invocation& inv) {
  int status = kExitOk;
  for (const std::string& path : inv.files) {
    diag::SourceManager sources;
    diag::DiagEngine diags(sources);
    const driver::PipelineResult p = driver::run_pipeline(path, inv.load, sources, diags, driver::Goal::Check);
    const driver::FrontendResult& r = p.front;
    const int errors = diags.error_count();
    const int warnings = diags.warning_count();
    std::cout.flush();  // keep stdout and stderr in order when both go to one terminal
    diags.flush(std::cerr);
    if (inv.dump_ast && r.loaded) ast::dump(r.program.modules.front(), std::cout);
    if (errors == 0 && r.loaded) {
      std::cout << path << ": ok" << (warnings > 0 ? " with " + plural(warnings, "warning") : std::string()) << " ("
                << driver::summary(r.program.modules.front(), r.symbols) << ")\n";
    } else {
      std::cout << path << ": " << plural(errors, "error")
                << (warnings > 0 ? ", " + plural(warnings, "warning") : std::string()) << "\n";
      status = kExitErrors;
    }
    std::cout.flush();
  }
  return status;
}

// Parse + build of the main file only (no includes, no checks).
bool load_main(const std::string& path, Invocation& inv, ast::Program& program) {
  diag::SourceManager sources;
  diag::DiagEngine diags(sources);
  build::LoadOptions opts = inv.load;
  opts.follow_includes = false;
  const bool ok = build::load_program(path, opts, sources, diags, program);
  diags.flush(std::cerr);
  return ok;
}

int cmd_fmt(Invocation& inv) {
  if (!inv.in_place && !inv.check_only && inv.files.size() != 1) {
    std::cerr << "ksmc fmt: give one FILE (or use --in-place / --check for several)\n";
    return kExitUsage;
  }
  int status = kExitOk;
  for (const std::string& path : inv.files) {
    ast::Program program;
    if (!load_main(path, inv, program)) {
      status = kExitErrors;
      continue;
    }
    const std::string text = fmt::format_module(program.modules.front());
    if (inv.check_only || inv.in_place) {
      std::string old;
      std::string error;
      build::read_file(path, old, error);
      if (old == text) continue;
      if (inv.check_only) {
        std::cout << path << ": not formatted\n";
        status = kExitErrors;
      } else {
        ksmc::runtime::io::rewrite_file_atomic(path, text);  // through links, mode kept
      }
    } else {
      std::cout << text;
    }
  }
  return status;
}

int cmd_dump_ast(Invocation& inv) {
  int status = kExitOk;
  for (const std::string& path : inv.files) {
    ast::Program program;
    if (!load_main(path, inv, program)) {
      status = kExitErrors;
      continue;
    }
    ast::dump(program.modules.front(), std::cout);
  }
  return status;
}

// Load, check and lower one file; diagnostics go to stderr.
bool lower_file(const std::string& path, Invocation& inv, lower::MlnIr& ir) {
  diag::SourceManager sources;
  diag::DiagEngine diags(sources);
  driver::PipelineResult r = driver::run_pipeline(path, inv.load, sources, diags, driver::Goal::LowerMln);
  diags.flush(std::cerr);
  if (r.ok) ir = std::move(r.mln);
  return r.ok;
}

int cmd_dump_domain_ir(Invocation& inv) {
  int status = kExitOk;
  for (const std::string& path : inv.files) {
    diag::SourceManager sources;
    diag::DiagEngine diags(sources);
    const driver::PipelineResult r = driver::run_pipeline(path, inv.load, sources, diags, driver::Goal::Lower);
    diags.flush(std::cerr);
    if (!r.ok) {
      status = kExitErrors;
      continue;
    }
    lower::dump_domain_ir(r.domain, sources, std::cout);
  }
  return status;
}

int cmd_dump_ir(Invocation& inv) {
  int status = kExitOk;
  for (const std::string& path : inv.files) {
    lower::MlnIr ir;
    if (!lower_file(path, inv, ir)) {
      status = kExitErrors;
      continue;
    }
    lower::dump_ir(ir, std::cout);
  }
  return status;
}

int cmd_emit(Invocation& inv) {
  if (inv.files.size() != 1 || inv.out_dir.empty()) {
    std::cerr << "ksmc emit: give one FILE and --out DIR\n";
    return kExitUsage;
  }
  const std::string& path = inv.files.front();
  diag::SourceManager sources;
  diag::DiagEngine diags(sources);
  const driver::PipelineResult r = driver::run_pipeline(path, inv.load, sources, diags, driver::Goal::Emit);
  diags.flush(std::cerr);
  if (!r.ok) return kExitErrors;
  if (inv.dump_ir) lower::dump_ir(r.mln, std::cout);
  if (inv.dump_domain_ir) lower::dump_domain_ir(r.domain, sources, std::cout);
  const std::vector<emit::GeneratedFile>& files = r.files;
  if (r.domain.kit.empty()) {
    std::cerr << path << ": note: the likelihood is not declared by a stdlib kit (stdlib/<kit>.ksm); "
              << "only the Markov logic factors were generated\n";
  }
  std::error_code ec;
  std::filesystem::create_directories(inv.out_dir, ec);
  if (ec) {
    std::cerr << "ksmc emit: cannot create '" << inv.out_dir << "': " << ec.message() << "\n";
    return kExitErrors;
  }
  for (const emit::GeneratedFile& f : files)
    ksmc::runtime::io::write_file_atomic(std::filesystem::path(inv.out_dir) / f.name, f.text);
  return kExitOk;
}

// --per-formula: one weight per formula instead of w / k per CNF clause (lower/per_formula.h).
bool per_formula(const Invocation& inv, lower::MlnIr& ir) {
  if (!inv.per_formula) return true;
  const std::string error = lower::use_per_formula_weights(ir);
  if (error.empty()) return true;
  std::cerr << error << "\n";
  return false;
}

int cmd_infer(Invocation& inv) {
  if (inv.files.size() != 1 || inv.infer.evidence_path.empty()) {
    std::cerr << "ksmc infer: give one FILE and --evidence E.db\n";
    return kExitUsage;
  }
  lower::MlnIr ir;
  if (!lower_file(inv.files.front(), inv, ir) || !per_formula(inv, ir)) return kExitErrors;
  return infer::run_infer(ir, inv.infer, std::cout, std::cerr);
}

int cmd_learn(Invocation& inv) {
  if (inv.files.empty()) {
    std::cerr << "ksmc learn: give FILE.ksm --data A.db [B.db ...]\n";
    return kExitUsage;
  }
  lower::MlnIr ir;
  if (!lower_file(inv.files.front(), inv, ir) || !per_formula(inv, ir)) return kExitErrors;
  inv.learn.out_path = inv.out_dir;
  inv.learn.per_formula = inv.per_formula;
  if (inv.infer.method != "auto") inv.learn.method = inv.infer.method;
  inv.learn.samples = inv.infer.samples;
  inv.learn.seed = inv.infer.seed;
  return learn::run_learn(ir, inv.files.front(), std::vector<std::string>(inv.files.begin() + 1, inv.files.end()),
                          inv.learn, std::cout, std::cerr);
}

int cmd_build(Invocation& inv) {
  if (inv.files.size() != 1 || inv.out_dir.empty()) {
    std::cerr << "ksmc build: give one FILE and -o BIN\n";
    return kExitUsage;
  }
  driver::BuildRequest request;
  request.file = inv.files.front();
  request.output = inv.out_dir;
  request.keep_dir = inv.keep_dir;
  request.verbose = inv.verbose;
  request.jobs = inv.jobs;
  request.load = inv.load;
  request.executable = inv.executable;
  return driver::run_build(request, std::cout, std::cerr);
}

int cmd_kit(Invocation& inv) {
  if (inv.files.size() != 1) {
    std::cerr << "ksmc kit: give one FILE\n";
    return kExitUsage;
  }
  return driver::run_kit(inv.files.front(), inv.load, std::cout, std::cerr);
}

const std::vector<Command>& commands() {
  static const std::vector<Command> kCommands{
      {"check", "ksmc check [--dump-ast] [-I DIR] FILE...",
       "check domain files; prints one summary line per file", cmd_check},
      {"fmt", "ksmc fmt [--in-place | --check] FILE...", "print FILE in canonical layout (comments kept)", cmd_fmt},
      {"emit", "ksmc emit [--dump-ir] [--dump-domain-ir] FILE --out DIR",
       "write the generated C++ of FILE: DIR/<domain>_factors.{h,cpp}, <domain>_model.{h,cpp}, <domain>_main.cpp", cmd_emit},
      {"infer", "ksmc infer FILE --evidence E.db [--query p,q] [--method exact|gibbs|mcsat|map|auto] [--seed N] [--per-formula]",
       "Markov logic inference without compiling: prints `pred(args) probability`, sorted", cmd_infer},
      {"build", "ksmc build FILE -o BIN [-I DIR] [--keep DIR] [--verbose] [-j N]",
       "compile FILE into the domain binary BIN against the installed ksmc (needs CMake and a C++20 compiler)",
       cmd_build},
      {"import-mln", "ksmc import-mln FILE.mln [--query p,q] [--per-formula] [--out FILE.ksm]",
       "translate an Alchemy rule base into .ksm (the --query predicates are query, the rest evidence)",
       [](Invocation& inv) {
         return alchemy::run_import(inv.files, inv.infer.queries, inv.out_dir, std::cout, std::cerr, inv.per_formula);
       }},
      {"learn", "ksmc learn FILE.ksm --data A.db [B.db ...] [--method pll|cll] [--expectations auto|exact|sampled] [--samples N] [--seed N] [--l2 SIGMA] [--per-formula] [--out FILE]",
       "learn FILE's soft rule weights from training worlds; writes FILE with the new weights (layout kept)",
       cmd_learn},
      {"kit", "ksmc kit FILE", "print `<domain> <kit>`: FILE's domain name and the stdlib kit that runs it", cmd_kit},
  };
  return kCommands;
}

void print_help(std::ostream& out) {
  out << "ksmc " << KSMC_VERSION << " - compiler for knowledge-supervised MCMC domain files\n\n"
      << "usage:\n";
  for (const Command& c : commands()) out << "  " << c.usage << "\n      " << c.summary << "\n";
  out << "  ksmc --dump-ast FILE\n      print the syntax tree of FILE (no checks)\n"
      << "  ksmc --dump-ir FILE\n      print the lowered clause program of FILE (after checking)\n"
      << "  ksmc --dump-domain-ir FILE\n      print the typed domain IR of FILE: every stdlib call with its bound arguments\n"
      << "  ksmc --list-passes\n      list the pipeline stages and passes in order\n\n"
      << "options:\n"
      << "  -I DIR        also search DIR for included files\n"
      << "  --dump-ast    print the syntax tree (with check: after checking)\n"
      << "  --in-place    fmt: rewrite the files instead of printing\n"
      << "  --check       fmt: exit 1 and name the files that are not formatted\n"
      << "  --dump-ir     print the lowered clause program\n"
      << "  --dump-domain-ir  print the typed domain IR (with emit: after emitting)\n"
      << "  --out DIR     emit: the output folder\n"
      << "  -o BIN        build: the binary to write (atomically)\n"
      << "  --keep DIR    build: work folder (generated C++, CMake project, build), kept and reused\n"
      << "  --verbose     build: show the build commands and their output\n"
      << "  -j N          build: parallel compile jobs (default: one per hardware thread)\n"
      << "  --evidence E  infer: the .db evidence file (ground atoms; `type = {A, B}` declares constants)\n"
      << "  --query LIST  infer: comma-separated query predicates to print (default: all)\n"
      << "  --method M    infer: exact, gibbs, mcsat, map or auto (default auto)\n"
      << "  --seed N      infer: random seed of the sampling engines (default 1)\n"
      << "  --samples N   infer: samples of gibbs / mcsat\n"
      << "  --burn-in N   infer: burn-in of gibbs / mcsat\n"
      << "  --result F    infer: also write the marginals to F in Alchemy's .result format\n"
      << "  --max-ground-clauses N  infer: refuse a grounding estimated above N clauses (default 50,000,000)\n"
      << "  --data        learn: the files that follow are training worlds (.db)\n"
      << "  --l2 SIGMA    learn: standard deviation of the Gaussian prior on the weights (default 10)\n"
      << "  --expectations E  learn --method cll: expected clause counts by exact inference (exact), from\n"
      << "                MC-SAT samples (sampled, --samples per gradient, default 1000, --seed), or exact\n"
      << "                where it applies to every training network, sampled otherwise (auto, default)\n"
      << "  --per-formula infer, learn, import-mln: a soft formula's weight counts once when the whole formula\n"
      << "                holds (default: split as w/k over its k CNF clauses, as Alchemy does)\n"
      << "  --help        this text\n"
      << "  --version     print the version\n\n"
      << "exit status: 0 ok, 1 errors in the input, 2 bad usage, 3 internal compiler error\n";
}

int run(int argc, char** argv) {
  Invocation inv;
  const Command* command = nullptr;
  bool list_passes = false;
  std::vector<std::string> args(argv + 1, argv + argc);
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--help" || a == "-h") {
      print_help(std::cout);
      return kExitOk;
    }
    if (a == "--version") {
      std::cout << "ksmc " << KSMC_VERSION << "\n";
      return kExitOk;
    }
    // Options that take a value.
    static const std::vector<std::string> kValued{"--out", "-o", "--evidence", "--query", "--method",
                                                  "--seed", "--samples", "--burn-in", "--keep", "-j",
                                                  "--result", "--l2", "--max-ground-clauses", "--expectations"};
    if (std::find(kValued.begin(), kValued.end(), a) != kValued.end()) {
      if (i + 1 >= args.size()) {
        std::cerr << "ksmc: " << a << " needs a value\n";
        return kExitUsage;
      }
      const std::string& v = args[++i];
      try {
        if (a == "--out" || a == "-o") inv.out_dir = v;
        else if (a == "--evidence") inv.infer.evidence_path = v;
        else if (a == "--method") inv.infer.method = v;
        else if (a == "--seed") inv.infer.seed = std::stoull(v);
        else if (a == "--samples") inv.infer.samples = infer::parse_count(v);
        else if (a == "--burn-in") inv.infer.burn_in = infer::parse_count(v);
        else if (a == "--result") inv.infer.result_path = v;
        else if (a == "--max-ground-clauses") inv.infer.max_ground_clauses = infer::parse_count(v);
        else if (a == "--l2") inv.learn.prior_sigma = std::stod(v);
        else if (a == "--expectations") inv.learn.expectations = v;
        else if (a == "--keep") inv.keep_dir = v;
        else if (a == "-j") {
          std::size_t used = 0;
          inv.jobs = std::stoi(v, &used);
          if (used != v.size() || inv.jobs < 1) throw std::invalid_argument(v);
        }
        else {  // --query
          std::size_t start = 0;
          while (start <= v.size()) {
            const std::size_t comma = std::min(v.find(',', start), v.size());
            if (comma > start) inv.infer.queries.push_back(v.substr(start, comma - start));
            start = comma + 1;
          }
        }
      } catch (const std::exception&) {
        std::cerr << "ksmc: " << a << ": '" << v << "' is not a " << (a == "-j" ? "positive " : "") << "number\n";
        return kExitUsage;
      }
      continue;
    }
    if (a == "--dump-ast") {
      inv.dump_ast = true;
    } else if (a == "--dump-ir") {
      inv.dump_ir = true;
    } else if (a == "--dump-domain-ir") {
      inv.dump_domain_ir = true;
    } else if (a == "--in-place") {
      inv.in_place = true;
    } else if (a == "--check") {
      inv.check_only = true;
    } else if (a == "--verbose") {
      inv.verbose = true;
    } else if (a == "--per-formula") {
      inv.per_formula = true;
    } else if (a == "--data") {
      // learn: the files that follow are training worlds (they are positional anyway)
    } else if (a == "--list-passes") {
      list_passes = true;
    } else if (a == "-I") {
      if (i + 1 >= args.size()) {
        std::cerr << "ksmc: -I needs a directory\n";
        return kExitUsage;
      }
      inv.load.include_dirs.push_back(args[++i]);
    } else if (a.rfind("-I", 0) == 0 && a.size() > 2) {
      inv.load.include_dirs.push_back(a.substr(2));
    } else if (a.size() > 1 && a[0] == '-') {
      std::cerr << "ksmc: unknown option '" << a << "' (see ksmc --help)\n";
      return kExitUsage;
    } else if (command == nullptr && inv.files.empty() && !inv.dump_ast && !inv.dump_ir && !inv.dump_domain_ir) {
      for (const Command& c : commands()) {
        if (a == c.name) command = &c;
      }
      if (command == nullptr) {
        std::cerr << "ksmc: unknown command '" << a << "' (see ksmc --help)\n";
        return kExitUsage;
      }
    } else {
      inv.files.push_back(a);
    }
  }
  // An installed ksmc (P/bin/ksmc) also searches P/share/ksmc, after the -I dirs, so
  // `include "stdlib/x.ksm"` works anywhere. A build tree has no such folder.
  inv.executable = driver::self_executable(argc > 0 ? argv[0] : nullptr);
  if (const auto root = driver::installed_stdlib_root(inv.executable)) inv.load.include_dirs.push_back(root->string());
  if (list_passes) {
    for (const std::string& p : driver::pass_names()) std::cout << p << "\n";
    return kExitOk;
  }
  if (command == nullptr && !inv.dump_ast && !inv.dump_ir && !inv.dump_domain_ir) {
    print_help(std::cerr);
    return kExitUsage;
  }
  if (inv.files.empty()) {
    std::cerr << "ksmc: no input files (see ksmc --help)\n";
    return kExitUsage;
  }
  if (command == nullptr) {
    if (inv.dump_domain_ir) return cmd_dump_domain_ir(inv);
    return inv.dump_ir ? cmd_dump_ir(inv) : cmd_dump_ast(inv);
  }
  return command->run(inv);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "ksmc: internal compiler error: " << e.what() << "\n";
  } catch (...) {
    std::cerr << "ksmc: internal compiler error: unknown exception\n";
  }
  return kExitInternal;
}
