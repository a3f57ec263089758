#include "runtime/cli/progress.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

namespace ksmc::runtime::cli {

namespace {

std::string si(double v) {
  if (v >= 1e9) return fmt::format("{:.2f}G", v / 1e9);
  if (v >= 1e6) return fmt::format("{:.2f}M", v / 1e6);
  if (v >= 1e3) return fmt::format("{:.1f}k", v / 1e3);
  return fmt::format("{:.0f}", v);
}

std::string lp_text(double v) { return std::isfinite(v) ? fmt::format("{:.2f}", v) : fmt::format("{}", v); }

}  // namespace

std::string format_progress(const mcmc::Progress& p, bool with_bar) {
  const double frac = p.iterations_total == 0
                          ? 1.0
                          : static_cast<double>(p.iterations_done) / static_cast<double>(p.iterations_total);
  const double rate = p.seconds > 0.0 ? static_cast<double>(p.iterations_done) / p.seconds : 0.0;
  if (p.until_plateau) {  // the length is not known: no bar, no percentage
    return fmt::format("{} it (until the plateau, at most {}), {} it/s, log posterior {} (best {}), acceptance {:.1f}%",
                       p.iterations_done, p.iterations_total, si(rate), lp_text(p.current_log_posterior),
                       lp_text(p.best_log_posterior), 100.0 * p.acceptance_rate);
  }
  std::string bar;
  if (with_bar) {
    constexpr int kWidth = 24;
    const int filled = std::clamp(static_cast<int>(frac * kWidth), 0, kWidth);
    bar = "[" + std::string(static_cast<std::size_t>(filled), '#') +
          std::string(static_cast<std::size_t>(kWidth - filled), '.') + "] ";
  }
  return fmt::format("{}{:5.1f}% {}/{} it, {} it/s, log posterior {} (best {}), acceptance {:.1f}%", bar,
                     100.0 * frac, p.iterations_done, p.iterations_total, si(rate),
                     lp_text(p.current_log_posterior), lp_text(p.best_log_posterior),
                     100.0 * p.acceptance_rate);
}

ProgressPrinter::ProgressPrinter(std::ostream& err, bool tty, double plain_interval_s)
    : err_(err), tty_(tty), plain_interval_s_(plain_interval_s) {}

void ProgressPrinter::operator()(const mcmc::Progress& p) {
  if (tty_) {
    err_ << '\r' << format_progress(p, true) << "\x1b[K";
    if (p.finished) err_ << '\n';
    err_.flush();
    return;
  }
  if (p.finished || p.seconds - last_plain_s_ >= plain_interval_s_) {
    last_plain_s_ = p.seconds;
    err_ << format_progress(p, false) << '\n';
    err_.flush();
  }
}

}  // namespace ksmc::runtime::cli
