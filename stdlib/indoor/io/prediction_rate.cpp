#include "stdlib/indoor/io/prediction_rate.h"

#include <cstdint>
#include <stdexcept>
#include <string>

namespace ksmc::stdlib::indoor::io {

static_assert(static_cast<int>(Cell::Free) == static_cast<int>(Predicted::Free));
static_assert(static_cast<int>(Cell::Unknown) == static_cast<int>(Predicted::Unknown));
static_assert(static_cast<int>(Cell::Occupied) == static_cast<int>(Predicted::Wall));

PredictionRate cell_prediction_rate(const ClassGrid& observed, const cv::Mat1b& predicted) {
  if (observed.empty() || predicted.empty()) {
    throw std::invalid_argument("cell_prediction_rate: empty map");
  }
  if (observed.size() != predicted.size()) {
    throw std::invalid_argument(
        "cell_prediction_rate: map is " + std::to_string(observed.cols) + "x" +
        std::to_string(observed.rows) + " but the prediction is " +
        std::to_string(predicted.cols) + "x" + std::to_string(predicted.rows));
  }
  PredictionRate k;
  k.total = static_cast<std::size_t>(observed.rows) * static_cast<std::size_t>(observed.cols);
  for (int r = 0; r < observed.rows; ++r) {
    const std::uint8_t* a = observed.ptr<std::uint8_t>(r);
    const std::uint8_t* b = predicted.ptr<std::uint8_t>(r);
    for (int c = 0; c < observed.cols; ++c) k.matching += a[c] == b[c] ? 1u : 0u;
  }
  return k;
}

}  // namespace ksmc::stdlib::indoor::io
