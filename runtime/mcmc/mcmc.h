// Umbrella header of the MH runtime, for generated domain code.
#pragma once

#include "runtime/mcmc/engine.h"
#include "runtime/mcmc/model.h"
#include "runtime/mcmc/results.h"
#include "runtime/mcmc/rng.h"
#include "runtime/mcmc/schedule.h"
