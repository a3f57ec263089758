#include "runtime/io/cancel.h"

#include <array>
#include <csignal>
#include <cstring>

#include <signal.h>

namespace ksmc::runtime::io {

namespace {

constexpr std::array<int, 3> kSignals = {SIGINT, SIGTERM, SIGHUP};
std::atomic<pid_t> g_forward{0};
static_assert(std::atomic<pid_t>::is_always_lock_free, "signal handlers need lock-free atomics");

extern "C" void on_cancel_signal(int sig) {
  request_cancel(sig);
  const pid_t child = g_forward.load();
  if (child > 0) ::kill(child, sig);
}

}  // namespace

std::string signal_name(int n) {
  switch (n) {
    case 0: return "cancelled";
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    default: return "signal " + std::to_string(n);
  }
}

int interrupted_exit_code(int n) noexcept { return n > 0 && n < 64 ? 128 + n : 128 + SIGINT; }

Cancelled::Cancelled(std::string_view where)
    : std::runtime_error(std::string(where) + ": interrupted by " + signal_name(cancel_signal())) {}

struct SignalGuard::Saved {
  std::array<struct sigaction, kSignals.size()> old{};
  std::array<bool, kSignals.size()> installed{};
};

SignalGuard::SignalGuard(bool clear) : saved_(std::make_unique<Saved>()) {
  if (clear) clear_cancel();
  struct sigaction sa;
  std::memset(&sa, 0, sizeof sa);
  sa.sa_handler = &on_cancel_signal;
  sigemptyset(&sa.sa_mask);
  for (const int s : kSignals) sigaddset(&sa.sa_mask, s);  // one handler at a time
  sa.sa_flags = SA_RESTART;  // interrupted reads and writes resume
  for (std::size_t i = 0; i < kSignals.size(); ++i) {
    saved_->installed[i] = ::sigaction(kSignals[i], &sa, &saved_->old[i]) == 0;
  }
}

SignalGuard::~SignalGuard() {
  g_forward.store(0);
  // A signal was received: the process is on its way out with 128 + signal and complete
  // outputs. The handlers stay, so a further signal (Ctrl-C pressed again, timeout's second
  // signal) cannot kill it while it finishes (buffers, exit handlers, a sanitizer's leak check).
  if (cancel_requested()) return;
  for (std::size_t i = 0; i < kSignals.size(); ++i) {
    if (saved_->installed[i]) ::sigaction(kSignals[i], &saved_->old[i], nullptr);
  }
}

void SignalGuard::forward_to(pid_t child) noexcept { g_forward.store(child); }

}  // namespace ksmc::runtime::io
