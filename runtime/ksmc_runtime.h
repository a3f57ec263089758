// The one header generated code includes: everything of the runtime a domain needs.
#pragma once

#include <cstdint>

#include "runtime/mln/error.h"
#include "runtime/mln/evidence.h"
#include "runtime/mln/factor_context.h"
#include "runtime/mln/ground_network.h"
#include "runtime/mln/grounder.h"
#include "runtime/mln/program.h"
