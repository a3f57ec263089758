#!/usr/bin/env python3
"""Loads a run's report.html in headless Chromium and checks what it drew.

  check_report.py OUT_DIR SCREENSHOT.png [--chromium PATH]

Expected elements come from the folder's own files (world.json, scene_graph.json,
segments.json, trace.csv): one drawn element per unit / door / box / segment, the summary
and kernel tables, the trace plots when trace.csv exists. The page's window.onerror writes
any script error into #report-status; Chromium's console log (stderr) must show no error.
Saves a screenshot. Exit 77 (CTest: skipped) when Chromium is not installed.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--disable-dev-shm-usage", "--virtual-time-budget=10000"]


def chromium(binary, extra, url, timeout=180):
    with tempfile.TemporaryDirectory(prefix="ksmc-chromium-") as profile:
        cmd = [binary] + FLAGS + ["--user-data-dir=" + profile, "--enable-logging=stderr", "--v=0"] + extra + [url]
        r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=timeout)
        return r.returncode, r.stdout.decode("utf-8", "replace"), r.stderr.decode("utf-8", "replace")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out_dir")
    ap.add_argument("screenshot")
    ap.add_argument("--chromium", default="")
    a = ap.parse_args()
    binary = a.chromium or shutil.which("chromium") or shutil.which("chromium-browser")
    if not binary:
        print("SKIP: chromium is not installed (Debian package `chromium`; scripts/install-deps.sh installs it)")
        return 77
    report = os.path.abspath(os.path.join(a.out_dir, "report.html"))
    failures = []

    def check(ok, what):
        print(("PASS: " if ok else "FAIL: ") + what)
        if not ok:
            failures.append(what)

    check(os.path.isfile(report), report + " exists")
    if failures:
        return 1
    html = open(report, encoding="utf-8").read()
    check(not re.search(r"""(src|href)\s*=\s*["']?(https?:)?//""", html), "no network reference (http:// or //host) in the page")

    rc, dom, log = chromium(binary, ["--dump-dom"], "file://" + report + "#hover-selftest")
    check(rc == 0, "chromium --dump-dom exit code 0 (got %d)" % rc)
    status = re.search(r'<div id="report-status"[^>]*data-status="([a-z]+)"[^>]*>([^<]*)<', dom)
    check(status is not None and status.group(1) == "ok",
          "#report-status is 'ok' (no script error): " + (status.group(2) if status else "missing"))
    console_errors = [l for l in log.splitlines() if "CONSOLE" in l and re.search(r"Uncaught|Error|error", l)]
    check(not console_errors, "no console errors in chromium's log" + ("" if not console_errors else ": " + console_errors[0]))

    hover = re.search(r'<div id="report-status"[^>]*data-hover="([^"]*)"', dom)
    hover = hover.group(1) if hover else ""

    def hover_shows(words):
        check(all(w in hover for w in words), "hover on the first element shows " + ", ".join(words) + ": '" + hover + "'")

    def count(pattern):
        return len(re.findall(pattern, dom))

    def has(id_):
        check(('id="%s"' % id_) in dom, "element #%s drawn" % id_)

    for id_ in ["summary-table", "kernel-table", "marginals"]:
        has(id_)
    d = a.out_dir
    s = json.load(open(os.path.join(d, "summary.json")))
    length = "until the plateau" if s.get("until_plateau") else "fixed: %d per chain" % s["iterations_per_chain"]
    check(length in dom, "summary table gives the run's length: '%s'" % length)
    if os.path.exists(os.path.join(d, "trace.csv")):
        has("trace-logpost")
        has("trace-acceptance")
    if os.path.exists(os.path.join(d, "world.json")):
        w = json.load(open(os.path.join(d, "world.json")))
        has("indoor-map")
        hover_shows(["unit ", "P(", "size (m)", "area (m2)"])
        n = count(r'<polygon id="unit-\d+" class="unit"')
        check(n == len(w["units"]), "indoor: %d unit outlines for %d units in world.json" % (n, len(w["units"])))
        n = count(r'<line id="door-\d+" class="door"')
        check(n == len(w["doors"]), "indoor: %d doors drawn for %d in world.json" % (n, len(w["doors"])))
        n = count(r'class="topology"')
        check(n == len(w["adjacent"]), "indoor: %d topology lines for %d adjacent pairs" % (n, len(w["adjacent"])))
        rows = len(re.findall(r"<tr>", dom.split('id="unit-table"')[1].split("</table>")[0])) - 1 if 'id="unit-table"' in dom else -1
        check(rows == len(w["units"]), "indoor: unit table has %d rows (type probabilities, size in m)" % rows)
    if os.path.exists(os.path.join(d, "scene_graph.json")):
        g = json.load(open(os.path.join(d, "scene_graph.json")))
        for id_ in ["tabletop-view", "scene-graph", "objects-table"]:
            has(id_)
        hover_shows(["object ", "P(false)", "P(hidden)"])
        n = count(r'<g id="box-[^"]+" class="box"')
        check(n == len(g["objects"]), "tabletop: %d boxes drawn for %d objects" % (n, len(g["objects"])))
        n = count(r'<g id="graph-node-[^"]+" class="graph-node"')
        check(n == len(g["objects"]), "tabletop: %d scene graph nodes" % n)
        n = count(r'class="support"')
        check(n == len(g["support"]), "tabletop: %d support arrows for %d support edges" % (n, len(g["support"])))
        n = count(r'class="intersect"')
        check(n == len(g.get("intersect", [])), "tabletop: %d 'cuts' lines for %d intersecting pairs" % (n, len(g.get("intersect", []))))
    if os.path.exists(os.path.join(d, "segments.json")):
        s = json.load(open(os.path.join(d, "segments.json")))
        for id_ in ["segments-view", "segments-table", "relations-table"]:
            has(id_)
        hover_shows(["segment ", "length (m)", "support (points)"])
        n = count(r'<line id="segment-\d+" class="segment"')
        check(n == len(s["segments"]), "segments: %d segments drawn for %d in segments.json" % (n, len(s["segments"])))

    shot = os.path.abspath(a.screenshot)
    if os.path.exists(shot):
        os.remove(shot)
    rc, _, _ = chromium(binary, ["--screenshot=" + shot, "--window-size=1400,2200", "--hide-scrollbars"], "file://" + report)
    check(rc == 0 and os.path.isfile(shot) and os.path.getsize(shot) > 10000,
          "screenshot " + shot + (" (%d bytes)" % os.path.getsize(shot) if os.path.isfile(shot) else " missing"))
    print("%s: %d checks failed" % (report, len(failures)) if failures else "%s: all checks passed" % report)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
