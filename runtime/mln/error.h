// The one exception type of the Markov logic runtime: bad programs, bad evidence,
// unsatisfiable hard rules and networks too large for the requested engine.
#pragma once

#include <stdexcept>
#include <string>

namespace ksmc::runtime::mln {

class MlnError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace ksmc::runtime::mln
