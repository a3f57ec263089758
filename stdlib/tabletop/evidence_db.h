// Evidence as Alchemy/pracmln `.db` text (one ground atom per line, `!` for false),
// the format runtime/mln's parse_db reads. Closed world written out: every ground
// atom of the six evidence predicates over all bodies is listed, true or negated,
// because atoms a .db file leaves out are read as unknown.
#pragma once

#include <string>

#include "stdlib/tabletop/evidence.h"

namespace ksmc::stdlib::tabletop {

// Throws std::invalid_argument naming the id when a constant is not a valid .db
// name (letters, digits, '_', '-', '.').
std::string evidence_db(const Evidence& ev);

}  // namespace ksmc::stdlib::tabletop
