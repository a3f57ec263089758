// Ctrl-C handling for domain runs: the first SIGINT sets a flag the engine polls (the
// run stops cleanly and outputs are written); the handler then resets itself, so a
// second Ctrl-C terminates the process the usual way.
#pragma once

#include <atomic>
#include <memory>

namespace ksmc::runtime::cli {

class InterruptGuard {
 public:
  InterruptGuard();   // clears the flag and installs the handler
  ~InterruptGuard();  // restores the previous handler
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  static const std::atomic<bool>& flag() noexcept;
  static bool interrupted() noexcept { return flag().load(); }

 private:
  struct Saved;
  std::unique_ptr<Saved> saved_;
};

}  // namespace ksmc::runtime::cli
