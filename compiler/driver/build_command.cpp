#include "compiler/driver/build_command.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <optional>
#include <sstream>
#include <system_error>
#include <thread>
#include <vector>

#include "compiler/driver/install_layout.h"
#include "compiler/driver/pipeline.h"
#include "compiler/driver/subprocess.h"
#include "compiler/emit/emit_factors.h"
#include "runtime/io/atomic_file.h"

#ifndef KSMC_VERSION
#define KSMC_VERSION "unknown"
#endif
#ifndef KSMC_FALLBACK_CMAKE
#define KSMC_FALLBACK_CMAKE ""
#endif

namespace ksmc::compiler::driver {

namespace fs = std::filesystem;

namespace {

constexpr int kOk = 0;
constexpr int kErrors = 1;
constexpr int kUsage = 2;

// The checked, lowered and emitted domain.
struct EmittedDomain {
  std::string domain;  // names the generated files: <domain>_factors.h, ...
  std::string kit;     // "" when no stdlib kit declares the likelihood
  std::vector<emit::GeneratedFile> files;
};

// Check + lower + emit of `path`; diagnostics go to `err`. False on errors in the file.
bool emit_domain(const std::string& path, const build::LoadOptions& load, std::ostream& err, EmittedDomain& out) {
  diag::SourceManager sources;
  diag::DiagEngine diags(sources);
  PipelineResult r = run_pipeline(path, load, sources, diags, Goal::Emit);
  diags.flush(err);
  if (!r.ok) return false;
  const std::string suffix = "_factors.h";
  const std::string& header = r.files.front().name;
  out.domain = header.substr(0, header.size() - suffix.size());
  out.kit = r.domain.kit;
  out.files = std::move(r.files);
  return true;
}

void report_no_kit(const std::string& path, std::ostream& err) {
  err << path << ": error: the likelihood is not declared by a stdlib kit (stdlib/<kit>.ksm), "
      << "so there is no runtime to build this domain against\n";
}

bool read_text(const fs::path& path, std::string& text) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream ss;
  ss << in.rdbuf();
  text = ss.str();
  return true;
}

// Writes `text` unless the file already holds it (a kept work folder rebuilds only what changed).
void write_if_changed(const fs::path& path, const std::string& text) {
  std::string old;
  if (read_text(path, old) && old == text) return;
  runtime::io::write_file_atomic(path, text);
}

// A CMake quoted argument.
std::string cmake_quote(const std::string& s) {
  std::string q = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\' || c == '$' || c == ';') q += '\\';
    q += c;
  }
  return q + "\"";
}

std::string project_text(const EmittedDomain& d, const fs::path& prefix, const std::string& file) {
  const std::string& n = d.domain;
  std::ostringstream o;
  o << "# Written by `ksmc build` for " << file << " (rewritten on every run).\n"
    << "cmake_minimum_required(VERSION 3.22)\n"
    << "project(ksmc_build_" << n << " LANGUAGES CXX)\n"
    << "set(CMAKE_CXX_EXTENSIONS OFF)\n"
    << "set(CMAKE_CXX_FLAGS_RELEASE \"-O2 -DNDEBUG\")  # as the ksmc build (RelWithDebInfo without -g)\n"
    << "find_package(ksmc " << KSMC_VERSION << " EXACT REQUIRED CONFIG PATHS " << cmake_quote(prefix.string())
    << " NO_DEFAULT_PATH)\n"
    << "add_executable(" << n << " src/" << n << "_factors.cpp src/" << n << "_model.cpp src/" << n << "_main.cpp)\n"
    << "target_include_directories(" << n << " PRIVATE src)\n"
    << "target_link_libraries(" << n << " PRIVATE ksmc::stdlib_" << d.kit << "_kit ksmc::runtime_cli "
    << "ksmc::runtime_domain)\n"
    << "# A faster linker when there is one (GNU ld takes ~2 s on the static libraries).\n"
    << "find_program(KSMC_LD_LLD ld.lld)\n"
    << "find_program(KSMC_LD_GOLD ld.gold)\n"
    << "if(CMAKE_CXX_COMPILER_ID MATCHES \"GNU|Clang\" AND KSMC_LD_LLD)\n"
    << "  target_link_options(" << n << " PRIVATE -fuse-ld=lld)\n"
    << "elseif(CMAKE_CXX_COMPILER_ID STREQUAL \"GNU\" AND KSMC_LD_GOLD)\n"
    << "  target_link_options(" << n << " PRIVATE -fuse-ld=gold)\n"
    << "endif()\n";
  return o.str();
}

