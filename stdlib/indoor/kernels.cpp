#include "stdlib/indoor/kernels.h"

#include "stdlib/indoor/kernel_common.h"

namespace ksmc::stdlib::indoor {

using namespace kernels;

KernelSet::KernelSet(const MapEvidence& evidence, KernelSources sources, KernelParams params)
    : evidence_(evidence), sources_(std::move(sources)), params_(params) {}

namespace {

std::optional<Forward> forward(KernelKind k, const Context& c, const World& w, Rng& rng) {
  switch (k) {
    case KernelKind::Add: return propose_add(c, w, rng);
    case KernelKind::Remove: return propose_remove(c, w, rng);
    case KernelKind::Split: return propose_split(c, w, rng);
    case KernelKind::Merge: return propose_merge(c, w, rng);
    case KernelKind::Shrink:
    case KernelKind::Dilate: return propose_shift(k, c, w, rng);
    case KernelKind::Allocate: return propose_allocate(c, w, rng);
    case KernelKind::Delete: return propose_delete(c, w, rng);
    case KernelKind::Interchange: return propose_interchange(c, w, rng);
  }
  return std::nullopt;
}

}  // namespace

double KernelSet::log_q(KernelKind k, const World& w, const Move& m) const {
  const Context c{evidence_, sources_, params_};
  switch (k) {
    case KernelKind::Add: return log_q_add(c, w, m);
    case KernelKind::Remove: return log_q_remove(c, w, m);
    case KernelKind::Split: return log_q_split(c, w, m);
    case KernelKind::Merge: return log_q_merge(c, w, m);
    case KernelKind::Shrink:
    case KernelKind::Dilate: return log_q_shift(k, c, w, m);
    case KernelKind::Allocate: return log_q_allocate(c, w, m);
    case KernelKind::Delete: return log_q_delete(c, w, m);
    case KernelKind::Interchange: return log_q_interchange(c, w, m);
  }
  return kNegInf;
}

std::optional<Proposal> KernelSet::propose(KernelKind k, const World& w, Rng& rng) const {
  const Context c{evidence_, sources_, params_};
  auto f = forward(k, c, w, rng);
  if (!f || !(f->log_q > kNegInf)) return std::nullopt;
  Proposal p;
  p.move = std::move(f->move);
  p.log_q_fwd = f->log_q;
  const World next = w.applied(p.move);
  p.log_q_bwd = log_q(reverse_of(k), next, p.move.inverse());
  return p;
}

}  // namespace ksmc::stdlib::indoor
