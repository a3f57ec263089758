// libFuzzer target: the .ksm front end reading real files and following includes.
// Input: main.ksm, then optionally more files, each after a line "//@file <name>" (a
// relative name); they are written to a scratch folder and `include "<name>";` finds them.
// The standard library is not on the include path: a stdlib include costs ~0.4 s per run
// under the sanitizers (the seeds from domains/ bring its text in as plain files instead).
// Any crash, sanitizer report or uncaught exception is a bug.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "compiler/driver/pipeline.h"
#include "compiler/fuzz/fuzz_files.h"
#include "compiler/parse/parser.h"

#ifndef KSMC_ROOT_DIR
#error "KSMC_ROOT_DIR must name the repository root"
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ksmc::compiler;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  ksmc::fuzz::write_scratch(ksmc::fuzz::split_files(bytes, "//@file ", "main.ksm"));
  diag::SourceManager sources;
  diag::DiagEngine diags(sources);
  build::LoadOptions opts;
  opts.follow_includes = true;
  driver::FrontendResult r = driver::run_frontend((ksmc::fuzz::scratch_dir() / "main.ksm").string(), opts, sources, diags);
  std::ostringstream sink;
  diags.flush(sink);
  (void)r;
  static const unsigned every = ksmc::fuzz::clear_caches_every();
  static unsigned runs = 0;
  if (every != 0 && ++runs % every == 0) ksmc::compiler::parse::clear_prediction_caches();  // see docs/reliability.md
  return 0;
}
