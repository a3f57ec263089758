// Table-top (scene_graph.json): the object boxes projected into the camera image (sizes and
// intrinsics from the input scene), the scene graph (support arrows upper -> lower, unstable
// contacts dashed, boxes that cut each other red dotted) and P(false) / P(hidden) per object,
// on hover and in a table.
"use strict";
K.rotate = function (q, v) {  // q = [w, x, y, z]
  var w = q[0], x = q[1], y = q[2], z = q[3];
  var tx = 2 * (y * v[2] - z * v[1]), ty = 2 * (z * v[0] - x * v[2]), tz = 2 * (x * v[1] - y * v[0]);
  return [v[0] + w * tx + (y * tz - z * ty), v[1] + w * ty + (z * tx - x * tz), v[2] + w * tz + (x * ty - y * tx)];
};
K.hull = function (pts) {  // monotone chain; pts [[x, y]]
  var p = pts.slice().sort(function (a, b) { return a[0] - b[0] || a[1] - b[1]; });
  var cross = function (o, a, b) { return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]); };
  var lower = [], upper = [];
  p.forEach(function (q) { while (lower.length >= 2 && cross(lower[lower.length - 2], lower[lower.length - 1], q) <= 0) lower.pop(); lower.push(q); });
  p.slice().reverse().forEach(function (q) { while (upper.length >= 2 && cross(upper[upper.length - 2], upper[upper.length - 1], q) <= 0) upper.pop(); upper.push(q); });
  return lower.slice(0, -1).concat(upper.slice(0, -1));
};
K.objectColor = function (o) {
  if (o["false"] === true) return "#d62728";
  if (o.hidden === true) return "#ff7f0e";
  if (o["false"] === null || o.hidden === null) return "#bcbd22";
  return "#2ca02c";
};
K.objectTip = function (o) {
  return function () {
    return K.lines("object " + o.id, [["P(false)", o.false_prob], ["P(hidden)", o.hidden_prob],
      ["false", o["false"] === null ? "undecided" : o["false"]], ["hidden", o.hidden === null ? "undecided" : o.hidden],
      ["stable", o.stable]]);
  };
};

K.drawBoxes = function (sec, data, objects) {
  var scene = data.scene_input, cam = scene && scene.camera;
  var sizes = {};
  ((scene && scene.objects) || []).forEach(function (o) { if (o.size) sizes[o.id] = o.size; });
  if (!cam || !cam.fx) {
    K.note(sec, "The input scene (camera intrinsics, box sizes) could not be read from the path in summary.json; boxes are not drawn.");
    if (data.images && data.images.overlay) sec.appendChild(K.el("img", { id: "tabletop-overlay", src: data.images.overlay, width: 640 }));
    return;
  }
  var W = cam.width || 640, H = cam.height || 480;
  var svg = K.svg("svg", { id: "tabletop-view", viewBox: "0 0 " + W + " " + H, width: W, height: H });
  if (data.images && data.images.overlay)
    svg.appendChild(K.svg("image", { href: data.images.overlay, x: 0, y: 0, width: W, height: H, opacity: 0.35, preserveAspectRatio: "none" }));
  else svg.appendChild(K.svg("rect", { x: 0, y: 0, width: W, height: H, fill: "#f4f4f4" }));
  objects.forEach(function (o) {
    var s = sizes[o.id];
    if (!s) return;
    var pts = [];
    for (var i = 0; i < 8; ++i) {
      var c = [(i & 1 ? 0.5 : -0.5) * s[0], (i & 2 ? 0.5 : -0.5) * s[1], (i & 4 ? 0.5 : -0.5) * s[2]];
      var r = K.rotate(o.pose.q, c);
      var p = [r[0] + o.pose.t[0], r[1] + o.pose.t[1], r[2] + o.pose.t[2]];
      pts.push(p[2] > 1e-6 ? [cam.fx * p[0] / p[2] + cam.cx, cam.fy * p[1] / p[2] + cam.cy] : null);
    }
    if (pts.some(function (p) { return p === null; })) return;  // behind the camera
    var color = K.objectColor(o);
    var g = K.svg("g", { id: "box-" + o.id, "class": "box", stroke: color, "stroke-width": 2 });
    var hull = K.svg("polygon", { points: K.hull(pts).map(function (p) { return p.join(","); }).join(" "),
                                  fill: color, "fill-opacity": 0.15 });
    hull.appendChild(K.svg("title", {}, "object " + o.id));
    g.appendChild(hull);
    var d = "";
    [[0, 1], [2, 3], [4, 5], [6, 7], [0, 2], [1, 3], [4, 6], [5, 7], [0, 4], [1, 5], [2, 6], [3, 7]].forEach(function (e) {
      d += "M" + pts[e[0]][0].toFixed(1) + " " + pts[e[0]][1].toFixed(1) + "L" + pts[e[1]][0].toFixed(1) + " " + pts[e[1]][1].toFixed(1);
    });
    g.appendChild(K.svg("path", { d: d, fill: "none" }));
    var top = pts.reduce(function (a, b) { return a[1] < b[1] ? a : b; });
    g.appendChild(K.svg("text", { x: top[0], y: top[1] - 4, fill: "#000", stroke: "none", "text-anchor": "middle" }, o.id));
    K.hover(g, K.objectTip(o));
    svg.appendChild(g);
  });
  sec.appendChild(svg);
};

