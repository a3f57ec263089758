// Cell prediction rate K(W, M) of seed eq. 3.39: the fraction of cells whose observed class
// C_M(x, y) (eq. 3.7) equals the class C_W(x, y) predicted by the world W (eq. 3.8).
#pragma once

#include <cstddef>

#include "stdlib/indoor/cell.h"

namespace ksmc::stdlib::indoor::io {

struct PredictionRate {
  std::size_t matching = 0;  // sum of l(c) over the map
  std::size_t total = 0;     // t_M
  double rate() const { return total == 0 ? 0.0 : static_cast<double>(matching) / static_cast<double>(total); }
};

// `observed` holds Cell values, `predicted` Predicted values (Free/Unknown/Wall share the numbering
// 0/1/2 with Cell Free/Unknown/Occupied). Throws std::invalid_argument when the sizes differ or
// a grid is empty.
PredictionRate cell_prediction_rate(const ClassGrid& observed, const cv::Mat1b& predicted);

}  // namespace ksmc::stdlib::indoor::io
