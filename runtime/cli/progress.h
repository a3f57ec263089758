// Progress display of a domain run on stderr: a one-line bar redrawn in place on a
// terminal (iterations, iterations/s, current and best log posterior, acceptance rate),
// plain periodic lines otherwise. The engine calls it at most 10 times per second.
#pragma once

#include <chrono>
#include <ostream>

#include "runtime/mcmc/engine.h"

namespace ksmc::runtime::cli {

class ProgressPrinter {
 public:
  // tty: redraw one line with '\r'; otherwise print a line every plain_interval_s.
  ProgressPrinter(std::ostream& err, bool tty, double plain_interval_s = 5.0);
  void operator()(const mcmc::Progress& p);

 private:
  std::ostream& err_;
  bool tty_;
  double plain_interval_s_;
  double last_plain_s_ = 0.0;
};

// The text of one progress report (without line ending), shared by both modes.
std::string format_progress(const mcmc::Progress& p, bool with_bar);

}  // namespace ksmc::runtime::cli
