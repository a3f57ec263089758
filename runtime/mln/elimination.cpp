#include "runtime/mln/elimination.h"

#include <algorithm>
#include <array>
#include <set>
#include <tuple>
#include <cmath>
#include <iterator>
#include <span>
#include <limits>
#include <numeric>
#include <string>

#include "runtime/io/cancel.h"
#include "runtime/mln/error.h"

namespace ksmc::runtime::mln {
namespace {

// Number of neighbour pairs of v that are not yet adjacent (the fill-in of eliminating v).
std::int64_t fill_in(const std::vector<std::vector<std::int32_t>>& adj, std::int32_t v,
                     std::vector<std::int32_t>& mark, std::int32_t& stamp) {
  const auto& nb = adj[v];
  std::int64_t missing = 0;
  for (std::size_t i = 0; i < nb.size(); ++i) {
    ++stamp;
    for (std::int32_t u : adj[nb[i]]) mark[u] = stamp;
    for (std::size_t j = i + 1; j < nb.size(); ++j) missing += mark[nb[j]] == stamp ? 0 : 1;
  }
  return missing;
}

// Walks every entry of a dense table over variables with `cards` (last variable
// fastest), keeping the index into a sub-table whose stride per position is `sub`
// (0 for a variable the sub-table does not have). f(index, sub_index, digits).
template <typename F>
void walk(const std::vector<std::int32_t>& cards, const std::vector<std::int64_t>& sub, F&& f) {
  // A cluster holds at most ~20 variables (tables are capped at 2^20-ish entries by the
  // planner's limit), so the digits live on the stack.
  constexpr std::size_t kMaxDigits = 64;
  const auto n = static_cast<std::int32_t>(cards.size());
  if (cards.size() > kMaxDigits) throw MlnError("exact inference: a junction-tree cluster has too many variables");
  std::array<std::int32_t, kMaxDigits> digit{};
  std::int64_t size = 1;
  for (auto c : cards) size *= c;
  std::int64_t s = 0;
  for (std::int64_t idx = 0; idx < size; ++idx) {
    f(idx, s, digit);
    for (std::int32_t p = n - 1; p >= 0; --p) {
      s += sub[p];
      if (++digit[p] < cards[p]) break;
      s -= sub[p] * cards[p];
      digit[p] = 0;
    }
  }
}

// Dense tables of all clusters in one allocation.
struct Tables {
  std::vector<double> data;
  std::vector<std::int64_t> off{0};
  void add(std::int64_t size, double init) {
    off.push_back(off.back() + size);
    data.resize(static_cast<std::size_t>(off.back()), init);
  }
  std::span<double> operator[](std::size_t i) {
    return {data.data() + off[i], data.data() + off[i + 1]};
  }
};

class JunctionTree {
 public:
  JunctionTree(const GroundNetwork& net, const Component& comp, const EliminationPlan& plan)
      : net_(net), comp_(comp), plan_(plan) {
    const auto n = static_cast<std::size_t>(plan.num_vars());
    cards_.resize(n);
    size_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      for (std::int32_t v : plan.scope[i]) cards_[i].push_back(plan.card(v));
      std::int64_t s = 1;
      for (auto c : cards_[i]) s *= c;
      size_[i] = s;
    }
    own_sep_.resize(n);
    parent_sep_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      own_sep_[i] = sep_strides(i, i);
      if (plan.parent[i] >= 0) parent_sep_[i] = sep_strides(static_cast<std::size_t>(plan.parent[i]), i);
    }
    // local atom -> (variable, value meaning "true")
    atom_var_.assign(comp.atoms.size(), -1);
    atom_val_.assign(comp.atoms.size(), 1);
    for (std::int32_t v = 0; v < plan.num_vars(); ++v) {
      const std::int32_t k = plan.var_offsets[v + 1] - plan.var_offsets[v];
      for (std::int32_t j = 0; j < k; ++j) {
        const auto li = local(plan.var_atoms[plan.var_offsets[v] + j]);
        atom_var_[li] = v;
        atom_val_[li] = k == 1 ? 1 : j;
      }
    }
  }

