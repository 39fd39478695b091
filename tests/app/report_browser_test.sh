#!/usr/bin/env bash
# report.html in a real browser (headless Chromium): the report of a shipped
# HCW solve and of a 2-cycle `simulate` are loaded, screenshotted and printed
# to PDF; a copy of each page with a probe script appended (the report itself
# has no script) records load errors, resources fetched and the rendered size
# of every plot, read back through --dump-dom.
#   report_browser_test.sh THRUSTSCHED_BINARY SOURCE_DIR WORK_DIR
# Exit 77 (ctest: skipped) when Chromium is not installed.
set -euo pipefail
case "${1:-}" in -h|--help) sed -n "2,8p" "$0" | sed "s/^# \{0,1\}//"; exit 0 ;; esac
cli=$1
src=$2
work=$3

browser=""
for b in chromium chromium-browser google-chrome; do
  if command -v "$b" >/dev/null 2>&1; then browser=$b; break; fi
done
if [ -z "$browser" ]; then
  echo "SKIPPED: no Chromium in PATH (Debian package 'chromium'; scripts/install-deps.sh installs it" \
       "for make test): report.html was not checked in a browser"
  exit 77
fi

rm -rf "$work"
mkdir -p "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }

"$cli" solve "$src/data/scenarios/hcw_table41_1d.json" --out "$work/solve" --threads 1 --quiet \
  > "$work/solve.txt" || fail "solve exited $? ($(cat "$work/solve.txt"))"
"$cli" simulate "$src/data/scenarios/year/year_test_4cycles.json" --cycles 2 --out "$work/year" \
  --quiet > "$work/year.txt" || fail "simulate exited $? ($(cat "$work/year.txt"))"

run_browser() {
  # A private profile; --no-sandbox for root in containers.
  timeout 120 "$browser" --headless=new --no-sandbox --disable-gpu --disable-dev-shm-usage \
    --no-first-run --user-data-dir="$work/profile" --hide-scrollbars "$@" 2>>"$work/browser.log"
}

for run in solve year; do
  report="$work/$run/report.html"
  [ -s "$report" ] || fail "$report missing or empty"
  grep -q "report.html" "$work/$run/.thrustsched-run.json" || fail "$run: report.html not in the manifest"
  # Self-contained: no script, no external resource.
  if grep -qi "<script" "$report"; then fail "$run: report.html has a script"; fi
  if grep -Eqi "(src|href)=[\"']?(https?:|//)|@import|url\((['\"])?https?:" "$report"; then
    fail "$run: report.html refers to an external resource"
  fi
  svgs=$(grep -o "<svg " "$report" | wc -l)
  [ "$svgs" -ge 3 ] || fail "$run: only $svgs plots in report.html"

  # Screenshot and PDF of the report itself.
  run_browser --window-size=1280,2000 --screenshot="$work/$run.png" "file://$report" >/dev/null
  [ -s "$work/$run.png" ] || fail "$run: no screenshot"
  png_bytes=$(stat -c %s "$work/$run.png")
  # A blank 1280x2000 page compresses to a few kB; text and plots do not.
  [ "$png_bytes" -gt 30000 ] || fail "$run: screenshot of $png_bytes bytes looks blank"
  run_browser --no-pdf-header-footer --print-to-pdf="$work/$run.pdf" "file://$report" >/dev/null
  [ -s "$work/$run.pdf" ] || fail "$run: no PDF (print)"
  pages=$(grep -a -c "/Type /Page\b" "$work/$run.pdf" || true)
  [ "$pages" -ge 1 ] || fail "$run: the PDF has no page"

  # The probe: the same page plus a script that reports what the browser did.
  python3 - "$report" "$work/$run.probe.html" <<'PY'
import sys
text = open(sys.argv[1], encoding="utf-8").read()
head = """<script>window.__errors = [];
window.addEventListener('error', function (e) {
  window.__errors.push(String(e.message || (e.target && (e.target.src || e.target.href)) || 'error'));
}, true);</script>"""
probe = """<script>window.addEventListener('load', function () {
  var svgs = Array.prototype.map.call(document.querySelectorAll('svg'), function (s) {
    var r = s.getBoundingClientRect();
    return [Math.round(r.width), Math.round(r.height), s.hasAttribute('viewBox') ? 1 : 0];
  });
  var res = performance.getEntriesByType('resource').map(function (e) { return e.name; });
  var p = document.createElement('pre');
  p.id = 'probe';
  p.textContent = 'PROBE ' + JSON.stringify({errors: window.__errors, svgs: svgs, resources: res,
                                             tables: document.querySelectorAll('table').length});
  document.body.appendChild(p);
});</script>"""
text = text.replace("<head>", "<head>\n" + head, 1).replace("</body>", probe + "\n</body>", 1)
open(sys.argv[2], "w", encoding="utf-8").write(text)
PY
  run_browser --virtual-time-budget=5000 --window-size=1280,2000 --dump-dom \
    "file://$work/$run.probe.html" > "$work/$run.dom.html"
  python3 - "$work/$run.dom.html" "$svgs" "$run" <<'PY'
import html, json, re, sys
dom, expected, run = open(sys.argv[1], encoding="utf-8").read(), int(sys.argv[2]), sys.argv[3]
m = re.search(r"PROBE (\{.*?\})</pre>", dom, re.S)
if not m:
    sys.exit(f"FAIL: {run}: the page did not finish loading (no probe result in the DOM)")
r = json.loads(html.unescape(m.group(1)))
problems = []
if r["errors"]:
    problems.append(f"load errors {r['errors']}")
if r["resources"]:
    problems.append(f"fetched resources {r['resources']}")
if len(r["svgs"]) != expected:
    problems.append(f"{len(r['svgs'])} plots rendered, {expected} in the file")
for i, (w, h, vb) in enumerate(r["svgs"]):
    if w <= 0 or h <= 0 or not vb:
        problems.append(f"plot {i + 1}: rendered {w} x {h} px, viewBox {bool(vb)}")
if r["tables"] < 2:
    problems.append(f"{r['tables']} tables")
if problems:
    sys.exit(f"FAIL: {run}: " + "; ".join(problems))
sizes = ", ".join(f"{w}x{h}" for w, h, _ in r["svgs"])
print(f"{run}: report loaded without errors, {len(r['svgs'])} plots ({sizes} px), {r['tables']} tables")
PY
done
echo "screenshots: $work/solve.png $work/year.png"
