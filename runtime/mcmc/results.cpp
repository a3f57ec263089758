#include "runtime/mcmc/results.h"

namespace ksmc::runtime::mcmc {

std::uint64_t ChainResult::accepted() const noexcept {
  std::uint64_t n = 0;
  for (const KernelStats& k : kernels) n += k.accepted;
  return n;
}

double RunResult::acceptance_rate() const noexcept {
  std::uint64_t selected = 0;
  std::uint64_t accepted = 0;
  for (const KernelStats& k : kernels) {
    selected += k.selected;
    accepted += k.accepted;
  }
  return selected == 0 ? 0.0 : static_cast<double>(accepted) / static_cast<double>(selected);
}

}  // namespace ksmc::runtime::mcmc
