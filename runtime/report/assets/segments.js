// Segments (segments.json): the fitted line segments (hover: length, support, query
// probabilities), the relations between them and the per-segment marginals.
"use strict";
K.drawSegments = function (data) {
  var res = data.segments, segs = res.segments || [];
  var sec = K.section("segments", "Segments: " + segs.length);
  var x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
  segs.forEach(function (s) {
    [s.a, s.b].forEach(function (p) { x0 = Math.min(x0, p[0]); x1 = Math.max(x1, p[0]); y0 = Math.min(y0, p[1]); y1 = Math.max(y1, p[1]); });
  });
  if (!isFinite(x0)) { x0 = 0; x1 = 1; y0 = 0; y1 = 1; }
  var span = Math.max(x1 - x0, y1 - y0, 1e-3), pad = 0.05 * span;
  var W = 640, scale = (W - 40) / (span + 2 * pad);
  var H = Math.round((y1 - y0 + 2 * pad) * scale) + 40;
  var px = function (p) { return [20 + (p[0] - x0 + pad) * scale, H - 20 - (p[1] - y0 + pad) * scale]; };
  var svg = K.svg("svg", { id: "segments-view", viewBox: "0 0 " + W + " " + H, width: W, height: H });
  segs.forEach(function (s, i) {
    var a = px(s.a), b = px(s.b), color = K.PALETTE[i % K.PALETTE.length];
    var l = K.svg("line", { id: "segment-" + s.id, "class": "segment", x1: a[0], y1: a[1], x2: b[0], y2: b[1],
                            stroke: color, "stroke-width": 3, "stroke-linecap": "round" });
    l.appendChild(K.svg("title", {}, "segment " + s.id));
    K.hover(l, function () {
      var probs = Object.keys(s.probabilities || {}).map(function (k) { return ["P(" + k + ")", s.probabilities[k]]; });
      return K.lines("segment " + s.id, [["length (m)", s.length], ["support (points)", s.support]].concat(probs));
    });
    svg.appendChild(l);
    svg.appendChild(K.svg("text", { x: (a[0] + b[0]) / 2 + 4, y: (a[1] + b[1]) / 2 - 4 }, s.id));
  });
  sec.appendChild(svg);
  if (data.images && data.images.overlay) {
    sec.appendChild(K.el("h2", {}, "overlay.png (points and segments)"));
    sec.appendChild(K.el("img", { id: "segments-overlay", src: data.images.overlay, style: "max-width:640px" }));
  }
  var m = res.metrics || {};
  sec.appendChild(K.el("h2", {}, "Metrics"));
  sec.appendChild(K.table("segments-metrics", ["metric", "value"], Object.keys(m).map(function (k) { return [k, m[k]]; })));

  var kb = K.section("marginals", "Knowledge base marginals");
  var preds = [];
  segs.forEach(function (s) { Object.keys(s.probabilities || {}).forEach(function (k) { if (preds.indexOf(k) < 0) preds.push(k); }); });
  kb.appendChild(K.table("segments-table", ["segment", "length (m)", "support"].concat(preds.map(function (p) { return "P(" + p + ")"; })),
    segs.map(function (s) {
      return [s.id, s.length, s.support].concat(preds.map(function (p) { return K.probCell((s.probabilities || {})[p]); }));
    })));
  var rel = res.relations || {}, rows = [];
  Object.keys(rel).forEach(function (name) {
    (rel[name].pairs || []).forEach(function (p) { rows.push([name + (rel[name].query ? " (query)" : " (evidence)"), p[0] + " - " + p[1], K.probCell(p[2])]); });
  });
  kb.appendChild(K.el("h2", {}, "Relations (pairs above 0.5)"));
  kb.appendChild(K.table("relations-table", ["relation", "segments", "probability"], rows));
};
