#include "stdlib/indoor/coverage.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace ksmc::stdlib::indoor {

int covering_units(const CellCounts& c) {
  int n = 0;
  for (auto a : c.area) n += a;
  return n;
}

int lut_class_of(const CellCounts& c) {
  for (int k = kMaxLutClasses - 1; k > 0; --k)
    if (c.area[static_cast<std::size_t>(k)] > 0) return k;
  return 0;
}

Predicted predicted_class(const CellCounts& c) {
  if (c.door > 0) return Predicted::Free;
  if (c.wall > 0) return Predicted::Wall;
  if (covering_units(c) > 0) return Predicted::Free;
  return Predicted::Unknown;
}

CoverageGrid::CoverageGrid(const ClassGrid& observed) : rows_(observed.rows), cols_(observed.cols) {
  if (observed.empty()) throw std::invalid_argument("CoverageGrid: empty class grid");
  cells_.resize(static_cast<std::size_t>(rows_) * static_cast<std::size_t>(cols_));
  for (int r = 0; r < rows_; ++r) {
    const std::uint8_t* row = observed.ptr<std::uint8_t>(r);
    for (int c = 0; c < cols_; ++c) {
      if (row[c] > 2)
        throw std::invalid_argument("CoverageGrid: class grid value " + std::to_string(row[c]) +
                                    " at row " + std::to_string(r) + ", col " +
                                    std::to_string(c) + " is not a Cell (0..2)");
      CellCounts& cc = cells_[index(r, c)];
      cc.observed = row[c];
      cc.key = static_cast<std::uint8_t>(histogram_index(0, static_cast<Cell>(row[c]), Predicted::Unknown));
      ++hist_[cc.key];
    }
  }
}

namespace {
// Histogram index of a cell from its counts, using the cached total (hot path).
int key_of(const CellCounts& c) {
  const int lut = c.area[3] ? 3 : c.area[2] ? 2 : c.area[1] ? 1 : 0;
  const Predicted p = c.door ? Predicted::Free
                      : c.wall ? Predicted::Wall
                      : c.total ? Predicted::Free
                                : Predicted::Unknown;
  return lut * 9 + c.observed * 3 + static_cast<int>(p);
}
static_assert(kMaxLutClasses == 4, "key_of assumes four likelihood classes");

[[noreturn]] void count_out_of_range() {
  throw std::logic_error("CoverageGrid: cell count out of range (removing what was never added?)");
}

bool in(const RowSpan& s, int x) { return x >= s.x0 && x < s.x1; }

// Sorted unique break points of up to 8 span ends.
int breaks(const RowSpan* spans, int n, int* out) {
  int m = 0;
  for (int i = 0; i < n; ++i) {
    if (spans[i].empty()) continue;
    out[m++] = spans[i].x0;
    out[m++] = spans[i].x1;
  }
  std::sort(out, out + m);
  return static_cast<int>(std::unique(out, out + m) - out);
}
}  // namespace

inline void CoverageGrid::bump(std::size_t idx, int lut_class, int d_area, int d_wall, int d_door) {
  ++visited_;
  CellCounts& c = cells_[idx];
  const int k0 = c.key;
  const int t0 = c.total;
  auto& slot = c.area[static_cast<std::size_t>(lut_class)];
  const int a = slot + d_area, t = t0 + d_area, w = c.wall + d_wall, d = c.door + d_door;
  if ((a | t | w | d) < 0 || (a | t | w | d) > 0xFFFF) [[unlikely]]
    count_out_of_range();
  slot = static_cast<std::uint16_t>(a);
  c.total = static_cast<std::uint16_t>(t);
  c.wall = static_cast<std::uint16_t>(w);
  c.door = static_cast<std::uint16_t>(d);
  const int k1 = key_of(c);
  if (k0 != k1) {
    c.key = static_cast<std::uint8_t>(k1);
    --hist_[static_cast<std::size_t>(k0)];
    ++hist_[static_cast<std::size_t>(k1)];
  }
  overlap_ += std::max(t - 1, 0) - std::max(t0 - 1, 0);
}

