#include "runtime/cli/input_adapter.h"

namespace ksmc::runtime::cli {

std::vector<InputAdapter>& input_adapters() {
  static std::vector<InputAdapter> adapters;
  return adapters;
}

}  // namespace ksmc::runtime::cli