// The installed package has the kit's library target.
bool package_has_kit(const fs::path& package_dir, const std::string& kit) {
  std::string targets;
  if (!read_text(package_dir / "ksmcTargets.cmake", targets)) return false;
  return targets.find("add_library(ksmc::stdlib_" + kit + "_kit ") != std::string::npos;
}

std::optional<fs::path> find_cmake() {
  if (auto p = find_on_path("cmake")) return p;
  const fs::path fallback = KSMC_FALLBACK_CMAKE;
  std::error_code ec;
  if (!fallback.empty() && fs::is_regular_file(fallback, ec)) return fallback;
  return std::nullopt;
}

// A fresh folder under the system temp folder.
std::optional<fs::path> make_temp_dir(std::string& error) {
  std::error_code ec;
  const fs::path base = fs::temp_directory_path(ec);
  if (ec) {
    error = ec.message();
    return std::nullopt;
  }
  std::string templ = (base / "ksmc-build-XXXXXX").string();
  if (::mkdtemp(templ.data()) == nullptr) {
    error = "cannot create a folder under " + base.string();
    return std::nullopt;
  }
  return fs::path(templ);
}

std::string shell_line(const std::vector<std::string>& argv) {
  std::string line;
  for (const std::string& a : argv) {
    if (!line.empty()) line += ' ';
    line += a.find_first_of(" \t\"'") == std::string::npos ? a : "'" + a + "'";
  }
  return line;
}

