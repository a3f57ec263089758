// Reads the inline data block and draws the report for the kind of run it holds; marks
// #report-status "ok" when every part was drawn (the headless test checks it).
"use strict";
(function () {
  var status = document.getElementById("report-status");
  try {
    var data = JSON.parse(document.getElementById("ksmc-data").textContent);
    var kinds = { indoor: K.drawIndoor, tabletop: K.drawTabletop, segments: K.drawSegments };
    if (kinds[data.kind]) kinds[data.kind](data);
    K.drawSummary(data);
    K.drawTrace(data);
    // report.html#hover-selftest: hover the first unit / box / segment and keep the tooltip's
    // text in #report-status data-hover (the headless test cannot move a mouse).
    if (location.hash === "#hover-selftest") {
      var target = document.querySelector(".unit, .box, .segment");
      if (target) {
        target.dispatchEvent(new MouseEvent("mouseenter"));
        status.setAttribute("data-hover", document.getElementById("tooltip").textContent);
      }
    }
    if (window.ksmcErrors.length === 0) {
      status.setAttribute("data-status", "ok");
      status.setAttribute("data-kind", data.kind);
      status.textContent = data.kind + " run: all parts drawn";
    }
  } catch (e) {
    window.ksmcErrors.push(String(e && e.stack ? e.stack : e));
    status.setAttribute("data-status", "error");
    status.textContent = "report error: " + window.ksmcErrors.join("; ");
  }
})();
