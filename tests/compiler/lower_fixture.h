// Runs the front end and the lowering on domain text given in a test.
#pragma once

#include <sstream>
#include <string>

#include "compiler/driver/pipeline.h"
#include "compiler/lower/lower_mln.h"

namespace ksmc::tests {

struct Lowered {
  compiler::lower::MlnIr ir;
  bool ok = false;
  std::string diagnostics;
};

inline Lowered lower_text(const std::string& text, const std::string& path = "test.ksm") {
  using namespace ksmc::compiler;
  Lowered out;
  diag::SourceManager sources;
  diag::DiagEngine diags(sources);
  build::LoadOptions options;
  driver::FrontendResult r = driver::run_frontend(path, options, sources, diags, &text);
  if (r.ok) out.ok = lower::lower_mln(r.program, r.symbols, sources, diags, out.ir);
  std::ostringstream ss;
  diags.flush(ss);
  out.diagnostics = ss.str();
  return out;
}

}  // namespace ksmc::tests
