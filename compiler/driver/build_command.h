// `ksmc build FILE -o BIN` and `ksmc kit FILE`.
//
// build: checks FILE (diagnostics as usual), emits the generated C++ into a work folder,
// writes a small CMake project there that finds the installed ksmc package
// (P/lib/cmake/ksmc next to P/bin/ksmc) and links the domain's stdlib kit, runs CMake's
// configure and build with the system C++ compiler, and copies the binary to BIN
// atomically (a temporary sibling renamed over BIN). One summary line on stdout; the
// build tools' output goes to stderr with --verbose, else only when they fail.
//
// kit: prints `<domain> <kit>` (the domain name, which names the generated files, and the
// stdlib kit that runs it) — what ksmc_add_domain of the installed package asks.
#pragma once

#include <filesystem>
#include <ostream>
#include <string>

#include "compiler/build/loader.h"

namespace ksmc::compiler::driver {

struct BuildRequest {
  std::string file;                  // the domain file
  std::string output;                // -o BIN
  std::string keep_dir;              // --keep DIR: work folder kept (and reused); "" = temporary
  bool verbose = false;              // --verbose: show the commands and the tools' output
  int jobs = 0;                      // -j N; 0 = one per hardware thread
  build::LoadOptions load;           // -I dirs (and the installed stdlib root)
  std::filesystem::path executable;  // this ksmc (locates the installed package)
};

// Exit status: 0 built, 1 errors in FILE or a failed build, 2 bad usage, 130 interrupted
// (Ctrl-C; the temporary work folder is removed).
int run_build(const BuildRequest& request, std::ostream& out, std::ostream& err);

// Exit status: 0 printed, 1 errors in FILE or no kit runs it.
int run_kit(const std::string& file, const build::LoadOptions& load, std::ostream& out, std::ostream& err);

}  // namespace ksmc::compiler::driver
