// Bullet rigid-body simulation of boxes dropped on a table, with a strict at-rest check.
// Deterministic: fixed time step, single thread, bodies added in input order.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "tools/tabletop_sim/box_geometry.h"

namespace ksmc::tools::tabletop_sim {

struct SimBody {
  Box box;  // initial pose (table frame)
  double mass = 0.3;
  double friction = 0.5;
};

struct TableSpec {
  Eigen::Vector2d half_extent{0.6, 0.4};  // table top, metres, centred at the table-frame origin
  double thickness = 0.04;
  double friction = 0.5;
};

struct SettleParams {
  double time_step = 1.0 / 240.0;  // s, fixed
  int solver_iterations = 40;
  double min_time = 1.5;   // s simulated before the first rest check
  double max_time = 10.0;  // s; a scene not at rest by then is "not settled"
  // Instantaneous rest: every body below these speeds for `rest_window` seconds.
  double linear_speed_tol = 0.002;   // m/s
  double angular_speed_tol = 0.02;   // rad/s
  double rest_window = 0.5;          // s
  // Creep check: poses now vs. `creep_window` seconds ago.
  double creep_window = 1.0;               // s
  double creep_translation_tol = 0.0005;   // m
  double creep_rotation_tol = 0.005;       // rad (~0.29 deg)
};

enum class SettleStatus { settled, fell_off_table, not_settled };

struct SettleResult {
  SettleStatus status = SettleStatus::not_settled;
  std::vector<Pose> poses;  // final poses, same order as the input bodies
  double time = 0.0;        // simulated seconds
  std::string detail;       // why it failed, for the redraw log
};

SettleResult settle(std::span<const SimBody> bodies, const TableSpec& table, const SettleParams& params);

struct Drift {
  double max_translation = 0.0;  // m
  double max_rotation = 0.0;     // rad
  int worst_body = -1;
};

// Starts a fresh world with the bodies at rest at their given poses, simulates `seconds` and
// reports how far anything moved (the check that a settled configuration is really at rest).
Drift resimulate(std::span<const SimBody> bodies, const TableSpec& table, const SettleParams& params,
                 double seconds);

}  // namespace ksmc::tools::tabletop_sim
