// The table-top kit's reading of a DomainConfig (runtime/domain/config.h): every
// model variable, extract, prior, likelihood, kernel and schedule item of the domain
// file is checked against what this kit implements and turned into parameters of the
// stdlib/tabletop building blocks. Anything else is a ConfigError naming the item's
// `file:line` (or the domain file when the item carries no location).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "runtime/domain/config.h"
#include "runtime/mcmc/schedule.h"
#include "stdlib/tabletop/evidence_params.h"

namespace ksmc::stdlib::tabletop::kit {

// keypoints.gaussian(sigma, robust, outlier_px) — see kit_likelihood.h.
struct KeypointModel {
  double sigma_px = 1.0;
  bool robust = false;
  double outlier_px = 20.0;
};

// One `kernel k(o: object) reverse k = pose.perturb(pose[o], sigma_t, sigma_r, candidates)`.
struct RefineKernelConfig {
  std::string name;
  std::string reverse;
  double sigma_t = 0.0;      // [m]
  double sigma_r = 0.0;      // [rad]
  int candidates = 0;
  // The current pose takes part in the choice of the best weight (refine_kernel.h).
  bool current_competes = true;
  std::string where;
};

// What `prior mln` scores a state with (docs/tabletop_kit.md, "Posterior"):
//   map   — eq. 4.3 for the scene graph the state stands for: Σ_i w_i n_i(x*) of the world
//           x* = (extracted evidence, most probable query atoms), the default;
//   log_z — log Σ_q exp(Σ_i w_i n_i(e, q)) over all query worlds (the earlier reading; it
//           rewards evidence that leaves query atoms unconstrained, i.e. fewer relations).
enum class PriorQuantity { map, log_z };

struct KitConfig {
  std::string domain;
  std::string source;
  // Evidence tolerances: stable tol, contact eps, intersect eps from the extract calls;
  // the vertical tolerances and higher_tol are the stdlib defaults (the .ksm signatures
  // have no parameter for them), raised to the lateral eps when that is larger.
  EvidenceParams evidence;
  double hover_eps = 0.0;    // must equal the contact eps (hover is "no contact, no intersect")
  KeypointModel likelihood;
  std::vector<RefineKernelConfig> kernels;
  std::vector<runtime::mcmc::ScheduleRow> schedule;
  std::string likelihood_where;
  std::string prior_where;
  PriorQuantity prior_quantity = PriorQuantity::map;
};

// Throws runtime::domain::ConfigError on anything the kit does not implement.
KitConfig read_kit_config(const runtime::domain::DomainConfig& config);

// The calls the kit implements, for messages and docs.
const std::vector<std::string>& implemented_calls();

}  // namespace ksmc::stdlib::tabletop::kit
