// The one error a stdlib kit throws for a configuration it cannot run. `ksmc check` enforces
// the kit contract declared in stdlib/<kit>.ksm, so a ConfigError reaching a domain binary is
// an internal error: runtime/cli reports it as such (exit 3) and never aborts. Header-only
// and dependency-free so the CLI can catch it without linking the domain layer.
#pragma once

#include <stdexcept>

namespace ksmc::runtime::domain {

class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace ksmc::runtime::domain
