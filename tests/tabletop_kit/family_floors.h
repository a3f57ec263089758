// The per-family accuracy floors the family tests assert (test_kit_families.cpp on
// tools/tabletop_families, test_kit_indep.cpp on tools/tabletop_indep): per family the least
// false F1, hidden F1, support-edge F1 and the largest undecided share (% of the truly false
// or hidden objects). Catch2 only.
#pragma once

#include <catch2/catch.hpp>

#include <iostream>
#include <span>
#include <vector>

#include "tests/tabletop_kit/family_score.h"

namespace ksmc::tests::tabletop_kit {

struct Floor {
  const char* family;
  double false_f1, hidden_f1, support_f1, undecided_pct;
};

// Scores every family with `evaluate(name)`, checks its floor, prints the table.
template <typename Evaluate>
std::vector<FamilyScore> check_floors(std::span<const Floor> floors, Evaluate evaluate) {
  std::vector<FamilyScore> rows;
  for (const Floor& f : floors) {
    rows.push_back(evaluate(f.family));
    const Score& s = rows.back().score;
    INFO(f.family);
    CHECK(s.is_false.f1() >= f.false_f1);
    CHECK(s.is_hidden.f1() >= f.hidden_f1);
    CHECK(s.support.f1() >= f.support_f1);
    CHECK(rows.back().undecided_percent() <= f.undecided_pct);
  }
  std::cout << family_table(rows) << pooled_line(rows) << false_kind_lines(rows);
  return rows;
}

}  // namespace ksmc::tests::tabletop_kit