void CoverageGrid::unit_rows(const UnitRaster* before, const UnitRaster* after, int lut_class) {
  if (lut_class < 0 || lut_class >= kMaxLutClasses)
    throw std::invalid_argument("CoverageGrid: lut class " + std::to_string(lut_class) +
                                " out of range");
  int r0 = rows_, r1 = 0;
  for (const UnitRaster* u : {before, after}) {
    if (!u || u->outer.empty()) continue;
    r0 = std::min(r0, u->outer.row_begin());
    r1 = std::max(r1, u->outer.row_end());
  }
  r0 = std::max(r0, 0);
  r1 = std::min(r1, rows_);
  for (int row = r0; row < r1; ++row) {
    RowSpan sp[4];
    if (before) { sp[0] = before->outer.span(row); sp[1] = before->inner.span(row); }
    if (after) { sp[2] = after->outer.span(row); sp[3] = after->inner.span(row); }
    int bp[8];
    const int m = breaks(sp, 4, bp);
    for (int i = 0; i + 1 < m; ++i) {
      const int x = bp[i];
      const int oa = in(sp[0], x), ow = oa && !in(sp[1], x);
      const int na = in(sp[2], x), nw = na && !in(sp[3], x);
      const int da = na - oa, dw = nw - ow;
      if (!da && !dw) continue;
      const std::size_t base = index(row, 0);
      for (int c = bp[i]; c < bp[i + 1]; ++c)
        bump(base + static_cast<std::size_t>(c), lut_class, da, dw, 0);
    }
  }
}

inline void CoverageGrid::bump_classes(std::size_t idx, const std::array<int, kMaxLutClasses>& d_area, int d_wall) {
  ++visited_;
  CellCounts& c = cells_[idx];
  const int k0 = c.key;
  const int t0 = c.total;
  int t = t0, bad = 0;
  std::array<int, kMaxLutClasses> a{};
  for (std::size_t k = 0; k < a.size(); ++k) {
    a[k] = c.area[k] + d_area[k];
    t += d_area[k];
    bad |= a[k];
  }
  const int w = c.wall + d_wall;
  bad |= t | w;
  if (bad < 0 || bad > 0xFFFF) [[unlikely]]
    count_out_of_range();
  for (std::size_t k = 0; k < a.size(); ++k) c.area[k] = static_cast<std::uint16_t>(a[k]);
  c.total = static_cast<std::uint16_t>(t);
  c.wall = static_cast<std::uint16_t>(w);
  const int k1 = key_of(c);
  if (k0 != k1) {
    c.key = static_cast<std::uint8_t>(k1);
    --hist_[static_cast<std::size_t>(k0)];
    ++hist_[static_cast<std::size_t>(k1)];
  }
  overlap_ += std::max(t - 1, 0) - std::max(t0 - 1, 0);
}

template <class PerRun>
void CoverageGrid::sweep_units(std::span<const Footprint> fs, PerRun&& per_run) const {
  if (fs.size() > kMaxJointFootprints)
    throw std::invalid_argument("CoverageGrid::update_units: more than " + std::to_string(kMaxJointFootprints) +
                                " footprints");
  int r0 = rows_, r1 = 0;
  for (const Footprint& f : fs) {
    if (f.lut_class < 0 || f.lut_class >= kMaxLutClasses)
      throw std::invalid_argument("CoverageGrid: lut class " + std::to_string(f.lut_class) + " out of range");
    if (f.sign != 1 && f.sign != -1) throw std::invalid_argument("CoverageGrid::update_units: sign must be +1 or -1");
    if (!f.raster || f.raster->outer.empty()) continue;
    r0 = std::min(r0, f.raster->outer.row_begin());
    r1 = std::max(r1, f.raster->outer.row_end());
  }
  r0 = std::max(r0, 0);
  r1 = std::min(r1, rows_);
  const std::size_t n = fs.size();
  for (int row = r0; row < r1; ++row) {
    RowSpan sp[2 * kMaxJointFootprints];
    for (std::size_t i = 0; i < n; ++i)
      if (fs[i].raster) {
        sp[2 * i] = fs[i].raster->outer.span(row);
        sp[2 * i + 1] = fs[i].raster->inner.span(row);
      }
    int bp[4 * kMaxJointFootprints];
    const int m = breaks(sp, static_cast<int>(2 * n), bp);
    const std::size_t base = index(row, 0);
    for (int j = 0; j + 1 < m; ++j) {
      const int x = bp[j];
      std::array<int, kMaxLutClasses> da{};
      int dw = 0;
      bool any = false;
      for (std::size_t i = 0; i < n; ++i) {
        if (!in(sp[2 * i], x)) continue;
        da[static_cast<std::size_t>(fs[i].lut_class)] += fs[i].sign;
        if (!in(sp[2 * i + 1], x)) dw += fs[i].sign;
      }
      for (int v : da) any = any || v != 0;
      if (!any && dw == 0) continue;
      per_run(base + static_cast<std::size_t>(bp[j]), base + static_cast<std::size_t>(bp[j + 1]), da, dw);
    }
  }
}

