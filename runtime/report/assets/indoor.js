// Indoor (world.json): the map with units coloured by type, doors and the topology
// (adjacency between unit centres); hovering a unit shows its type probabilities and size
// in metres. Below: the unit table and the knowledge base marginals.
"use strict";
K.unitGeometry = function (u, res) {
  var c = u.corners, cx = 0, cy = 0;
  c.forEach(function (p) { cx += p[0] / c.length; cy += p[1] / c.length; });
  var side = function (a, b) { return Math.hypot(b[0] - a[0], b[1] - a[1]) * res; };
  var w = side(c[0], c[1]), h = c.length > 2 ? side(c[1], c[2]) : 0;
  return { cx: cx, cy: cy, w: w, h: h, area: w * h };
};

K.drawIndoor = function (data) {
  var world = data.world, map = world.map || {};
  var res = map.resolution || 0.05, W = map.width || 1, H = map.height || 1;
  var units = world.units || [], doors = world.doors || [];
  var sec = K.section("indoor", "Semantic map: " + units.length + " units, " + doors.length + " doors");
  var scale = Math.min(3, 900 / Math.max(W, H * 1.5));  // about 900 px wide, small maps enlarged
  var svg = K.svg("svg", { id: "indoor-map", viewBox: [-0.5, -0.5, W, H].join(" "),
                           width: Math.round(W * scale), height: Math.round(H * scale) });
  if (data.images && data.images.overlay) {
    svg.appendChild(K.svg("image", { id: "indoor-overlay", href: data.images.overlay, x: -0.5, y: -0.5, width: W, height: H,
                                     opacity: 0.45, preserveAspectRatio: "none" }));
  } else {
    svg.appendChild(K.svg("rect", { x: -0.5, y: -0.5, width: W, height: H, fill: "#f4f4f4" }));
  }
  var stroke = Math.max(1, W / 400);
  var geom = {};
  var gUnits = K.svg("g", { id: "indoor-units" });
  units.forEach(function (u) {
    var g = K.unitGeometry(u, res);
    geom[u.id] = g;
    var color = K.TYPE_COLORS[u.type] || "#888";
    var poly = K.svg("polygon", { id: "unit-" + u.id, "class": "unit", "data-type": u.type,
                                  points: u.corners.map(function (p) { return p[0] + "," + p[1]; }).join(" "),
                                  fill: color, "fill-opacity": 0.25, stroke: color, "stroke-width": 2 * stroke });
    poly.appendChild(K.svg("title", {}, "unit " + u.id + " " + u.type));
    K.hover(poly, function () {
      var probs = Object.keys(u.type_probs || {}).map(function (k) { return ["P(" + k + ")", u.type_probs[k]]; });
      return K.lines("unit " + u.id + ": " + u.type, probs.concat([
        ["size (m)", K.fmt(g.w, 2) + " x " + K.fmt(g.h, 2)], ["area (m2)", g.area]]));
    });
    gUnits.appendChild(poly);
  });
  svg.appendChild(gUnits);
  var gTopo = K.svg("g", { id: "indoor-topology" });
  (world.adjacent || []).forEach(function (pair) {
    var a = geom[pair[0]], b = geom[pair[1]];
    if (!a || !b) return;
    gTopo.appendChild(K.svg("line", { "class": "topology", x1: a.cx, y1: a.cy, x2: b.cx, y2: b.cy,
                                      stroke: "#333", "stroke-width": stroke, "stroke-dasharray": 4 * stroke + " " + 3 * stroke }));
  });
  units.forEach(function (u) {
    var g = geom[u.id];
    gTopo.appendChild(K.svg("circle", { cx: g.cx, cy: g.cy, r: 3 * stroke, fill: "#333", "pointer-events": "none" }));
    gTopo.appendChild(K.svg("text", { x: g.cx + 4 * stroke, y: g.cy - 4 * stroke, "font-size": 10 * stroke, "pointer-events": "none" },
                            u.id + " " + u.type));
  });
  svg.appendChild(gTopo);
  var gDoors = K.svg("g", { id: "indoor-doors" });
  doors.forEach(function (d) {
    var s = d.segment;
    var line = K.svg("line", { id: "door-" + d.id, "class": "door", x1: s[0][0], y1: s[0][1], x2: s[1][0], y2: s[1][1],
                               stroke: "#d62728", "stroke-width": 4 * stroke, "stroke-linecap": "round" });
    line.appendChild(K.svg("title", {}, "door " + d.id + ": units " + d.units.join(" - ")));
    gDoors.appendChild(line);
  });
  svg.appendChild(gDoors);
  sec.appendChild(svg);
  sec.appendChild(K.legend(Object.keys(K.TYPE_COLORS).map(function (t) { return { name: t, color: K.TYPE_COLORS[t] }; })
    .concat([{ name: "door", color: "#d62728" }, { name: "adjacent (topology)", color: "#333" }])));

  var m = world.metrics || {};
  sec.appendChild(K.el("h2", {}, "Metrics"));
  sec.appendChild(K.table("indoor-metrics", ["metric", "value"], Object.keys(m).map(function (k) { return [k, m[k]]; })));

  var kb = K.section("marginals", "Knowledge base marginals");
  var preds = [];
  units.forEach(function (u) { Object.keys(u.type_probs || {}).forEach(function (k) { if (preds.indexOf(k) < 0) preds.push(k); }); });
  kb.appendChild(K.table("unit-table", ["unit", "type", "size (m)"].concat(preds.map(function (p) { return "P(" + p + ")"; })),
    units.map(function (u) {
      var g = geom[u.id];
      return [u.id, u.type, K.fmt(g.w, 2) + " x " + K.fmt(g.h, 2)].concat(preds.map(function (p) {
        return K.probCell((u.type_probs || {})[p]);
      }));
    })));
  if (world.queries) {
    kb.appendChild(K.el("h2", {}, "Queries"));
    kb.appendChild(K.table("queries-table", ["query", "probability"], K.flattenQueries(world.queries).map(function (r) {
      return [r[0], K.probCell(r[1])];
    })));
  }
};
