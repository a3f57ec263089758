// The indoor kit's reading of a blocks::Binding (generated from a domain file): the likelihood
// tables, the weak prior, the proposal-source pools of the kernels and the type group of the
// Markov logic program. Nothing here names a predicate, type or kernel: predicates come as
// ids, kernels as their declarations, the unit types as the exactly-one-of group of unary
// query predicates over the binding's constant type.
#pragma once

#include <cstdint>
#include <vector>

#include "stdlib/indoor/blocks.h"
#include "stdlib/indoor/likelihood.h"
#include "stdlib/indoor/prior.h"
#include "stdlib/indoor/world.h"

namespace ksmc::stdlib::indoor::kit {

// The proposal sources one kernel (and its reverse) pools: its own, not another kernel's.
struct SourcePool {
  std::vector<blocks::detect::Wbu> wbu;
  std::vector<blocks::detect::Fsu> fsu;
  std::vector<blocks::detect::Rpb> rpb;
  std::vector<blocks::detect::SplitLines> split;  // lines pooled
  std::vector<blocks::detect::Doors> doors;       // candidates pooled
  std::vector<blocks::move::WallShift> wall_shift;  // the first one's sigma
  std::vector<blocks::move::UniformRect> uniform_rect;  // shares add up (at most 1)
  std::vector<blocks::move::SeamDoors> seam_doors;      // candidates pooled
  std::vector<blocks::Source> declared;  // as declared (pools with equal sources are shared)
};

struct KernelPlan {
  const blocks::KernelDecl* decl = nullptr;
  KernelKind kind = KernelKind::Add;
  std::size_t pool = 0;  // index into KitPlan::pools
};

struct KitPlan {
  std::vector<LikelihoodTable> tables;  // [0] default, [1] lenient (enum order of likelihood.h)
  WeakPriorParams prior;
  std::vector<SourcePool> pools;
  std::vector<KernelPlan> kernels;  // declaration order
  // The unit types: the first exactly-one-of group of the program whose predicates are unary
  // query predicates over the constant type (empty without a program or such a group).
  std::vector<std::int32_t> type_predicates;
  std::vector<bool> lenient;  // per type_predicates entry: the likelihood's lenient_types
  bool semantic = false;      // the binding has a Markov logic program
  bool mln_prior = false;     // `prior mln`: log Z(evidence(W)) is a term of log p(W)
  // The tables do not depend on the unit types (no lenient type, or a lenient table equal to
  // the default): the likelihood and weak prior are then a function of the geometry alone and
  // a cheap first stage of delayed acceptance (IndoorModel).
  bool type_free_likelihood = true;
};

KernelKind kernel_kind(blocks::Move m);
KitPlan make_plan(const blocks::Binding& binding);

}  // namespace ksmc::stdlib::indoor::kit
