// `ksmc --dump-domain-ir`: the typed domain IR as stable text, one item per line and one
// bound argument per indented line, with source locations (path:line:col) and values in
// base units next to their source spelling.
#pragma once

#include <ostream>

#include "compiler/diag/source_manager.h"
#include "compiler/lower/domain_ir.h"

namespace ksmc::compiler::lower {

void dump_domain_ir(const DomainIr& ir, const diag::SourceManager& sources, std::ostream& out);

}  // namespace ksmc::compiler::lower
