// The segments kit's reading of a generated blocks::Binding: the priors and the likelihood
// as values, and per kernel direction the parameters of its proposal sources. No name of the
// domain file is read: moves come from KernelDecl::move, parameters from the source values.
#pragma once

#include <memory>
#include <vector>

#include "stdlib/segments/blocks.h"

namespace ksmc::stdlib::segments::kit {

// The parameters one kernel direction uses: its sources' (both directions of a pair share
// them, so a move's reverse density uses its reverse's parameters); the stdlib/segments.ksm
// defaults where no source gives them. A later source of one kind replaces an earlier one.
struct KernelParams {
  blocks::Move move = blocks::Move::jitter;
  RansacParams ransac;
  BirthParams birth;
  DeathParams death;
  SplitParams split;
  MergeParams merge;
  JitterParams jitter;
  bool detects = false;  // has a detect.ransac source (birth candidates)
};

struct ModelParams {
  LikelihoodParams likelihood;
  std::vector<blocks::Prior> priors;  // binding order
  bool mln_prior = false;
};

ModelParams model_params(const blocks::Binding& b);
KernelParams kernel_params(const runtime::domain::KernelDecl<blocks::Move, blocks::Source>& k);

}  // namespace ksmc::stdlib::segments::kit