  // Sum-product: returns log Z, writes marginals (and, if given, the probability that
  // each of the component's clauses is satisfied, into (*clause_prob)[clause]).
  double sum_product(std::vector<double>& marg, std::vector<double>* clause_prob) {
    build_potentials();
    const auto n = static_cast<std::size_t>(plan_.num_vars());
    Tables beta = psi_;
    std::vector<double> scale = psi_scale_;
    Tables mu;
    for (std::size_t i = 0; i < n; ++i) mu.add(sep_size(i), 0.0);
    std::vector<double> delta;
    double log_z = 0.0;
    // Upward beliefs are not rescaled: psi is at most 1 and every message is scaled to
    // max 1, and only ratios of a belief to its own upward message are used below.
    for (std::size_t i = 0; i < n; ++i) {
      const auto& sep = own_sep_[i];
      walk(cards_[i], sep, [&](std::int64_t idx, std::int64_t s, const auto&) { mu[i][s] += beta[i][idx]; });
      const double m = *std::max_element(mu[i].begin(), mu[i].end());
      if (!(m > 0.0)) throw infeasible();
      for (double& x : mu[i]) x /= m;
      const std::int32_t p = plan_.parent[i];
      if (p < 0) {
        log_z += scale[i] + std::log(m);
        continue;
      }
      scale[p] += scale[i] + std::log(m);
      walk(cards_[p], parent_sep_[i], [&](std::int64_t idx, std::int64_t s, const auto&) { beta[p][idx] *= mu[i][s]; });
    }
    std::vector<double> acc;
    for (std::size_t r = n; r-- > 0;) {
      const std::int32_t p = plan_.parent[r];
      const std::int32_t v = plan_.order[r];
      const auto pos = static_cast<std::size_t>(position(r, v));
      acc.assign(static_cast<std::size_t>(plan_.card(v)), 0.0);
      double total = 0.0;
      if (p >= 0) {
        delta.assign(mu[r].size(), 0.0);
        walk(cards_[p], parent_sep_[r], [&](std::int64_t idx, std::int64_t s, const auto&) { delta[s] += beta[p][idx]; });
        walk(cards_[r], own_sep_[r], [&](std::int64_t idx, std::int64_t s, const auto& digit) {
          const double b = mu[r][s] > 0.0 ? beta[r][idx] * delta[s] / mu[r][s] : 0.0;
          beta[r][idx] = b;
          acc[static_cast<std::size_t>(digit[pos])] += b;
          total += b;
        });
      } else {
        walk(cards_[r], own_sep_[r], [&](std::int64_t idx, std::int64_t, const auto& digit) {
          acc[static_cast<std::size_t>(digit[pos])] += beta[r][idx];
          total += beta[r][idx];
        });
      }
      if (!(total > 0.0)) throw infeasible();
      if (total < 1e-100 || total > 1e100)  // keep the scale of the children's messages in range
        for (double& x : beta[r]) x /= total;
      set_marginal(v, acc, total, marg);
      if (clause_prob) clause_probabilities(r, beta[r], *clause_prob);
    }
    return log_z;
  }

