// Cell coverage counts of the world (units' areas per likelihood class, walls, doors) over the
// map, and the histogram of (likelihood class, observed class, predicted class) they induce.
// The predicted class C_W (eq. 3.8) of a cell is: a door covers it -> Free (doorway); else a
// wall band covers it -> Wall; else a unit covers it -> Free; else Unknown. Its likelihood
// class is the highest lut_class among the units covering it (0 if none).
// Updates visit only the cells whose counts change (row-span differences), so a wall shift
// costs the cells between the old and new wall bands, not the unit's area.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "stdlib/indoor/cell.h"
#include "stdlib/indoor/raster.h"
#include "stdlib/indoor/world.h"

namespace ksmc::stdlib::indoor {

inline constexpr int kHistogramSize = kMaxLutClasses * 9;
using Histogram = std::array<std::int64_t, kHistogramSize>;
inline constexpr int histogram_index(int lut_class, Cell observed, Predicted predicted) {
  return lut_class * 9 + static_cast<int>(observed) * 3 + static_cast<int>(predicted);
}

struct CellCounts {
  std::array<std::uint16_t, kMaxLutClasses> area{};  // units covering the cell, per lut class
  std::uint16_t wall = 0;                            // wall bands covering the cell
  std::uint16_t door = 0;                            // doors covering the cell
  // Kept by CoverageGrid only (the full recomputation ignores them): sum of `area`, the
  // observed class, and the cell's current histogram index.
  std::uint16_t total = 0;
  std::uint8_t observed = 0;
  std::uint8_t key = 0;
};
static_assert(sizeof(CellCounts) == 16, "one cell's counts fit 16 bytes");

// Classification shared by the incremental grid and the full recomputation.
Predicted predicted_class(const CellCounts& c);
int lut_class_of(const CellCounts& c);
int covering_units(const CellCounts& c);

class CoverageGrid {
 public:
  // `observed` must hold Cell values (0..2); throws std::invalid_argument otherwise.
  explicit CoverageGrid(const ClassGrid& observed);

  int rows() const { return rows_; }
  int cols() const { return cols_; }

  // Unit footprint replaced: `before` / `after` may be null (unit added / removed). When both
  // are given with the same lut class only the differing cells are visited.
  void update_unit(const UnitRaster* before, int before_class, const UnitRaster* after,
                   int after_class);
  void update_door(const SpanRaster* before, const SpanRaster* after);
  // Several footprints at once, each removed (sign -1) or added (sign +1): the net count
  // change is applied in one sweep, so only cells whose counts change in total are visited
  // (a split or merge costs the cells of the cut walls, not the units' areas).
  struct Footprint {
    const UnitRaster* raster = nullptr;
    int lut_class = 0;
    int sign = 1;
  };
  static constexpr std::size_t kMaxJointFootprints = 8;
  void update_units(std::span<const Footprint> fs);  // at most kMaxJointFootprints
  // What update_units(fs) would change, without changing anything: histogram and overlap
  // deltas (throws like update_units if a count would leave its range).
  struct Delta {
    Histogram hist{};
    std::int64_t overlap = 0;
  };
  Delta preview_units(std::span<const Footprint> fs) const;

  const Histogram& histogram() const { return hist_; }
  // Cells visited by updates so far (each visit changes that cell's counts).
  std::uint64_t cells_visited() const { return visited_; }
  // Sum over cells of max(sigma - 1, 0), sigma = number of units covering the cell (eq. 3.5).
  std::int64_t overlap() const { return overlap_; }

  Cell observed(int row, int col) const { return static_cast<Cell>(cells_[index(row, col)].observed); }
  const CellCounts& counts(int row, int col) const { return cells_[index(row, col)]; }
  // The predicted class is the last digit of the cell's histogram index (= predicted_class()).
  Predicted predicted(int row, int col) const { return static_cast<Predicted>(cells_[index(row, col)].key % 3); }

 private:
  std::size_t index(int row, int col) const {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(cols_) +
           static_cast<std::size_t>(col);
  }
  void unit_rows(const UnitRaster* before, const UnitRaster* after, int lut_class);
  void door_rows(const SpanRaster* before, const SpanRaster* after);
  void bump(std::size_t idx, int lut_class, int d_area, int d_wall, int d_door);
  // Calls per_run(first, last, d_area, d_wall) for each run of cells [first, last) of one row
  // whose counts change by the same amounts.
  template <class PerRun>
  void sweep_units(std::span<const Footprint> fs, PerRun&& per_run) const;
  void bump_classes(std::size_t idx, const std::array<int, kMaxLutClasses>& d_area, int d_wall);

  int rows_ = 0, cols_ = 0;
  std::vector<CellCounts> cells_;
  Histogram hist_{};
  std::int64_t overlap_ = 0;
  std::uint64_t visited_ = 0;
};

}  // namespace ksmc::stdlib::indoor