K.drawSceneGraph = function (sec, graph) {
  var objects = graph.objects || [], n = objects.length;
  var W = 460, H = 420, R = Math.min(W, H) / 2 - 50, pos = {};
  var svg = K.svg("svg", { id: "scene-graph", viewBox: "0 0 " + W + " " + H, width: W, height: H });
  var defs = K.svg("defs");
  var marker = K.svg("marker", { id: "arrow", viewBox: "0 0 10 10", refX: 22, refY: 5, markerWidth: 8, markerHeight: 8, orient: "auto" });
  marker.appendChild(K.svg("path", { d: "M0 0L10 5L0 10z", fill: "#333" }));
  defs.appendChild(marker);
  svg.appendChild(defs);
  objects.forEach(function (o, i) {
    var a = -Math.PI / 2 + 2 * Math.PI * i / Math.max(1, n);
    pos[o.id] = [W / 2 + R * Math.cos(a), H / 2 + R * Math.sin(a)];
  });
  // Bodies that are no scene object (the table) sit in the middle.
  var extra = [];
  (graph.support || []).concat(graph.contact || []).forEach(function (e) {
    e.forEach(function (id) { if (!pos[id] && extra.indexOf(id) < 0) extra.push(id); });
  });
  extra.forEach(function (id, i) { pos[id] = [W / 2 + 60 * (i - (extra.length - 1) / 2), H / 2]; });
  var edge = function (a, b, cls, attrs) {
    if (!pos[a] || !pos[b]) return;
    var l = K.svg("line", Object.assign({ "class": cls, x1: pos[a][0], y1: pos[a][1], x2: pos[b][0], y2: pos[b][1], stroke: "#333" }, attrs));
    l.appendChild(K.svg("title", {}, cls + " " + a + " - " + b));
    svg.appendChild(l);
  };
  (graph.support || []).forEach(function (e) { edge(e[0], e[1], "support", { "stroke-width": 2, "marker-end": "url(#arrow)" }); });
  (graph.contact || []).forEach(function (e) { edge(e[0], e[1], "contact", { "stroke-dasharray": "5 4" }); });
  (graph.intersect || []).forEach(function (e) {  // boxes that cut each other: one of them is wrong
    edge(e[0], e[1], "intersect", { stroke: "#d62728", "stroke-width": 2, "stroke-dasharray": "2 3" });
  });
  extra.forEach(function (id) {
    svg.appendChild(K.svg("rect", { x: pos[id][0] - 30, y: pos[id][1] - 12, width: 60, height: 24, fill: "#ddd", stroke: "#333" }));
    svg.appendChild(K.svg("text", { x: pos[id][0], y: pos[id][1] + 4, "text-anchor": "middle" }, id));
  });
  objects.forEach(function (o) {
    var g = K.svg("g", { id: "graph-node-" + o.id, "class": "graph-node" });
    g.appendChild(K.svg("circle", { cx: pos[o.id][0], cy: pos[o.id][1], r: 16, fill: K.objectColor(o), stroke: "#333" }));
    g.appendChild(K.svg("text", { x: pos[o.id][0], y: pos[o.id][1] + 4, "text-anchor": "middle", fill: "#fff" }, o.id));
    K.hover(g, K.objectTip(o));
    svg.appendChild(g);
  });
  sec.appendChild(svg);
};

K.drawTabletop = function (data) {
  var graph = data.scene_graph, objects = graph.objects || [];
  var count = function (n, one, many) { return n + " " + (n === 1 ? one : many); };
  var sec = K.section("tabletop", "Scene: " + count(objects.length, "object", "objects") + ", " +
                      count((graph.support || []).length, "support edge", "support edges") + ", " +
                      count((graph.contact || []).length, "unstable contact", "unstable contacts") + ", " +
                      count((graph.intersect || []).length, "pair of boxes that cut each other",
                            "pairs of boxes that cut each other"));
  var row = K.el("div", { "class": "row" });
  sec.appendChild(row);
  var left = K.el("div"), right = K.el("div");
  left.appendChild(K.el("h2", {}, "Boxes (camera view)"));
  right.appendChild(K.el("h2", {}, "Scene graph (arrow: upper supported by lower)"));
  row.appendChild(left);
  row.appendChild(right);
  K.drawBoxes(left, data, objects);
  K.drawSceneGraph(right, graph);
  sec.appendChild(K.legend([{ name: "false estimate", color: "#d62728" }, { name: "hidden supporter", color: "#ff7f0e" },
                            { name: "undecided (0.4..0.6)", color: "#bcbd22" }, { name: "fine", color: "#2ca02c" }]));
  var kb = K.section("marginals", "Knowledge base marginals");
  kb.appendChild(K.table("objects-table", ["object", "model", "stable", "P(false)", "false", "P(hidden)", "hidden"],
    objects.map(function (o) {
      var model = "";
      ((data.scene_input && data.scene_input.objects) || []).forEach(function (s) { if (s.id === o.id && s.model) model = s.model; });
      return [o.id, model, String(o.stable), K.probCell(o.false_prob), String(o["false"]), K.probCell(o.hidden_prob), String(o.hidden)];
    })));
  if (data.images && data.images.graph) {
    kb.appendChild(K.el("h2", {}, "graph.png (graphviz)"));
    kb.appendChild(K.el("img", { id: "tabletop-graph-png", src: data.images.graph, style: "max-width:100%" }));
  }
};
