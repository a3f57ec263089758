#include "tools/mln_tabletop/evaluate.h"

#include <algorithm>
#include <cmath>

#include "runtime/mln/evidence.h"
#include "runtime/mln/exact.h"
#include "runtime/mln/grounder.h"

namespace ksmc::tools::mln_tabletop {
namespace {

namespace mln = ksmc::runtime::mln;

constexpr double kFloor = 1e-12;

}  // namespace

Evaluation evaluate(const mln::Program& program, const std::vector<std::string>& db_paths) {
  Evaluation e;
  std::vector<std::size_t> score_of(program.predicates.size(), 0);
  for (std::size_t p = 0; p < program.predicates.size(); ++p) {
    if (!program.predicates[p].query || program.predicates[p].auxiliary) continue;
    score_of[p] = e.predicates.size();
    e.predicates.push_back({program.predicates[p].name});
  }
  for (const auto& path : db_paths) {
    const std::string text = mln::read_text_file(path);
    mln::Domain domain;
    domain.resize(static_cast<std::int32_t>(program.types.size()));
    mln::collect_db_constants(text, path, program, domain);
    mln::Evidence full(program, domain);
    mln::DbOptions all;
    all.allow_all_query_evidence = true;
    mln::parse_db(text, path, program, domain, full, all);
    mln::Evidence given = full;
    for (std::size_t p = 0; p < program.predicates.size(); ++p) {
      if (!program.predicates[p].query) continue;
      for (std::int64_t f = 0; f < full.num_atoms(static_cast<std::int32_t>(p)); ++f)
        given.set_flat(static_cast<std::int32_t>(p), f, mln::Evidence::kUnknown);
    }
    const mln::Grounding g = mln::ground(program, domain, given);
    const auto r = mln::exact_inference(g.network);
    std::vector<std::uint8_t> world(static_cast<std::size_t>(g.network.num_atoms()), 0);
    for (std::size_t p = 0; p < program.predicates.size(); ++p) {
      if (!program.predicates[p].query || program.predicates[p].auxiliary) continue;
      auto& s = e.predicates[score_of[p]];
      const auto p32 = static_cast<std::int32_t>(p);
      for (std::int64_t f = 0; f < full.num_atoms(p32); ++f) {
        const std::int64_t q = g.index.offset[p] + f;
        const bool truth = full.get_flat(p32, f) == 1;
        const double prob = g.marginal(r, q);
        const double of_truth = truth ? prob : 1.0 - prob;
        ++s.atoms;
        s.correct += (prob > 0.5) == truth ? 1 : 0;
        if (of_truth < kFloor) ++s.clamped;
        s.log_p += std::log(std::max(of_truth, kFloor));
        if (g.index.atom[q] >= 0) world[static_cast<std::size_t>(g.index.atom[q])] = truth ? 1 : 0;
      }
    }
    ++e.worlds;
    const double lw = g.network.log_weight(world);
    if (std::isinf(lw)) ++e.infeasible;
    else e.joint_cll += lw - r.log_z;
  }
  return e;
}

}  // namespace ksmc::tools::mln_tabletop
