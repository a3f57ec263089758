// Entry header of the table-top kit, included by the generated <domain>_main.cpp:
//   ksmc::stdlib::tabletop::kit::domain_spec(domain_config(), mln_binding())
#pragma once

#include "stdlib/tabletop/kit/domain_spec.h"