  // Max-product with back-pointers: a most probable state of the component.
  void max_product(std::vector<std::uint8_t>& mode, double* mode_lw) {
    if (!built_) build_potentials();
    const auto n = static_cast<std::size_t>(plan_.num_vars());
    Tables beta = psi_;
    std::vector<std::vector<std::int32_t>> arg(n);
    std::vector<double> m;
    for (std::size_t i = 0; i < n; ++i) {
      normalise(beta[i]);
      const auto& sep = own_sep_[i];
      const std::int32_t pos = position(i, plan_.order[i]);
      m.assign(static_cast<std::size_t>(sep_size(i)), -1.0);
      arg[i].assign(m.size(), 0);
      walk(cards_[i], sep, [&](std::int64_t idx, std::int64_t s, const auto& digit) {
        if (beta[i][idx] > m[s]) {
          m[s] = beta[i][idx];
          arg[i][s] = digit[pos];
        }
      });
      const double mx = *std::max_element(m.begin(), m.end());
      if (!(mx > 0.0)) throw infeasible();
      const std::int32_t p = plan_.parent[i];
      if (p < 0) continue;
      for (double& x : m) x /= mx;
      walk(cards_[p], parent_sep_[i], [&](std::int64_t idx, std::int64_t s, const auto&) { beta[p][idx] *= m[s]; });
    }
    std::vector<std::int32_t> value(n, 0);
    for (std::size_t r = n; r-- > 0;) {  // separator variables are eliminated later: known
      std::int64_t s = 0;
      const auto& sc = plan_.scope[r];
      for (std::size_t k = 0; k < sc.size(); ++k) {
        if (sc[k] == plan_.order[r]) continue;
        s = s * cards_[r][k] + value[sc[k]];
      }
      value[plan_.order[r]] = arg[r][s];
    }
    double lw = 0.0;
    for (std::size_t li = 0; li < comp_.atoms.size(); ++li) {
      const bool on = value[atom_var_[li]] == atom_val_[li];
      mode[comp_.atoms[li]] = on ? 1 : 0;
    }
    for (std::int32_t c : comp_.clauses) {
      if (net_.is_hard(c)) continue;
      for (Lit l : net_.clause(c)) {
        if (lit_true(l, mode[lit_atom(l)])) {
          lw += net_.weight(c);
          break;
        }
      }
    }
    if (mode_lw) *mode_lw = lw;
  }

 private:
  std::size_t local(AtomId a) const {
    return static_cast<std::size_t>(std::lower_bound(comp_.atoms.begin(), comp_.atoms.end(), a) - comp_.atoms.begin());
  }
  std::int32_t position(std::size_t cluster, std::int32_t var) const {
    const auto& sc = plan_.scope[cluster];
    return static_cast<std::int32_t>(std::lower_bound(sc.begin(), sc.end(), var) - sc.begin());
  }
  std::int64_t sep_size(std::size_t i) const { return size_[i] / plan_.card(plan_.order[i]); }

  // Strides, per position of cluster `table`'s scope, of the separator of cluster `child`
  // (its scope without its eliminated variable), laid out in ascending variable order.
  std::vector<std::int64_t> sep_strides(std::size_t table, std::size_t child) const {
    const auto& sc = plan_.scope[table];
    const auto& cs = plan_.scope[child];
    const std::int32_t skip = plan_.order[child];
    std::vector<std::int64_t> st(sc.size(), 0);
    std::int64_t stride = 1;
    for (std::size_t k = cs.size(); k-- > 0;) {
      if (cs[k] == skip) continue;
      st[static_cast<std::size_t>(position(table, cs[k]))] = stride;
      stride *= plan_.card(cs[k]);
    }
    return st;
  }

  // Scales t to max 1; returns the log of the factor taken out.
  static double normalise(std::span<double> t) {
    const double m = *std::max_element(t.begin(), t.end());
    if (!(m > 0.0)) return 0.0;
    for (double& x : t) x /= m;
    return std::log(m);
  }

  // A literal of a clause as a test on a cluster's table digits.
  struct Test {
    std::int32_t pos, value;
    bool negated;
  };
  void clause_tests(std::size_t cluster, std::int32_t c, std::vector<Test>& tests) const {
    tests.clear();
    for (Lit l : net_.clause(c)) {
      const auto li = local(lit_atom(l));
      tests.push_back({position(cluster, atom_var_[li]), atom_val_[li], lit_negated(l)});
    }
  }
  template <typename Digits>
  static bool satisfied(const std::vector<Test>& tests, const Digits& digit) {
    for (const auto& t : tests)
      if ((digit[t.pos] == t.value) != t.negated) return true;
    return false;
  }

