// `ksmc emit`, second half: the binding of a domain to its stdlib kit (docs/binding.md §3).
//
//   <domain>_model.h/.cpp  binding(): a blocks::Binding of the kit filled from the domain file:
//                          per `extract` a function calling the extractor it names, per
//                          conditional prior a term function, and one statement per prior,
//                          likelihood, output, kernel direction and schedule row, calling the
//                          kit's blocks directly with their arguments bound in signature order,
//                          defaults filled in, numbers in base units.
//   <domain>_main.cpp      the entry point: the common domain CLI over the kit's domain_spec().
//
// Names come from the domain file only; no source line numbers appear (comments and text
// fields hold the item as written), so an edit changes only the lines of the edited item.
#pragma once

#include <string>

#include "compiler/emit/emit_factors.h"
#include "compiler/lower/domain_ir.h"

namespace ksmc::compiler::emit {

struct ModelOutput {
  GeneratedFile header;
  GeneratedFile source;
  GeneratedFile main;
};

// The binding of the domain in `ir` to its kit `ir.kit` (non-empty).
ModelOutput emit_model(const lower::DomainIr& ir);

}  // namespace ksmc::compiler::emit
