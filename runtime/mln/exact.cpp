#include "runtime/mln/exact.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>

#include "runtime/mln/error.h"

namespace ksmc::runtime::mln {
namespace {

constexpr double kNegInf = -std::numeric_limits<double>::infinity();

std::string describe_hard_origins(const GroundNetwork& net) {
  std::set<std::string> names;
  for (std::int32_t c = 0; c < net.num_clauses(); ++c)
    if (net.is_hard(c)) names.insert(net.origin_name(c));
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  if (net.num_blocks() > 0) out += std::string(out.empty() ? "" : ", ") + "exactly-one blocks";
  return out;
}

std::string describe_labels(const GroundNetwork& net, std::span<const AtomId> atoms) {
  std::set<std::string> names;
  for (AtomId a : atoms) names.insert(net.label_name(a));
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

ComponentResult closed_form_single(const GroundNetwork& net) {
  // One atom, every clause is a unit clause over it.
  double s0 = 0.0, s1 = 0.0;
  bool allow0 = true, allow1 = true;
  for (std::int32_t c = 0; c < net.num_clauses(); ++c) {
    const bool neg = lit_negated(net.clause(c)[0]);
    if (net.is_hard(c)) {
      (neg ? allow1 : allow0) = false;
    } else {
      (neg ? s0 : s1) += net.weight(c);
    }
  }
  ComponentResult r;
  if (!allow0 && !allow1) {
    throw MlnError("exact inference: no state satisfies the hard clauses (" +
                   describe_hard_origins(net) + ") over " + net.label_name(0));
  }
  r.mode = {static_cast<std::uint8_t>(allow1 && (!allow0 || s1 > s0) ? 1 : 0)};
  r.mode_log_weight = r.mode[0] ? s1 : s0;
  if (!allow0) {
    r.marginals = {1.0};
    r.log_z = s1;
  } else if (!allow1) {
    r.marginals = {0.0};
    r.log_z = s0;
  } else {
    const double m = std::max(s0, s1);
    const double e0 = std::exp(s0 - m), e1 = std::exp(s1 - m);
    r.marginals = {e1 / (e0 + e1)};
    r.log_z = m + std::log(e0 + e1);
  }
  return r;
}

}  // namespace

double component_state_bits(const GroundNetwork& net, const Component& comp) {
  double bits = 0.0;
  for (AtomId a : comp.atoms)
    if (net.block_of(a) < 0) bits += 1.0;
  for (std::int32_t b : comp.blocks) bits += std::log2(static_cast<double>(net.block(b).size()));
  return bits;
}

ComponentResult enumerate_network(const GroundNetwork& net) {
  const std::int32_t n = net.num_atoms();
  if (n == 0) return {};
  if (n == 1 && net.num_blocks() == 0) return closed_form_single(net);

  const Occurrences occ = build_occurrences(net);
  const std::int32_t m = net.num_clauses();
  std::vector<double> w(static_cast<std::size_t>(m));
  std::vector<std::uint8_t> hard(static_cast<std::size_t>(m));
  double ref = 0.0;
  for (std::int32_t c = 0; c < m; ++c) {
    hard[c] = net.is_hard(c) ? 1 : 0;
    w[c] = hard[c] ? 0.0 : net.weight(c);
    if (!hard[c]) ref += std::max(w[c], 0.0);
  }
  // Digits: a free atom (radix 2) or a block (radix k).
  std::vector<std::int32_t> radix, first;
  std::vector<AtomId> digit_atoms;
  for (AtomId a = 0; a < n; ++a) {
    if (net.block_of(a) >= 0) continue;
    radix.push_back(2);
    first.push_back(static_cast<std::int32_t>(digit_atoms.size()));
    digit_atoms.push_back(a);
  }
  for (std::int32_t b = 0; b < net.num_blocks(); ++b) {
    const auto atoms = net.block(b);
    radix.push_back(static_cast<std::int32_t>(atoms.size()));
    first.push_back(static_cast<std::int32_t>(digit_atoms.size()));
    digit_atoms.insert(digit_atoms.end(), atoms.begin(), atoms.end());
  }
  const std::int32_t nd = static_cast<std::int32_t>(radix.size());

  std::vector<std::uint8_t> val(static_cast<std::size_t>(n));
  std::vector<std::int32_t> cnt(static_cast<std::size_t>(m));
  std::vector<double> acc(static_cast<std::size_t>(n)), since(static_cast<std::size_t>(n));
  std::vector<std::int32_t> digit(static_cast<std::size_t>(nd)), dir(static_cast<std::size_t>(nd));
  std::vector<std::int32_t> focus(static_cast<std::size_t>(nd) + 1);

  double z = 0.0, s = 0.0, max_s = kNegInf;
  std::int32_t violated = 0;
  std::vector<std::uint8_t> mode;

  auto flip = [&](AtomId a) {
    const std::uint8_t nv = val[a] ? 0 : 1;
    if (nv) since[a] = z; else acc[a] += z - since[a];
    val[a] = nv;
    for (std::int32_t k = occ.offsets[a]; k < occ.offsets[a + 1]; ++k) {
      const std::int32_t c = occ.clause[k];
      if ((nv != 0) != (occ.negated[k] != 0)) {
        if (cnt[c]++ == 0) {
          if (hard[c]) --violated; else s += w[c];
        }
      } else {
        if (--cnt[c] == 0) {
          if (hard[c]) ++violated; else s -= w[c];
        }
      }
    }
  };

  auto run = [&](double shift) {
    std::fill(val.begin(), val.end(), 0);
    std::fill(acc.begin(), acc.end(), 0.0);
    std::fill(since.begin(), since.end(), 0.0);
    for (std::int32_t d = 0; d < nd; ++d)
      if (radix[d] > 2 || net.block_of(digit_atoms[first[d]]) >= 0) val[digit_atoms[first[d]]] = 1;
    z = 0.0;
    s = 0.0;
    violated = 0;
    max_s = kNegInf;
    for (std::int32_t c = 0; c < m; ++c) {
      std::int32_t k = 0;
      for (Lit l : net.clause(c)) k += lit_true(l, val[lit_atom(l)]) ? 1 : 0;
      cnt[c] = k;
      if (k > 0) { if (!hard[c]) s += w[c]; }
      else if (hard[c]) ++violated;
    }
    for (std::int32_t d = 0; d < nd; ++d) {
      digit[d] = 0;
      dir[d] = 1;
      focus[d] = d;
    }
    focus[nd] = nd;
    while (true) {
      if (violated == 0) {
        z += std::exp(s - shift);
        if (s > max_s) {
          max_s = s;
          mode = val;
        }
      }
      const std::int32_t j = focus[0];
      focus[0] = 0;
      if (j == nd) break;
      const std::int32_t old = digit[j];
      digit[j] += dir[j];
      if (radix[j] == 2 && net.block_of(digit_atoms[first[j]]) < 0) {
        flip(digit_atoms[first[j]]);
      } else {
        flip(digit_atoms[first[j] + old]);
        flip(digit_atoms[first[j] + digit[j]]);
      }
      if (digit[j] == 0 || digit[j] == radix[j] - 1) {
        dir[j] = -dir[j];
        focus[j] = focus[j + 1];
        focus[j + 1] = j + 1;
      }
    }
    for (AtomId a = 0; a < n; ++a)
      if (val[a]) acc[a] += z - since[a];
  };

  run(ref);
  if (max_s == kNegInf) {
    throw MlnError("exact inference: no state satisfies the hard constraints (" +
                   describe_hard_origins(net) + ") over atoms of " +
                   describe_labels(net, digit_atoms));
  }
  double shift = ref;
  if (!(z > 1e-250)) {  // everything underflowed against the bound: rescale on the true max
    shift = max_s;
    run(shift);
  }
  ComponentResult r;
  r.marginals.resize(static_cast<std::size_t>(n));
  for (AtomId a = 0; a < n; ++a) r.marginals[a] = std::clamp(acc[a] / z, 0.0, 1.0);
  r.log_z = shift + std::log(z);
  r.mode = mode;
  r.mode_log_weight = max_s;
  return r;
}

MapResult exact_map(const GroundNetwork& net, const ExactOptions& options) {
  const auto comps = split_components(net);
  for (const auto& comp : comps) {
    if (component_state_bits(net, comp) > options.max_component_bits + 1e-9)
      throw MlnError(too_large_message(net, comp, options));
  }
  MapResult r;
  r.state.assign(static_cast<std::size_t>(net.num_atoms()), 0);
  for (const auto& comp : comps) {
    const auto cr = enumerate_network(extract_component(net, comp));
    for (std::size_t i = 0; i < comp.atoms.size(); ++i) r.state[comp.atoms[i]] = cr.mode[i];
  }
  r.feasible = net.feasible(r.state);
  r.log_weight = net.log_weight(r.state);
  return r;
}

std::string too_large_message(const GroundNetwork& net, const Component& comp,
                              const ExactOptions& options) {
  return "exact inference: a connected component has " + std::to_string(comp.atoms.size()) +
         " free atoms (" + std::to_string(static_cast<long long>(std::ceil(component_state_bits(net, comp)))) +
         " bits of state), above the limit of " + std::to_string(options.max_component_bits) +
         " bits (network: " + std::to_string(net.num_atoms()) + " atoms, " +
         std::to_string(net.num_clauses()) + " clauses); its atoms come from " +
         describe_labels(net, comp.atoms) +
         "; use the auto or mcsat method, or raise max_component_bits";
}

InferenceResult exact_inference(const GroundNetwork& net, const ExactOptions& options) {
  const auto comps = split_components(net);
  for (const auto& comp : comps) {
    if (component_state_bits(net, comp) > options.max_component_bits + 1e-9)
      throw MlnError(too_large_message(net, comp, options));
  }
  InferenceResult r;
  r.method = "exact";
  r.marginals.assign(static_cast<std::size_t>(net.num_atoms()), 0.0);
  r.log_z = net.constant();
  r.log_z_exact = true;
  for (const auto& comp : comps) {
    ComponentResult cr;
    if (comp.atoms.size() == 1 && comp.blocks.empty()) {
      // Closed form straight from the parent network (no extraction needed).
      const AtomId a = comp.atoms[0];
      double s0 = 0.0, s1 = 0.0;
      bool allow0 = true, allow1 = true;
      for (std::int32_t c : comp.clauses) {
        const bool neg = lit_negated(net.clause(c)[0]);
        if (net.is_hard(c)) (neg ? allow1 : allow0) = false;
        else (neg ? s0 : s1) += net.weight(c);
      }
      if (!allow0 && !allow1) {
        throw MlnError("exact inference: no state satisfies the hard constraints over " +
                       net.label_name(a) + " (" + net.origin_name(comp.clauses.front()) + ")");
      }
      if (!allow0) { r.marginals[a] = 1.0; r.log_z += s1; continue; }
      if (!allow1) { r.marginals[a] = 0.0; r.log_z += s0; continue; }
      const double mx = std::max(s0, s1);
      const double e0 = std::exp(s0 - mx), e1 = std::exp(s1 - mx);
      r.marginals[a] = e1 / (e0 + e1);
      r.log_z += mx + std::log(e0 + e1);
      continue;
    }
    cr = enumerate_network(extract_component(net, comp));
    for (std::size_t i = 0; i < comp.atoms.size(); ++i) r.marginals[comp.atoms[i]] = cr.marginals[i];
    r.log_z += cr.log_z;
  }
  return r;
}

}  // namespace ksmc::runtime::mln