  // P(clause satisfied) of the clauses assigned to cluster i, from its calibrated belief.
  void clause_probabilities(std::size_t i, std::span<const double> belief, std::vector<double>& out) {
    std::vector<Test> tests;
    const std::vector<std::int64_t> none(cards_[i].size(), 0);
    for (std::int32_t c : plan_.clauses[i]) {
      clause_tests(i, c, tests);
      double sat = 0.0, all = 0.0;
      walk(cards_[i], none, [&](std::int64_t idx, std::int64_t, const auto& digit) {
        const double b = belief[static_cast<std::size_t>(idx)];
        all += b;
        if (satisfied(tests, digit)) sat += b;
      });
      out[static_cast<std::size_t>(c)] = all > 0.0 ? std::clamp(sat / all, 0.0, 1.0) : 0.0;
    }
  }

  // psi of each cluster: the product of its clauses' factors, each scaled to max 1 (a
  // soft clause of weight w >= 0 is 1 when satisfied and e^-w when not, its w going to
  // the cluster's log scale; w < 0: e^w when satisfied, 1 when not; hard: 1 or 0), so
  // one exp per clause instead of one per table entry.
  void build_potentials() {
    const auto n = static_cast<std::size_t>(plan_.num_vars());
    psi_ = Tables{};
    psi_.data.reserve(static_cast<std::size_t>(std::accumulate(size_.begin(), size_.end(), std::int64_t{0})));
    psi_scale_.assign(n, 0.0);
    std::vector<Test> tests;
    std::vector<std::int64_t> none;
    for (std::size_t i = 0; i < n; ++i) {
      psi_.add(size_[i], 1.0);
      auto table = psi_[i];
      for (std::int32_t c : plan_.clauses[i]) {
        clause_tests(i, c, tests);
        double if_sat = 1.0, if_unsat = 0.0;
        if (!net_.is_hard(c)) {
          const double w = net_.weight(c);
          if (w >= 0.0) {
            if_unsat = std::exp(-w);
            psi_scale_[i] += w;
          } else {
            if_sat = std::exp(w);
            if_unsat = 1.0;
          }
        }
        none.assign(cards_[i].size(), 0);
        walk(cards_[i], none, [&](std::int64_t idx, std::int64_t, const auto& digit) {
          table[static_cast<std::size_t>(idx)] *= satisfied(tests, digit) ? if_sat : if_unsat;
        });
      }
    }
    built_ = true;
  }

  void set_marginal(std::int32_t v, const std::vector<double>& m, double z, std::vector<double>& marg) const {
    const std::int32_t k = plan_.var_offsets[v + 1] - plan_.var_offsets[v];
    for (std::int32_t j = 0; j < k; ++j) {
      const double p = k == 1 ? m[1] / z : m[static_cast<std::size_t>(j)] / z;
      marg[plan_.var_atoms[plan_.var_offsets[v] + j]] = std::clamp(p, 0.0, 1.0);
    }
  }

  MlnError infeasible() const {
    std::string rules;
    for (std::int32_t c : comp_.clauses) {
      if (!net_.is_hard(c)) continue;
      const auto name = net_.origin_name(c);
      if (rules.find(name) == std::string::npos) rules += (rules.empty() ? "" : ", ") + name;
    }
    if (!comp_.blocks.empty()) rules += std::string(rules.empty() ? "" : ", ") + "exactly-one blocks";
    return MlnError("exact inference: no state satisfies the hard constraints (" + rules + ") over a component of " +
                    std::to_string(comp_.atoms.size()) + " atoms");
  }

  const GroundNetwork& net_;
  const Component& comp_;
  const EliminationPlan& plan_;
  std::vector<std::vector<std::int32_t>> cards_;
  std::vector<std::int64_t> size_;
  std::vector<std::int32_t> atom_var_, atom_val_;
  std::vector<std::vector<std::int64_t>> own_sep_, parent_sep_;  // separator strides in own / parent table
  Tables psi_;
  bool built_ = false;
  std::vector<double> psi_scale_;
};

}  // namespace

