#include "stdlib/indoor/likelihood.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace ksmc::stdlib::indoor {

LikelihoodTable LikelihoodTable::table_3_1() {
  LikelihoodTable t;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      t.p[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = 0.1;
  // Diagonal: predicted Free/Unknown/Wall against observed Free/Unknown/Occupied.
  t.p[0][0] = t.p[1][1] = t.p[2][2] = 0.8;
  return t;
}

LikelihoodModel::LikelihoodModel(std::vector<LikelihoodTable> tables) {
  if (tables.empty() || tables.size() > static_cast<std::size_t>(kMaxLutClasses))
    throw std::invalid_argument("LikelihoodModel: need 1.." + std::to_string(kMaxLutClasses) +
                                " lookup tables, got " + std::to_string(tables.size()));
  for (int k = 0; k < kMaxLutClasses; ++k) {
    const std::size_t src = static_cast<std::size_t>(k) < tables.size() ? static_cast<std::size_t>(k) : 0;
    for (int pr = 0; pr < 3; ++pr)
      for (int ob = 0; ob < 3; ++ob) {
        const double v = tables[src].p[static_cast<std::size_t>(pr)][static_cast<std::size_t>(ob)];
        if (!std::isfinite(v) || !(v > 0.0))
          throw std::invalid_argument("LikelihoodModel: table " + std::to_string(src) +
                                      " entry [predicted " + std::to_string(pr) + "][observed " +
                                      std::to_string(ob) + "] = " + std::to_string(v) +
                                      " must be finite and > 0");
        log_[static_cast<std::size_t>(
            histogram_index(k, static_cast<Cell>(ob), static_cast<Predicted>(pr)))] = std::log(v);
      }
  }
}

double LikelihoodModel::log_likelihood(const Histogram& h) const {
  double s = 0.0;
  for (std::size_t i = 0; i < h.size(); ++i)
    if (h[i] != 0) s += static_cast<double>(h[i]) * log_[i];
  return s;
}

CellConfusion cell_confusion(const Histogram& h) {
  CellConfusion out{};
  for (int k = 0; k < kMaxLutClasses; ++k)
    for (int o = 0; o < 3; ++o)
      for (int p = 0; p < 3; ++p)
        out[static_cast<std::size_t>(o)][static_cast<std::size_t>(p)] +=
            h[static_cast<std::size_t>(histogram_index(k, static_cast<Cell>(o), static_cast<Predicted>(p)))];
  return out;
}

double cell_prediction_rate(const Histogram& h) {
  const CellConfusion m = cell_confusion(h);
  std::int64_t total = 0, match = 0;
  for (std::size_t o = 0; o < 3; ++o)
    for (std::size_t p = 0; p < 3; ++p) {
      total += m[o][p];
      // Free=0/Free=0, Unknown=1/Unknown=1, Occupied=2/Wall=2.
      if (o == p) match += m[o][p];
    }
  return total > 0 ? static_cast<double>(match) / static_cast<double>(total) : 0.0;
}

FullScore full_score(const ClassGrid& observed, const World& world, const LikelihoodModel& lik,
                     const RasterParams& raster) {
  const int rows = observed.rows, cols = observed.cols;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
      if (observed(r, c) > 2)
        throw std::invalid_argument("full_score: class grid value at row " + std::to_string(r) + ", col " +
                                    std::to_string(c) + " is not a Cell (0..2)");
  std::vector<CellCounts> cells(static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols));
  auto at = [&](int r, int c) -> CellCounts& {
    return cells[static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) +
                 static_cast<std::size_t>(c)];
  };
  for (const Unit& u : world.units()) {
    const UnitRaster ur(u.rect, raster.wall_thickness, cols);
    if (ur.outer.empty()) continue;
    for (int r = std::max(ur.outer.row_begin(), 0); r < std::min(ur.outer.row_end(), rows); ++r) {
      const RowSpan o = ur.outer.span(r), i = ur.inner.span(r);
      for (int c = o.x0; c < o.x1; ++c) {
        ++at(r, c).area[u.lut_class];
        if (!(c >= i.x0 && c < i.x1)) ++at(r, c).wall;
      }
    }
  }
  for (const Door& d : world.doors()) {
    const SpanRaster dr(door_rect(d.a, d.b, raster.door_depth_or_default()), cols);
    if (dr.empty()) continue;
    for (int r = std::max(dr.row_begin(), 0); r < std::min(dr.row_end(), rows); ++r) {
      const RowSpan s = dr.span(r);
      for (int c = s.x0; c < s.x1; ++c) ++at(r, c).door;
    }
  }
  FullScore out;
  std::int64_t match = 0;
  for (int r = 0; r < rows; ++r) {
    const std::uint8_t* orow = observed.ptr<std::uint8_t>(r);
    for (int c = 0; c < cols; ++c) {
      const CellCounts& cc = at(r, c);
      const Cell ob = static_cast<Cell>(orow[c]);
      const Predicted pr = predicted_class(cc);
      out.log_likelihood += lik.log_p(lut_class_of(cc), ob, pr);
      out.overlap += std::max(covering_units(cc) - 1, 0);
      match += static_cast<int>(ob) == static_cast<int>(pr) ? 1 : 0;
    }
  }
  out.prediction_rate = static_cast<double>(match) / (static_cast<double>(rows) * cols);
  return out;
}

cv::Mat1b render_predicted(const CoverageGrid& grid) {
  cv::Mat1b out(grid.rows(), grid.cols());
  for (int r = 0; r < grid.rows(); ++r)
    for (int c = 0; c < grid.cols(); ++c)
      out(r, c) = static_cast<std::uint8_t>(grid.predicted(r, c));
  return out;
}

double one_cell_gain(const LikelihoodModel& lik) {
  double gain = std::numeric_limits<double>::infinity();
  for (int k = 0; k < kMaxLutClasses; ++k)
    for (int o = 0; o < 3; ++o) {
      const auto obs = static_cast<Cell>(o);
      double other = -std::numeric_limits<double>::infinity();
      for (int x = 0; x < 3; ++x)
        if (x != o) other = std::max(other, lik.log_p(k, obs, static_cast<Predicted>(x)));
      gain = std::min(gain, lik.log_p(k, obs, static_cast<Predicted>(o)) - other);
    }
  if (!(gain > 0.0))
    throw std::invalid_argument("one_cell_gain: some likelihood table does not favour the correct prediction of a cell");
  return gain;
}


}  // namespace ksmc::stdlib::indoor
