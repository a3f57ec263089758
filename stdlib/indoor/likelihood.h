// Likelihood p(M|W) of eq. 3.6 with the 3x3 lookup table of Table 3.1, in log space, evaluated
// from the coverage histogram in O(1); plus full (non-incremental) recomputations used to
// verify the incremental bookkeeping and the cell prediction rate K(W,M) of eq. 3.39.
#pragma once

#include <array>
#include <vector>

#include "stdlib/indoor/cell.h"
#include "stdlib/indoor/coverage.h"
#include "stdlib/indoor/world.h"

namespace ksmc::stdlib::indoor {

// p(c | W): p[predicted][observed], indexed by the Predicted and Cell enums (Table 3.1 layout:
// rows = C_W, columns = C_M). Entries must be finite and > 0.
struct LikelihoodTable {
  std::array<std::array<double, 3>, 3> p{};
  static LikelihoodTable table_3_1();  // 0.8 on the diagonal, 0.1 elsewhere
};

// One table per likelihood class (index = Unit::lut_class); at least one, at most
// kMaxLutClasses. A class without its own table uses table 0.
class LikelihoodModel {
 public:
  explicit LikelihoodModel(std::vector<LikelihoodTable> tables = {LikelihoodTable::table_3_1()});
  double log_p(int lut_class, Cell observed, Predicted predicted) const {
    return log_[static_cast<std::size_t>(histogram_index(lut_class, observed, predicted))];
  }
  // Sum over the histogram of count * log p (exact for a given histogram).
  double log_likelihood(const Histogram& h) const;

 private:
  std::array<double, kHistogramSize> log_{};
};

// The smallest gain in log p(D|W) from correcting one cell under `lik`: over the observed
// classes o and likelihood classes k, log p_k(o|o) - max_{x != o} log p_k(o|x) (predicted x,
// observed o; Free/Unknown/Wall against Free/Unknown/Occupied). ln 8 = 2.079 for Table 3.1.
// The unit of the indoor binary's plateau (--iterations auto, runtime/mcmc/plateau.h).
// Throws std::invalid_argument if no table rewards the correct prediction (result <= 0).
double one_cell_gain(const LikelihoodModel& lik);

// Geometry of the predicted map.
struct RasterParams {
  double wall_thickness = 1.0;  // wall band width inside each unit, cells
  double door_depth = 0.0;      // door rectangle depth across the wall; <= 0: 2*wall + 2
  double door_depth_or_default() const {
    return door_depth > 0.0 ? door_depth : 2.0 * wall_thickness + 2.0;
  }
};

// Cells by observed class (row: Free/Unknown/Occupied) and predicted class (column:
// Free/Unknown/Wall), summed over the likelihood classes of a histogram.
using CellConfusion = std::array<std::array<std::int64_t, 3>, 3>;
CellConfusion cell_confusion(const Histogram& h);

// Cell prediction rate K(W,M) (eq. 3.39) from a histogram: share of cells with
// observed Free/Unknown/Occupied predicted Free/Unknown/Wall (the confusion's diagonal).
double cell_prediction_rate(const Histogram& h);

// Full recomputation from scratch: paints every unit and door of `world` into fresh counts and
// sums log p per cell. O(map + footprints); used by tests and for verification.
struct FullScore {
  double log_likelihood = 0.0;
  std::int64_t overlap = 0;
  double prediction_rate = 0.0;
};
FullScore full_score(const ClassGrid& observed, const World& world, const LikelihoodModel& lik,
                     const RasterParams& raster);

// The predicted map C_W as an image of Predicted values (0 free, 1 unknown, 2 wall).
cv::Mat1b render_predicted(const CoverageGrid& grid);

}  // namespace ksmc::stdlib::indoor
