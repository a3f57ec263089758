// Labels of scene elements: the `exactly one of` blocks of a program whose members are unary
// query predicates over the kit's constant type (`hard exactly one of Room(u), Corr(u), ...`).
// A kit that reports a type per element (indoor units) reads the members of such a group,
// whatever their names and number; `ksmc check` gives `set<label>` parameters the same meaning.
#pragma once

#include <cstdint>
#include <vector>

#include "runtime/mln/program.h"

namespace ksmc::runtime::domain {

struct LabelGroup {
  std::vector<std::int32_t> predicates;  // program ids, in the order of the block
  std::size_t group = 0;                 // index into Program::groups
};

// Every such group, in program order.
std::vector<LabelGroup> label_groups(const mln::Program& program, std::int32_t constant_type);

// The most probable label among `probabilities` (one per group member): the first maximum.
std::size_t most_probable(const std::vector<double>& probabilities);

}  // namespace ksmc::runtime::domain
