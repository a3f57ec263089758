#include "runtime/mln/inference.h"

#include "runtime/mln/components.h"
#include "runtime/mln/error.h"

namespace ksmc::runtime::mln {

Method parse_method(const std::string& name) {
  if (name == "exact") return Method::Exact;
  if (name == "gibbs") return Method::Gibbs;
  if (name == "mcsat") return Method::McSat;
  if (name == "auto") return Method::Auto;
  throw MlnError("unknown inference method '" + name + "' (expected exact, gibbs, mcsat or auto)");
}

double sample_component(const GroundNetwork& net, const Component& comp, const InferenceOptions& options,
                        std::size_t index, InferenceResult& r) {
  const GroundNetwork sub = extract_component(net, comp);
  McSatOptions mo = options.mcsat;
  mo.seed = options.mcsat.seed * 1000003ULL + index;
  mo.on_sample = nullptr;  // states of a sub-network: meaningless to the caller's observer
  const auto sr = mc_sat(sub, mo);
  for (std::size_t k = 0; k < comp.atoms.size(); ++k) r.marginals[comp.atoms[k]] = sr.marginals[k];
  r.samples = std::max(r.samples, sr.samples);
  if (!options.compute_log_z) return 0.0;
  r.log_z_exact = false;
  return ais_log_z(sub, options.log_z, options.log_z.seed * 1000003ULL + index).first;
}

InferenceResult infer(const GroundNetwork& net, const InferenceOptions& options) {
  switch (options.method) {
    case Method::Exact:
      return exact_inference(net, options.exact);
    case Method::Gibbs:
    case Method::McSat: {
      InferenceResult r = options.method == Method::Gibbs ? gibbs_sampling(net, options.gibbs)
                                                          : mc_sat(net, options.mcsat);
      if (options.compute_log_z) {
        const auto lz = log_partition(net, options.log_z);
        r.log_z = lz.log_z;
        r.log_z_exact = lz.exact;
      }
      return r;
    }
    case Method::Auto:
      break;
  }
  const auto comps = split_components(net);
  InferenceResult r;
  r.marginals.assign(static_cast<std::size_t>(net.num_atoms()), 0.0);
  r.log_z = net.constant();
  r.log_z_exact = true;
  bool sampled = false;
  ExactSummary summary;
  std::vector<Component> small;
  std::vector<ExactPlan> plans;
  for (std::size_t i = 0; i < comps.size(); ++i) {
    const auto& comp = comps[i];
    auto plan = plan_exact(net, comp, options.exact);
    summary.add(plan);
    if (plan.solver != ExactPlan::Solver::TooLarge) {
      small.push_back(comp);
      plans.push_back(std::move(plan));
      continue;
    }
    sampled = true;
    r.log_z += sample_component(net, comp, options, i, r);
  }
  r.log_z += solve_components(net, small, plans, r.marginals);
  if (sampled && !options.compute_log_z) r.log_z = std::numeric_limits<double>::quiet_NaN();
  r.method = summary.describe();
  return r;
}

}  // namespace ksmc::runtime::mln
