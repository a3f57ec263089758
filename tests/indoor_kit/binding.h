// The generated Markov logic part of domains/indoor.ksm as the kit's MlnBinding.
#pragma once

#include "indoor_factors.h"
#include "runtime/domain/config.h"

namespace ksmc::tests::indoor_kit {

inline ksmc::runtime::domain::MlnBinding indoor_binding() {
  return {&ksmc_generated::indoor::program, &ksmc_generated::indoor::make_domain, &ksmc_generated::indoor::ground};
}

}  // namespace ksmc::tests::indoor_kit
