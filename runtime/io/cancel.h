// Cooperative cancellation of a run. SIGINT, SIGTERM and SIGHUP (while a SignalGuard is
// alive) or a test set a process-wide request; long computations poll it and stop at
// their next step: the MCMC engine before every iteration, `ksmc build` between steps,
// and any kit or Markov logic routine that calls cancel_requested() / throw_if_cancelled()
// in its loops (model construction, initial inference, map reading).
//
// The request is a lock-free atomic, so polling costs one relaxed load. Further signals
// while outputs are being written only set the flag again: they never kill the process
// mid-write (use SIGKILL to force it).
#pragma once

#include <atomic>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>

#include <sys/types.h>

namespace ksmc::runtime::io {

namespace detail {
inline std::atomic<bool> g_cancel_requested{false};
inline std::atomic<int> g_cancel_signal{0};  // the first signal received, 0 = none or not a signal
inline std::atomic<int> g_shields{0};        // live CancelShield objects
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free,
              "signal handlers need lock-free atomics");
}  // namespace detail

// The flag itself (for mcmc::EngineConfig::cancel).
inline const std::atomic<bool>& cancel_flag() noexcept { return detail::g_cancel_requested; }
inline bool cancel_requested() noexcept { return detail::g_cancel_requested.load(std::memory_order_relaxed); }
// The first signal that requested cancellation (SIGINT, SIGTERM, SIGHUP), or 0.
inline int cancel_signal() noexcept { return detail::g_cancel_signal.load(std::memory_order_relaxed); }

// Async-signal-safe. The first signal number is kept; 0 = a request that is not a signal.
inline void request_cancel(int signal_number = 0) noexcept {
  int none = 0;
  if (signal_number != 0) detail::g_cancel_signal.compare_exchange_strong(none, signal_number);
  detail::g_cancel_requested.store(true);
}
inline void clear_cancel() noexcept {
  detail::g_cancel_signal.store(0);
  detail::g_cancel_requested.store(false);
}

// "SIGINT", "SIGTERM", "SIGHUP", "signal N"; "cancelled" for 0.
std::string signal_name(int signal_number);
// The conventional exit code of a run stopped by the signal: 128 + N (130 for 0).
int interrupted_exit_code(int signal_number) noexcept;

// Thrown by throw_if_cancelled: a computation gave up because cancellation was requested.
class Cancelled : public std::runtime_error {
 public:
  explicit Cancelled(std::string_view where);
};

// Whether a long computation should stop now: a request is set and no CancelShield is alive.
inline bool stop_requested() noexcept {
  return cancel_requested() && detail::g_shields.load(std::memory_order_relaxed) == 0;
}

// Polls the request; throws Cancelled("<where>: interrupted by SIGTERM") when it is set
// (and no CancelShield is alive).
inline void throw_if_cancelled(std::string_view where) {
  if (stop_requested()) throw Cancelled(where);
}

// While one is alive (any thread), stop_requested() and throw_if_cancelled() ignore the
// request: the run has already stopped and the outputs of its best state are being
// computed and written (which may run inference again); the request itself stays set.
class CancelShield {
 public:
  CancelShield() noexcept { detail::g_shields.fetch_add(1); }
  ~CancelShield() { detail::g_shields.fetch_sub(1); }
  CancelShield(const CancelShield&) = delete;
  CancelShield& operator=(const CancelShield&) = delete;
};

// Installs the cancelling handler for SIGINT, SIGTERM and SIGHUP (SA_RESTART, no
// SA_RESETHAND: every further signal only sets the flag again) and, if `clear`, clears the
// request; the destructor restores the previous handlers, unless a signal was received
// (then the process is ending: further signals must not kill it). Guards nest.
class SignalGuard {
 public:
  explicit SignalGuard(bool clear = true);
  ~SignalGuard();
  SignalGuard(const SignalGuard&) = delete;
  SignalGuard& operator=(const SignalGuard&) = delete;

  // While a child process runs (ksmc build), signals received are also sent on to it.
  static void forward_to(pid_t child) noexcept;

 private:
  struct Saved;
  std::unique_ptr<Saved> saved_;
};

}  // namespace ksmc::runtime::io