EliminationPlan plan_elimination(const GroundNetwork& net, const Component& comp, double entry_limit) {
  EliminationPlan plan;
  plan.var_offsets.push_back(0);
  std::vector<std::int32_t> var_of_local(comp.atoms.size(), -1);
  auto local = [&](AtomId a) {
    return static_cast<std::size_t>(std::lower_bound(comp.atoms.begin(), comp.atoms.end(), a) - comp.atoms.begin());
  };
  for (std::size_t i = 0; i < comp.atoms.size(); ++i) {
    if (net.block_of(comp.atoms[i]) >= 0) continue;
    var_of_local[i] = plan.num_vars();
    plan.var_atoms.push_back(comp.atoms[i]);
    plan.var_offsets.push_back(static_cast<std::int32_t>(plan.var_atoms.size()));
  }
  for (std::int32_t b : comp.blocks) {
    const std::int32_t v = plan.num_vars();
    for (AtomId a : net.block(b)) {
      var_of_local[local(a)] = v;
      plan.var_atoms.push_back(a);
    }
    plan.var_offsets.push_back(static_cast<std::int32_t>(plan.var_atoms.size()));
  }
  const auto n = static_cast<std::size_t>(plan.num_vars());
  // Variables of each clause and the interaction graph.
  std::vector<std::vector<std::int32_t>> cvars(comp.clauses.size());
  std::vector<std::vector<std::int32_t>> adj(n);
  for (std::size_t k = 0; k < comp.clauses.size(); ++k) {
    io::throw_if_cancelled("planning variable elimination");  // a long clause adds size^2 edges
    auto& vs = cvars[k];
    for (Lit l : net.clause(comp.clauses[k])) vs.push_back(var_of_local[local(lit_atom(l))]);
    std::sort(vs.begin(), vs.end());
    vs.erase(std::unique(vs.begin(), vs.end()), vs.end());
    for (std::int32_t a : vs)
      for (std::int32_t b : vs)
        if (a != b) adj[a].push_back(b);
  }
  for (auto& nb : adj) {
    io::throw_if_cancelled("planning variable elimination");
    std::sort(nb.begin(), nb.end());
    nb.erase(std::unique(nb.begin(), nb.end()), nb.end());
  }
  // Greedy min-fill.
  std::vector<std::int32_t> mark(n, 0);
  std::int32_t stamp = 0;
  std::vector<std::int64_t> fill(n);
  // fill_in costs degree^2: poll before each (dense components have thousands of neighbours).
  for (std::size_t v = 0; v < n; ++v) {
    io::throw_if_cancelled("planning variable elimination");
    fill[v] = fill_in(adj, static_cast<std::int32_t>(v), mark, stamp);
  }
  std::vector<std::int32_t> step_of(n, -1), merged, touched;
  // Candidates by (fill-in, degree, id); entries are replaced when a score changes.
  using Key = std::tuple<std::int64_t, std::size_t, std::int32_t>;
  std::set<Key> queue;
  std::vector<Key> key_of(n);
  for (std::size_t v = 0; v < n; ++v) {
    key_of[v] = {fill[v], adj[v].size(), static_cast<std::int32_t>(v)};
    queue.insert(key_of[v]);
  }
  for (std::size_t step = 0; step < n; ++step) {
    const std::int32_t best = std::get<2>(*queue.begin());
    queue.erase(queue.begin());
    const std::vector<std::int32_t> nb = adj[best];
    std::vector<std::int32_t> scope = nb;
    scope.insert(std::lower_bound(scope.begin(), scope.end(), best), best);
    double entries = 1.0;
    for (std::int32_t v : scope) entries *= plan.card(v);
    plan.width = std::max(plan.width, static_cast<std::int32_t>(scope.size()) - 1);
    plan.max_entries = std::max(plan.max_entries, entries);
    plan.total_entries += entries;
    if (entries > entry_limit) return plan;
    plan.order.push_back(best);
    plan.scope.push_back(std::move(scope));
    step_of[best] = static_cast<std::int32_t>(step);
    touched.clear();
    // Without fill-in (v simplicial) no edge is added, so only v's neighbours change
    // score; otherwise also the neighbours of the new edges' ends.
    const bool new_edges = fill[best] > 0;
    for (std::int32_t a : nb) {
      merged.clear();
      if (new_edges) {
        std::set_union(adj[a].begin(), adj[a].end(), nb.begin(), nb.end(), std::back_inserter(merged));
        merged.erase(std::remove_if(merged.begin(), merged.end(), [&](std::int32_t u) { return u == a || u == best; }),
                     merged.end());
      } else {
        std::remove_copy(adj[a].begin(), adj[a].end(), std::back_inserter(merged), best);
      }
      adj[a].swap(merged);
      touched.push_back(a);
      if (new_edges) touched.insert(touched.end(), adj[a].begin(), adj[a].end());
    }
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    for (std::int32_t u : touched) {
      io::throw_if_cancelled("planning variable elimination");
      fill[u] = fill_in(adj, u, mark, stamp);
      const Key k{fill[u], adj[u].size(), u};
      if (k == key_of[u]) continue;
      queue.erase(key_of[u]);
      key_of[u] = k;
      queue.insert(k);
    }
  }
  plan.parent.assign(n, -1);
  for (std::size_t i = 0; i < n; ++i) {
    std::int32_t p = -1;
    for (std::int32_t u : plan.scope[i])
      if (u != plan.order[i] && (p < 0 || step_of[u] < p)) p = step_of[u];
    plan.parent[i] = p;
  }
  plan.clauses.assign(n, {});
  for (std::size_t k = 0; k < comp.clauses.size(); ++k) {
    std::int32_t first = static_cast<std::int32_t>(n);
    for (std::int32_t v : cvars[k]) first = std::min(first, step_of[v]);
    plan.clauses[first].push_back(comp.clauses[k]);
  }
  return plan;
}

