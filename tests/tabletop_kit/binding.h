// The generated Markov logic part of domains/tabletop.ksm as the kit's MlnBinding.
#pragma once

#include "runtime/domain/config.h"
#include "tabletop_factors.h"

namespace ksmc::tests::tabletop_kit {

inline ksmc::runtime::domain::MlnBinding tabletop_binding() {
  return {&ksmc_generated::tabletop::program, &ksmc_generated::tabletop::make_domain,
          &ksmc_generated::tabletop::ground};
}

}  // namespace ksmc::tests::tabletop_kit
