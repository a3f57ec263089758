// Helpers shared by the report's drawings: DOM and SVG builders, number formatting,
// the hover tooltip, tables and a line plot.
"use strict";
var K = {};
K.SVG = "http://www.w3.org/2000/svg";
K.TYPE_COLORS = { room: "#4e79a7", corridor: "#f28e2b", hall: "#59a14f", other: "#b07aa1" };
K.PALETTE = ["#4e79a7", "#f28e2b", "#e15759", "#76b7b2", "#59a14f", "#edc948", "#b07aa1", "#ff9da7", "#9c755f", "#bab0ac"];

K.el = function (tag, attrs, text) {
  var e = document.createElement(tag);
  for (var k in (attrs || {})) e.setAttribute(k, attrs[k]);
  if (text !== undefined && text !== null) e.textContent = String(text);
  return e;
};
K.svg = function (tag, attrs, text) {
  var e = document.createElementNS(K.SVG, tag);
  for (var k in (attrs || {})) e.setAttribute(k, attrs[k]);
  if (text !== undefined && text !== null) e.textContent = String(text);
  return e;
};
K.fmt = function (v, digits) {
  if (v === null || v === undefined) return "-";
  if (typeof v !== "number") return String(v);
  if (Number.isInteger(v)) return String(v);
  var d = digits === undefined ? 4 : digits;
  if (Math.abs(v) >= 1e9 || (Math.abs(v) < 1e-3 && v !== 0)) return v.toExponential(2);
  return String(Number(v.toFixed(d)));
};
K.section = function (id, title) {
  var s = K.el("section", { id: id });
  s.appendChild(K.el("h2", {}, title));
  document.getElementById("report").appendChild(s);
  return s;
};
K.note = function (parent, text) { parent.appendChild(K.el("p", { "class": "note" }, text)); };

// A table from a header list and rows of cells; numbers are right-aligned.
K.table = function (id, header, rows) {
  var t = K.el("table", { id: id });
  var tr = K.el("tr");
  header.forEach(function (h) { tr.appendChild(K.el("th", {}, h)); });
  t.appendChild(tr);
  rows.forEach(function (r) {
    var row = K.el("tr");
    r.forEach(function (c) {
      if (c instanceof Node) { var td = K.el("td"); td.appendChild(c); row.appendChild(td); }
      else row.appendChild(K.el("td", typeof c === "number" ? { "class": "num" } : {}, K.fmt(c)));
    });
    t.appendChild(row);
  });
  return t;
};
// A probability as a number with a small bar.
K.probCell = function (p) {
  var span = K.el("span");
  span.appendChild(K.el("span", { "class": "bar", style: "width:" + Math.round(60 * (p || 0)) + "px" }));
  span.appendChild(document.createTextNode(" " + K.fmt(p, 3)));
  return span;
};

// Hover tooltip: `html` is built from K.el nodes by the caller (a function, called on enter).
K.hover = function (node, build) {
  var tip = document.getElementById("tooltip");
  node.addEventListener("mouseenter", function () {
    tip.textContent = "";
    tip.appendChild(build());
    tip.hidden = false;
  });
  node.addEventListener("mousemove", function (ev) {
    tip.style.left = (ev.clientX + 14) + "px";
    tip.style.top = (ev.clientY + 14) + "px";
  });
  node.addEventListener("mouseleave", function () { tip.hidden = true; });
};
// Key/value lines for a tooltip.
K.lines = function (title, pairs) {
  var d = K.el("div");
  d.appendChild(K.el("b", {}, title));
  pairs.forEach(function (p) { d.appendChild(K.el("div", {}, p[0] + ": " + K.fmt(p[1], 3))); });
  return d;
};

