#include "runtime/domain/labels.h"

namespace ksmc::runtime::domain {

std::vector<LabelGroup> label_groups(const mln::Program& program, std::int32_t constant_type) {
  std::vector<LabelGroup> out;
  for (std::size_t g = 0; g < program.groups.size(); ++g) {
    const auto& members = program.groups[g].predicates;
    bool labels = !members.empty();
    for (const std::int32_t p : members) {
      const mln::Predicate& pred = program.predicates[static_cast<std::size_t>(p)];
      labels = labels && pred.query && pred.arg_types.size() == 1 && pred.arg_types[0] == constant_type;
    }
    if (labels) out.push_back({members, g});
  }
  return out;
}

std::size_t most_probable(const std::vector<double>& probabilities) {
  std::size_t best = 0;
  for (std::size_t k = 1; k < probabilities.size(); ++k)
    if (probabilities[k] > probabilities[best]) best = k;
  return best;
}

}  // namespace ksmc::runtime::domain