bool rebind_plan(const GroundNetwork& net, const Component& from, const Component& to, EliminationPlan& plan) {
  if (from.atoms.size() != to.atoms.size()) return false;
  auto position = [](const std::vector<AtomId>& atoms, AtomId a) {
    return static_cast<std::size_t>(std::lower_bound(atoms.begin(), atoms.end(), a) - atoms.begin());
  };
  std::vector<std::int32_t> var_of_local(to.atoms.size(), -1);
  for (std::int32_t v = 0; v < plan.num_vars(); ++v) {
    for (std::int32_t k = plan.var_offsets[v]; k < plan.var_offsets[v + 1]; ++k) {
      const auto pos = position(from.atoms, plan.var_atoms[k]);
      plan.var_atoms[k] = to.atoms[pos];
      var_of_local[pos] = v;
    }
  }
  const auto n = static_cast<std::size_t>(plan.num_vars());
  std::vector<std::int32_t> step_of(n, 0);
  for (std::size_t i = 0; i < n; ++i) step_of[plan.order[i]] = static_cast<std::int32_t>(i);
  plan.clauses.assign(n, {});
  for (std::int32_t c : to.clauses) {
    std::int32_t first = static_cast<std::int32_t>(n);
    for (Lit l : net.clause(c)) first = std::min(first, step_of[var_of_local[position(to.atoms, lit_atom(l))]]);
    const auto& sc = plan.scope[first];
    for (Lit l : net.clause(c)) {
      if (!std::binary_search(sc.begin(), sc.end(), var_of_local[position(to.atoms, lit_atom(l))])) return false;
    }
    plan.clauses[first].push_back(c);
  }
  return true;
}

double eliminate_component(const GroundNetwork& net, const Component& comp, const EliminationPlan& plan,
                           std::vector<double>& marg, std::vector<std::uint8_t>* mode, double* mode_lw,
                           std::vector<double>* clause_prob) {
  if (static_cast<std::size_t>(plan.num_vars()) != plan.order.size())
    throw MlnError("exact inference: elimination plan incomplete (a cluster exceeded the table limit)");
  io::throw_if_cancelled("variable elimination");
  JunctionTree jt(net, comp, plan);
  const double log_z = jt.sum_product(marg, clause_prob);
  if (mode) jt.max_product(*mode, mode_lw);
  return log_z;
}

}  // namespace ksmc::runtime::mln
