// The parts every run has: the run summary (summary.json) and, with --trace, the trace
// plots (log posterior per chain, acceptance rate per kernel over the windows).
"use strict";
K.drawSummary = function (data) {
  var s = data.summary || {};
  var sec = K.section("summary", "Run summary");
  var dom = s.domain || {};
  var best = s.best || {};
  var inputs = (s.inputs || []).map(function (i) { return i.path; }).join(", ");
  sec.appendChild(K.table("summary-table", ["", ""], [
    ["domain", (dom.name || "?") + " " + (dom.version || "")],
    ["inputs", inputs || "-"],
    ["seed", s.seed], ["chains", s.chains], ["iterations", s.iterations],
    ["length", K.runLength(s)],
    ["burn-in", s.burn_in], ["seconds", s.seconds], ["iterations / s", s.iterations_per_second],
    ["acceptance rate", s.acceptance_rate],
    ["best log posterior", best.log_posterior],
    ["best chain / iteration", (best.chain === undefined ? "-" : best.chain) + " / " + (best.iteration === undefined ? "-" : best.iteration)],
    ["cancelled", s.cancelled ? "yes (Ctrl-C)" : "no"],
    ["ksmc", s.ksmc_version]]));
  var kernels = s.kernels || [];
  if (kernels.length) {
    sec.appendChild(K.el("h2", {}, "Kernels"));
    sec.appendChild(K.table("kernel-table", ["kernel", "reverse", "selected", "accepted", "declined", "rejected", "acceptance"],
      kernels.map(function (k) { return [k.name, k.reverse, k.selected, k.accepted, k.declined, k.rejected, K.probCell(k.acceptance_rate)]; })));
  }
};

// "fixed: N per chain", or with --iterations auto where each chain's plateau began.
K.runLength = function (s) {
  var u = s.until_plateau;
  if (!u) return "fixed: " + s.iterations_per_chain + " per chain";
  var at = (s.chain_results || []).map(function (c) {
    return c.plateau_iteration === null || c.plateau_iteration === undefined ? "none" : c.plateau_iteration;
  }).join(", ");
  return "until the plateau (gain at most " + Number(u.min_gain).toFixed(3) + " nats over " + u.window +
    " iterations; at most " + s.iterations_per_chain + "): reached by " + u.chains_reached + " of " + s.chains +
    " chains, from iteration " + at;
};

K.drawTrace = function (data) {
  var sec = K.section("trace", "Trace");
  var tr = data.trace;
  if (!tr || !tr.chains || !tr.chains.length) {
    K.note(sec, "No trace.csv in this folder: run with --trace for the log posterior and acceptance plots.");
    return;
  }
  var row = K.el("div", { "class": "row" });
  sec.appendChild(row);
  var lp = tr.chains.map(function (c, i) {
    return { name: "chain " + c.chain, xs: c.iteration, ys: c.log_posterior, color: K.PALETTE[i % K.PALETTE.length] };
  });
  var left = K.el("div");
  left.appendChild(K.el("h2", {}, "Log posterior"));
  left.appendChild(K.linePlot("trace-logpost", lp, "iteration", "log posterior"));
  left.appendChild(K.legend(lp));
  row.appendChild(left);
  // Acceptance per kernel, in the window before each trace row (first chain; others alike).
  var c0 = tr.chains[0];
  var acc = [];
  tr.columns.forEach(function (col) {
    if (col.indexOf("acceptance_") === 0 && col !== "acceptance_window" && col !== "acceptance_total")
      acc.push({ name: col.substring(11), xs: c0.iteration, ys: c0[col], color: K.PALETTE[acc.length % K.PALETTE.length] });
  });
  if (!acc.length) acc.push({ name: "all kernels", xs: c0.iteration, ys: c0.acceptance_window, color: K.PALETTE[0] });
  var right = K.el("div");
  right.appendChild(K.el("h2", {}, "Acceptance rate per kernel (chain " + c0.chain + ")"));
  right.appendChild(K.linePlot("trace-acceptance", acc, "iteration", "acceptance in window", [0, 1]));
  right.appendChild(K.legend(acc));
  row.appendChild(right);
};
