// One entry point over all engines: exact, gibbs, mcsat, or auto (per component:
// enumeration or variable elimination when either fits, by estimated cost, MC-SAT for
// the rest; log Z exact or AIS-estimated per component; InferenceResult::method says
// what ran, e.g. "exact:enum 3, elim 1 (width 4)" or "auto:enum 40, mcsat 1"). In auto mode MC-SAT runs on each large component separately, so
// mcsat.on_sample is not called. MAP is separate: max_walksat() or exact_map().
#pragma once

#include <string>

#include "runtime/mln/exact.h"
#include "runtime/mln/gibbs.h"
#include "runtime/mln/inference_result.h"
#include "runtime/mln/log_z.h"
#include "runtime/mln/mcsat.h"

namespace ksmc::runtime::mln {

enum class Method { Exact, Gibbs, McSat, Auto };

// "exact", "gibbs", "mcsat", "auto"; throws MlnError otherwise.
Method parse_method(const std::string& name);

struct InferenceOptions {
  Method method = Method::Auto;
  ExactOptions exact;
  GibbsOptions gibbs;
  McSatOptions mcsat;
  LogZOptions log_z;          // used by auto (and by gibbs/mcsat when compute_log_z)
  bool compute_log_z = true;  // auto: exact or AIS per component; gibbs/mcsat: AIS
};

InferenceResult infer(const GroundNetwork& net, const InferenceOptions& options = {});

// The auto mode's sampled path for one component (`index`: its position, which seeds
// the chains): MC-SAT marginals into r.marginals (global ids), r.samples updated; returns
// the AIS log Z of the component (0 when !options.compute_log_z) and clears
// r.log_z_exact when it estimated one.
double sample_component(const GroundNetwork& net, const Component& comp, const InferenceOptions& options,
                        std::size_t index, InferenceResult& r);

}  // namespace ksmc::runtime::mln
