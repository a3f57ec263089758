// The entry point generated <domain>_main.cpp includes for a domain run by the table-top
// kit (docs/binding.md §3): domain_spec(binding()).
#pragma once

#include "stdlib/tabletop/kit/domain_spec.h"
