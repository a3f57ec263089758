#include <cmath>
#include <map>

#include "compiler/check/passes.h"

namespace ksmc::compiler::check {

namespace {

constexpr double kSumTolerance = 1e-9;

std::string row_name(const ast::ScheduleRow& row) {
  if (!row.has_range) return "row";
  return "row [" + row.lo.text + ", " + (row.hi_inf ? std::string("inf") : row.hi.text) + ")";
}

bool plain_iteration(Context& ctx, const ast::Number& n) {
  if (!n.unit.empty()) {
    ctx.diags.error(n.unit_loc, "an iteration number has no unit");
    return false;
  }
  if (!n.integral || n.value < 0) {
    ctx.diags.error(n.loc, "an iteration number must be a non-negative integer, got " + n.text);
    return false;
  }
  return true;
}

void check_row(Context& ctx, const ast::ScheduleRow& row) {
  std::map<std::string, double> probs;
  double sum = 0.0;
  bool ok = true;
  for (const ast::ScheduleEntry& e : row.entries) {
    if (!e.prob.unit.empty()) {
      ctx.diags.error(e.prob.unit_loc, "a selection probability has no unit");
      ok = false;
    }
    if (e.prob.value < 0.0 || e.prob.value > 1.0) {
      ctx.diags.error(e.prob.loc, "selection probability " + e.prob.text + " is outside [0, 1]");
      ok = false;
    }
    if (!probs.emplace(e.kernel.name, e.prob.value).second) {
      ctx.diags.error(e.kernel.loc, "kernel '" + e.kernel.name + "' appears twice in schedule " + row_name(row));
      ok = false;
    }
    sum += e.prob.value;
  }
  if (ok && std::fabs(sum - 1.0) > kSumTolerance) {
    ctx.diags.error(row.loc, "the probabilities of schedule " + row_name(row) + " sum to " + format_number(sum) + ", not 1");
  }
  // Metropolis-Hastings needs the reverse move whenever a move can be proposed.
  for (const ast::ScheduleEntry& e : row.entries) {
    if (e.prob.value <= 0.0) continue;
    auto k = ctx.symbols.kernels.find(e.kernel.name);
    if (k == ctx.symbols.kernels.end() || !k->second.reverse) continue;
    const std::string& rev = k->second.reverse->name;
    auto r = probs.find(rev);
    if (rev != e.kernel.name && ctx.symbols.kernels.count(rev) != 0 && (r == probs.end() || r->second <= 0.0)) {
      ctx.diags.error(e.kernel.loc, "kernel '" + e.kernel.name + "' is scheduled in " + row_name(row) +
                                        " without its reverse '" + rev + "'");
    }
  }
}

}  // namespace

void SchedulePass::run(Context& ctx) {
  for (const ast::ScheduleDecl* s : ctx.symbols.schedules) {
    if (s->rows.empty()) continue;
    double expect_lo = 0.0;
    bool chain_ok = true;
    for (std::size_t i = 0; i < s->rows.size(); ++i) {
      const ast::ScheduleRow& row = s->rows[i];
      check_row(ctx, row);
      if (!row.has_range) {
        if (s->rows.size() > 1) ctx.diags.error(row.loc, "a schedule with several rows needs an iteration range on each");
        continue;
      }
      if (!chain_ok) continue;
      if (!plain_iteration(ctx, row.lo) || (!row.hi_inf && !plain_iteration(ctx, row.hi))) {
        chain_ok = false;
        continue;
      }
      if (row.lo.value != expect_lo) {
        ctx.diags.error(row.lo.loc, i == 0 ? "the first schedule row must start at iteration 0"
                                           : "schedule " + row_name(row) + " must start where the previous row ends (" +
                                                 format_number(expect_lo) + ")");
        chain_ok = false;
        continue;
      }
      if (!row.hi_inf && row.hi.value <= row.lo.value) {
        ctx.diags.error(row.hi.loc, "schedule " + row_name(row) + " is empty");
        chain_ok = false;
        continue;
      }
      const bool last = i + 1 == s->rows.size();
      if (last && !row.hi_inf) ctx.diags.error(row.hi.loc, "the last schedule row must end at inf");
      if (!last && row.hi_inf) ctx.diags.error(row.loc, "only the last schedule row may end at inf");
      expect_lo = row.hi_inf ? expect_lo : row.hi.value;
    }
  }
}

}  // namespace ksmc::compiler::check
