// Kernel pairs and the schedule of a binding, as the MCMC engine wants them: the kit turns
// each KernelDecl (one direction of `kernel pair A / B` or `kernel K reverse K`) into a kernel
// object that makes KernelDecl::move; this file does the bookkeeping every kit shares
// (KernelInfo table, schedule rows, their checks). Errors are ConfigError (`ksmc check`
// has already refused what they catch).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "runtime/domain/binding.h"
#include "runtime/mcmc/model.h"
#include "runtime/mcmc/schedule.h"

namespace ksmc::runtime::domain {

struct KernelTable {
  mcmc::KernelList kernels;  // declaration order
  mcmc::Schedule schedule;
};

// The engine's schedule from the binding's rows over `kernels` (declaration order). Throws
// ConfigError for a duplicate kernel name, an unknown reverse, an empty or negative row, and
// for whatever mcmc::Schedule refuses (rows not contiguous, probabilities not summing to 1,
// a kernel scheduled without its reverse).
mcmc::Schedule make_schedule(const std::vector<mcmc::KernelInfo>& kernels, const std::vector<ScheduleRow>& rows);

template <class Move, class Source>
std::vector<mcmc::KernelInfo> kernel_infos(const std::vector<KernelDecl<Move, Source>>& decls) {
  std::vector<mcmc::KernelInfo> infos;
  for (const auto& d : decls) infos.push_back({d.name, d.reverse});
  return infos;
}

// `make(decl)` builds the kernel of one declaration (a shared_ptr to an mcmc::Kernel whose
// name() and reverse_name() are decl.name and decl.reverse).
template <class Move, class Source, class Make>
KernelTable make_kernels(const std::vector<KernelDecl<Move, Source>>& decls, const std::vector<ScheduleRow>& rows,
                         Make&& make) {
  KernelTable t;
  t.schedule = make_schedule(kernel_infos(decls), rows);
  for (const auto& d : decls) {
    std::shared_ptr<const mcmc::Kernel> k = make(d);
    if (!k || k->name() != d.name || k->reverse_name() != d.reverse)
      throw ConfigError("kernel " + d.name + ": the kit made a kernel of another name");
    t.kernels.push_back(std::move(k));
  }
  return t;
}

}  // namespace ksmc::runtime::domain
