// libFuzzer target: the Alchemy / pracmln .mln reader of `ksmc import-mln`
// (compiler/alchemy), with both weight semantics. Bad input must come back as located
// errors; a crash, sanitizer report or exception is a bug. When the import succeeds, the
// .ksm it wrote must load and check in the front end (the property the command promises:
// `ksmc infer` reads what `import-mln` writes); a .ksm that does not is reported and aborts.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>

#include "compiler/alchemy/mln_import.h"
#include "compiler/build/loader.h"
#include "compiler/driver/pipeline.h"
#include "compiler/fuzz/fuzz_files.h"
#include "compiler/parse/parser.h"

namespace {

using namespace ksmc::compiler;

void check_output(const std::string& mln, const std::string& ksm, bool per_formula) {
  diag::SourceManager sources;
  diag::DiagEngine diags(sources);
  build::LoadOptions opts;
  opts.follow_includes = false;
  const driver::FrontendResult r = driver::run_frontend("fuzz.ksm", opts, sources, diags, &ksm);
  if (r.ok) return;
  std::ostringstream messages;
  diags.flush(messages);
  std::cerr << "import-mln wrote a .ksm the front end rejects (per_formula " << per_formula << ")\n--- mln\n"
            << mln << "\n--- ksm\n" << ksm << "\n--- diagnostics\n" << messages.str() << "\n";
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const unsigned every = ksmc::fuzz::clear_caches_every();
  static unsigned runs = 0;
  if (every != 0 && ++runs % every == 0) parse::clear_prediction_caches();
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (const bool per_formula : {false, true}) {
    const alchemy::ImportResult r = alchemy::import_mln(text, "fuzz.mln", {}, per_formula);
    if (r.errors.empty()) check_output(text, r.ksm, per_formula);
  }
  return 0;
}
