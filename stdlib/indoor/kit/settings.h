// The indoor kit's reading of a DomainConfig (runtime/domain/config.h): every extract, prior,
// likelihood, kernel source and schedule row of domains/indoor.ksm as plain parameters in
// base units (metres, radians, cells). A call the kit does not implement, a missing or
// ill-typed parameter, or an out-of-range value is a ConfigError naming the call's `where`.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "runtime/domain/config.h"

namespace ksmc::stdlib::indoor::kit {

using Lut = std::array<std::array<double, 3>, 3>;  // lut[world class][map class], .ksm order

struct ClassifierSettings {  // geom.room_like / corridor_like / hall_like (Table 3.6)
  double big_size_m = 10.0;
  double big_ratio = 3.0;
};

struct SemanticSettings {
  bool enabled = false;            // the .ksm declares the semantic extractors and an MLN
  ClassifierSettings classifier;
  double adjacent_dilate_cells = 2.0;
  int multi_door_min = 2;
  // The semantic prior `for a, b where P(SaLe(a, b)) > t: gaussian(wall_length_diff, sigma)`.
  bool sale_prior = false;
  std::string sale_predicate = "SaLe";
  std::string sale_op = ">";
  double sale_threshold = 0.5;
  double sale_sigma_m = 0.3;
  // Query predicates that give a unit its type, and the lenient ones.
  std::vector<std::string> type_predicates{"Room", "Corr", "Hall", "Other"};
  std::vector<std::string> lenient_types;
};

struct SourceSettings {
  bool wbu = false;
  double wbu_min_size_m = 1.5;
  int wbu_max_units = 200;
  bool fsu = false;
  std::int64_t fsu_after = 4000;
  int fsu_min_area_cells = 100;
  bool rpb = false;
  double rpb_min_size_m = 1.0;
  bool split = false;
  int split_min_votes = 20;
  double split_angle_tol_rad = 0.03490658503988659;
  bool wall_shift = false;
  double wall_shift_sigma_cells = 2.0;
  bool doors = false;
  double door_min_width_m = 0.6;
  double door_max_width_m = 2.0;
};

struct ScheduleRowSettings {
  std::uint64_t begin = 0, end = 0;  // end == UINT64_MAX: open
  std::vector<std::pair<std::string, double>> probabilities;
};

struct IndoorSettings {
  Lut lut{};
  Lut lenient_lut{};
  double psi1 = 1.0;      // rect_penalty weight: log prior -= psi1 per misaligned wall pair
  double tol_rad = 0.08726646259971647;
  double psi2 = 1.0;      // overlap_penalty weight: log prior -= psi2 per overlapping cell
  SemanticSettings semantic;
  SourceSettings sources;
  std::vector<std::pair<std::string, std::string>> kernels;  // (name, reverse), config order
  std::vector<ScheduleRowSettings> schedule;
};

// Throws runtime::domain::ConfigError (naming the call's where) on anything it cannot honour.
IndoorSettings read_settings(const runtime::domain::DomainConfig& config);

}  // namespace ksmc::stdlib::indoor::kit
