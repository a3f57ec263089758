// Signal handling for domain runs (runtime/io/cancel.h): SIGINT, SIGTERM and SIGHUP set
// the cancel request the engine polls before every iteration (kits and the Markov logic
// runtime may poll it too, io::cancel_requested()); the run stops cleanly, the complete
// outputs of the best state so far are written with "interrupted": "<signal>" in
// summary.json, and the exit code is 128 + the signal (130, 143, 129). The handler stays
// installed, so further signals while the outputs are written do not kill the process.
#pragma once

#include <atomic>
#include <string>

#include "runtime/io/cancel.h"

namespace ksmc::runtime::cli {

class InterruptGuard {
 public:
  InterruptGuard() = default;  // clears the request and installs the handlers
  ~InterruptGuard() = default;  // restores the previous handlers
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  static const std::atomic<bool>& flag() noexcept { return io::cancel_flag(); }
  static bool interrupted() noexcept { return io::cancel_requested(); }
  static int signal_number() noexcept { return io::cancel_signal(); }
  static std::string signal_name() { return io::signal_name(io::cancel_signal()); }
  static int exit_code() noexcept { return io::interrupted_exit_code(io::cancel_signal()); }

 private:
  io::SignalGuard guard_;
};

}  // namespace ksmc::runtime::cli