void CoverageGrid::update_units(std::span<const Footprint> fs) {
  sweep_units(fs, [this](std::size_t i0, std::size_t i1, const std::array<int, kMaxLutClasses>& da, int dw) {
    for (std::size_t idx = i0; idx < i1; ++idx) bump_classes(idx, da, dw);
  });
}

namespace {
// The counts that decide a cell's histogram index apart from its observed class: the areas
// per class, the wall and the door counts (the total is their sum).
struct CountPattern {
  std::array<std::uint16_t, kMaxLutClasses> area;
  std::uint16_t wall, door;
  bool operator==(const CountPattern&) const = default;
};
CountPattern pattern_of(const CellCounts& c) { return {c.area, c.wall, c.door}; }
}  // namespace

CoverageGrid::Delta CoverageGrid::preview_units(std::span<const Footprint> fs) const {
  Delta d;
  // Along a run the change (da, dw) is the same for every cell, and neighbouring cells mostly
  // share their counts: the index shift and the overlap change are worked out once per
  // pattern. The observed class adds the same 3 * observed to the index before and after, so
  // a cell's new index is its cached key plus the pattern's shift.
  sweep_units(fs, [this, &d](std::size_t i0, std::size_t i1, const std::array<int, kMaxLutClasses>& da, int dw) {
    CountPattern last{};
    bool have = false;
    int shift = 0;
    std::int64_t d_overlap = 0;
    for (std::size_t idx = i0; idx < i1; ++idx) {
      const CellCounts& now = cells_[idx];
      const CountPattern pat = pattern_of(now);
      if (!have || !(pat == last)) {
        CellCounts c = now;
        c.observed = 0;
        const int k0 = key_of(c);
        const int t0 = c.total;
        int t = t0, bad = 0;
        for (std::size_t k = 0; k < da.size(); ++k) {
          const int a = c.area[k] + da[k];
          t += da[k];
          bad |= a;
          c.area[k] = static_cast<std::uint16_t>(a);
        }
        const int w = c.wall + dw;
        bad |= t | w;
        if (bad < 0 || bad > 0xFFFF) [[unlikely]]
          count_out_of_range();
        c.total = static_cast<std::uint16_t>(t);
        c.wall = static_cast<std::uint16_t>(w);
        shift = key_of(c) - k0;
        d_overlap = std::max(t - 1, 0) - std::max(t0 - 1, 0);
        last = pat;
        have = true;
      }
      if (shift) {
        --d.hist[now.key];
        ++d.hist[static_cast<std::size_t>(now.key + shift)];
      }
      d.overlap += d_overlap;
    }
  });
  return d;
}

void CoverageGrid::door_rows(const SpanRaster* before, const SpanRaster* after) {
  int r0 = rows_, r1 = 0;
  for (const SpanRaster* s : {before, after}) {
    if (!s || s->empty()) continue;
    r0 = std::min(r0, s->row_begin());
    r1 = std::max(r1, s->row_end());
  }
  r0 = std::max(r0, 0);
  r1 = std::min(r1, rows_);
  for (int row = r0; row < r1; ++row) {
    RowSpan sp[2];
    if (before) sp[0] = before->span(row);
    if (after) sp[1] = after->span(row);
    int bp[4];
    const int m = breaks(sp, 2, bp);
    for (int i = 0; i + 1 < m; ++i) {
      const int d = static_cast<int>(in(sp[1], bp[i])) - static_cast<int>(in(sp[0], bp[i]));
      if (!d) continue;
      const std::size_t base = index(row, 0);
      for (int c = bp[i]; c < bp[i + 1]; ++c) bump(base + static_cast<std::size_t>(c), 0, 0, 0, d);
    }
  }
}

void CoverageGrid::update_unit(const UnitRaster* before, int before_class, const UnitRaster* after,
                               int after_class) {
  if (before && after && before_class != after_class) {
    unit_rows(before, nullptr, before_class);
    unit_rows(nullptr, after, after_class);
    return;
  }
  unit_rows(before, after, before ? before_class : after_class);
}

void CoverageGrid::update_door(const SpanRaster* before, const SpanRaster* after) {
  door_rows(before, after);
}

}  // namespace ksmc::stdlib::indoor
