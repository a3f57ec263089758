#include "runtime/cli/interrupt.h"

#include <csignal>
#include <cstring>

#include <signal.h>

namespace ksmc::runtime::cli {

namespace {

std::atomic<bool> g_interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free, "the signal handler needs a lock-free flag");

extern "C" void on_sigint(int) { g_interrupted.store(true); }

}  // namespace

struct InterruptGuard::Saved {
  struct sigaction old {};
  bool installed = false;
};

InterruptGuard::InterruptGuard() : saved_(std::make_unique<Saved>()) {
  g_interrupted.store(false);
  struct sigaction sa;
  std::memset(&sa, 0, sizeof sa);
  sa.sa_handler = &on_sigint;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESETHAND;  // a second Ctrl-C kills as usual
  saved_->installed = ::sigaction(SIGINT, &sa, &saved_->old) == 0;
}

InterruptGuard::~InterruptGuard() {
  if (saved_->installed) ::sigaction(SIGINT, &saved_->old, nullptr);
}

const std::atomic<bool>& InterruptGuard::flag() noexcept { return g_interrupted; }

}  // namespace ksmc::runtime::cli
