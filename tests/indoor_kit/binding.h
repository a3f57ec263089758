// The generated binding of domains/indoor.ksm (indoor_model.h, indoor_factors.h of
// emit_binding.cmake): the kit tests run it as bin/indoor does, or a copy they change
// (other kernels, lenient types, conditional priors).
#pragma once

#include "indoor_factors.h"
#include "indoor_model.h"
#include "stdlib/indoor/blocks.h"

namespace ksmc::tests::indoor_kit {

namespace blk = ksmc::stdlib::indoor::blocks;
namespace dom = ksmc::runtime::domain;
namespace gen = ksmc_generated::indoor;

inline blk::Binding indoor_binding() { return gen::binding(); }

}  // namespace ksmc::tests::indoor_kit
