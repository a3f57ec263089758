// The entry point generated <domain>_main.cpp includes for a domain run by the table-top
// kit (see compiler/emit/emit_model.h): domain_spec(config, mln_binding).
#pragma once

#include "stdlib/tabletop/kit/domain_spec.h"