// Removes the temporary work folder when the build is over (kept folders stay).
struct WorkDir {
  fs::path path;
  bool temporary = false;
  WorkDir() = default;
  WorkDir(const WorkDir&) = delete;
  WorkDir& operator=(const WorkDir&) = delete;
  ~WorkDir() {
    if (!temporary) return;
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

// Copies `from` to `to` through a temporary sibling renamed over `to`.
bool install_binary(const fs::path& from, const fs::path& to, std::string& error) {
  const fs::path tmp = to.parent_path() / ("." + to.filename().string() + ".ksmc-build-" + std::to_string(::getpid()));
  std::error_code ec;
  fs::copy_file(from, tmp, fs::copy_options::overwrite_existing, ec);
  if (!ec) {
    fs::permissions(tmp,
                    fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec | fs::perms::others_read |
                        fs::perms::others_exec,
                    ec);
  }
  if (!ec) fs::rename(tmp, to, ec);
  if (ec) {
    error = ec.message();
    std::error_code ignored;
    fs::remove(tmp, ignored);
    return false;
  }
  return true;
}

}  // namespace

int run_kit(const std::string& file, const build::LoadOptions& load, std::ostream& out, std::ostream& err) {
  EmittedDomain d;
  if (!emit_domain(file, load, err, d)) return kErrors;
  if (d.kit.empty()) {
    report_no_kit(file, err);
    return kErrors;
  }
  out << d.domain << " " << d.kit << "\n";
  return kOk;
}

int run_build(const BuildRequest& request, std::ostream& out, std::ostream& err) {
  const auto start = std::chrono::steady_clock::now();
  if (request.file.empty() || request.output.empty()) {
    err << "ksmc build: give one FILE and -o BIN\n";
    return kUsage;
  }
  std::error_code ec;
  const fs::path output = fs::absolute(request.output, ec).lexically_normal();
  if (ec || output.filename().empty()) {
    err << "ksmc build: -o '" << request.output << "' does not name a file\n";
    return kUsage;
  }
  if (fs::is_directory(output, ec)) {
    err << "ksmc build: -o '" << request.output << "' is a folder; give the binary's file name\n";
    return kUsage;
  }

  EmittedDomain d;
  if (!emit_domain(request.file, request.load, err, d)) return kErrors;
  if (d.kit.empty()) {
    report_no_kit(request.file, err);
    return kErrors;
  }

  const std::optional<fs::path> package_dir = installed_package_dir(request.executable);
  if (!package_dir) {
    const fs::path prefix = install_prefix_of(request.executable);
    err << "ksmc build: needs an installed ksmc, and " << request.executable.string()
        << " is not one (no " << (prefix / "lib/cmake/ksmc/ksmcConfig.cmake").string() << ").\n"
        << "  Install it with `cmake --install <build-dir> --prefix P` and run P/bin/ksmc build;\n"
        << "  inside the source tree, use ksmc_add_domain() in CMake instead.\n";
    return kErrors;
  }
  const fs::path prefix = install_prefix_of(request.executable);
  if (!package_has_kit(*package_dir, d.kit)) {
    err << "ksmc build: " << request.file << " runs on the stdlib kit '" << d.kit
        << "', which the installed ksmc at " << prefix.string() << " does not have\n";
    return kErrors;
  }
  const std::optional<fs::path> cmake = find_cmake();
  if (!cmake) {
    err << "ksmc build: cmake not found on PATH; ksmc build needs CMake (3.22 or newer) and a C++20 compiler\n";
    return kErrors;
  }

  WorkDir work;
  if (!request.keep_dir.empty()) {
    work.path = fs::absolute(request.keep_dir, ec).lexically_normal();
    if (!ec) fs::create_directories(work.path / "src", ec);
    if (ec) {
      err << "ksmc build: cannot create the work folder '" << request.keep_dir << "': " << ec.message() << "\n";
      return kErrors;
    }
  } else {
    std::string error;
    const std::optional<fs::path> tmp = make_temp_dir(error);
    if (!tmp) {
      err << "ksmc build: cannot create a work folder: " << error << "\n";
      return kErrors;
    }
    work.path = *tmp;
    work.temporary = true;
    fs::create_directories(work.path / "src", ec);
  }
  try {
    for (const emit::GeneratedFile& f : d.files) write_if_changed(work.path / "src" / f.name, f.text);
    write_if_changed(work.path / "CMakeLists.txt", project_text(d, prefix, request.file));
  } catch (const std::exception& e) {
    err << "ksmc build: " << e.what() << "\n";
    return kErrors;
  }

  const fs::path build_dir = work.path / "build";
  const fs::path log = work.path / "build.log";
  fs::remove(log, ec);
  const int jobs = request.jobs > 0 ? request.jobs : static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
  const std::vector<std::vector<std::string>> steps{
      {cmake->string(), "-S", work.path.string(), "-B", build_dir.string(), "-DCMAKE_BUILD_TYPE=Release"},
      {cmake->string(), "--build", build_dir.string(), "-j", std::to_string(jobs)},
  };
  const char* const step_names[] = {"configuring", "compiling"};
  for (std::size_t i = 0; i < steps.size(); ++i) {
    if (request.verbose) err << "ksmc build: " << shell_line(steps[i]) << "\n" << std::flush;
    const ProcessResult r = run_process(steps[i], request.verbose ? std::nullopt : std::optional<fs::path>(log));
    if (!r.started) {
      err << "ksmc build: cannot run " << steps[i].front() << ": " << r.error << "\n";
      return kErrors;
    }
    if (r.exit_code == kExitInterrupted) {
      err << "ksmc build: interrupted\n";
      return kExitInterrupted;
    }
    if (r.exit_code != 0) {
      std::string text;
      if (!request.verbose) read_text(log, text);
      err << "ksmc build: " << step_names[i] << " " << request.file << " failed (exit " << r.exit_code << ")";
      if (i == 0 && (request.verbose || text.find("CMAKE_CXX_COMPILER") != std::string::npos ||
                     text.find("is not able to compile") != std::string::npos)) {
        err << "; is a C++20 compiler installed? (CXX selects one)";
      }
      if (!request.verbose) {
        err << "; build output:\n" << text;
        if (!text.empty() && text.back() != '\n') err << "\n";
      } else {
        err << "\n";
      }
      if (!work.temporary) err << "ksmc build: work folder kept at " << work.path.string() << "\n";
      return kErrors;
    }
  }

  const fs::path built = build_dir / d.domain;
  if (!fs::is_regular_file(built, ec)) {
    err << "ksmc build: the build finished but " << built.string() << " is missing\n";
    return kErrors;
  }
  fs::create_directories(output.parent_path(), ec);
  std::string error;
  if (!install_binary(built, output, error)) {
    err << "ksmc build: cannot write " << request.output << ": " << error << "\n";
    return kErrors;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  char when[32];
  std::snprintf(when, sizeof when, "%.1f", seconds);
  out << "ksmc build: " << request.output << " (domain " << d.domain << ", kit " << d.kit << ") in " << when
      << " s\n";
  return kOk;
}

}  // namespace ksmc::compiler::driver