// Line plot: series = [{name, xs, ys, color}] (null ys are gaps).
K.linePlot = function (id, series, xlabel, ylabel, fixedRange) {
  var W = 560, H = 260, L = 64, R = 12, T = 12, B = 40;
  var svg = K.svg("svg", { id: id, viewBox: "0 0 " + W + " " + H, width: W, height: H });
  var x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
  series.forEach(function (s) {
    for (var i = 0; i < s.xs.length; ++i) {
      if (s.ys[i] === null || s.ys[i] === undefined) continue;
      x0 = Math.min(x0, s.xs[i]); x1 = Math.max(x1, s.xs[i]);
      y0 = Math.min(y0, s.ys[i]); y1 = Math.max(y1, s.ys[i]);
    }
  });
  if (fixedRange) { y0 = fixedRange[0]; y1 = fixedRange[1]; }
  if (!isFinite(x0)) { x0 = 0; x1 = 1; y0 = 0; y1 = 1; }
  if (x1 === x0) x1 = x0 + 1;
  if (y1 === y0) { y0 -= 1; y1 += 1; }
  var sx = function (x) { return L + (x - x0) / (x1 - x0) * (W - L - R); };
  var sy = function (y) { return H - B - (y - y0) / (y1 - y0) * (H - T - B); };
  svg.appendChild(K.svg("rect", { x: L, y: T, width: W - L - R, height: H - T - B, fill: "none", stroke: "#999" }));
  for (var k = 0; k <= 4; ++k) {
    var yv = y0 + (y1 - y0) * k / 4, xv = x0 + (x1 - x0) * k / 4;
    svg.appendChild(K.svg("line", { x1: L, x2: W - R, y1: sy(yv), y2: sy(yv), stroke: "#eee" }));
    svg.appendChild(K.svg("text", { x: L - 4, y: sy(yv) + 4, "text-anchor": "end" }, K.fmt(yv, 2)));
    svg.appendChild(K.svg("text", { x: sx(xv), y: H - B + 14, "text-anchor": "middle" }, K.fmt(Math.round(xv))));
  }
  svg.appendChild(K.svg("text", { x: (L + W - R) / 2, y: H - 6, "text-anchor": "middle" }, xlabel));
  svg.appendChild(K.svg("text", { x: 12, y: (T + H - B) / 2, "text-anchor": "middle",
                                  transform: "rotate(-90 12 " + (T + H - B) / 2 + ")" }, ylabel));
  series.forEach(function (s) {
    var d = "", pen = false;
    for (var i = 0; i < s.xs.length; ++i) {
      if (s.ys[i] === null || s.ys[i] === undefined) { pen = false; continue; }
      d += (pen ? "L" : "M") + sx(s.xs[i]).toFixed(1) + " " + sy(s.ys[i]).toFixed(1) + " ";
      pen = true;
    }
    if (d) svg.appendChild(K.svg("path", { d: d, fill: "none", stroke: s.color, "stroke-width": 1.5, "class": "series" }));
  });
  return svg;
};
K.legend = function (items) {
  var d = K.el("div", { "class": "legend" });
  items.forEach(function (it) {
    var s = K.el("span");
    s.appendChild(K.el("span", { "class": "swatch", style: "background:" + it.color }));
    s.appendChild(document.createTextNode(it.name));
    d.appendChild(s);
  });
  return d;
};

// Generic knowledge base marginals: {"pred": number | {args: number} | [[args..., p]]} flattened
// into rows [query, probability].
K.flattenQueries = function (q) {
  var rows = [];
  var walk = function (prefix, v) {
    if (typeof v === "number") rows.push([prefix, v]);
    else if (Array.isArray(v)) v.forEach(function (e, i) {
      if (Array.isArray(e) && typeof e[e.length - 1] === "number") rows.push([prefix + "(" + e.slice(0, -1).join(", ") + ")", e[e.length - 1]]);
      else walk(prefix + "[" + i + "]", e);
    });
    else if (v && typeof v === "object") Object.keys(v).forEach(function (k) { walk(prefix ? prefix + "." + k : k, v[k]); });
  };
  walk("", q);
  return rows;
};
