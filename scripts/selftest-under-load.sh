#!/usr/bin/env bash
# The pages' ?selftest on every chapter, repeated with the CPU saturated: the check that the
# in-page time guard never stops a correct shader on a busy machine, and still stops the slow
# probe (issue 24, item 0).
#
#   scripts/selftest-under-load.sh [RUNS] [BUSY]      (defaults: 10 runs, 2 busy processes)
#
# Needs a built book (`cargo run --release`) and Chromium (`apt-get install -y chromium`).
# `BOOK=book/build/fr` checks another language's build. Each run opens every chapter page of
# the build with ?selftest in headless Chromium (SwiftShader), while BUSY processes spin on
# the CPU, and reads the JSON the page writes into <pre id="lightlab-selftest">. A run passes
# when every live figure and every exercise passes and no page reports a JavaScript error;
# the page that ran the slow probe must have stopped it. Prints one line per page and run, a
# summary, and exits 1 when any run failed.
set -uo pipefail
cd "$(dirname "$0")/.."
runs=${1:-10}
busy=${2:-2}
book=${BOOK:-book/build}
browser=${LIGHTLAB_CHROMIUM:-$(command -v chromium || command -v chromium-browser || true)}
[ -n "$browser" ] || { echo "no Chromium: apt-get install -y chromium" >&2; exit 2; }
[ -f "$book/index.html" ] || { echo "no $book/index.html: run cargo run --release first" >&2; exit 2; }

pids=()
stop_load() { for p in "${pids[@]}"; do kill "$p" 2>/dev/null; done; }
trap stop_load EXIT
for _ in $(seq "$busy"); do (while :; do :; done) & pids+=($!); done

pages=$(ls "$book"/*.html | grep -vE '/(print|404|toc)\.html$')
profile_root=$(mktemp -d)
failed_runs=0
for run in $(seq "$runs"); do
  run_ok=1
  for page in $pages; do
    out=$(timeout 900 "$browser" --headless --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader \
      --disable-quic --no-first-run --disable-background-networking --disable-component-update --disable-sync \
      --virtual-time-budget=120000 --user-data-dir="$profile_root/p$run" --dump-dom \
      "file://$(realpath "$page")?selftest" 2>/dev/null)
    verdict=$(printf '%s' "$out" | python3 -c '
import html, json, re, sys
dom = sys.stdin.read()
m = re.search(r"<pre id=\"lightlab-selftest\">(.*?)</pre>", dom, re.S)
if not m:
    print("FAIL no self-test output"); sys.exit()
v = json.loads(html.unescape(m.group(1)))
bad = ["js error: %s" % e for e in v.get("errors", [])]
bad += ["figure %s" % f.get("id") for f in v.get("figures", []) if f.get("pass") is not True]
slow = []
for e in v.get("exercises", []):
    if e.get("pass") is not True:
        bad.append("exercise %s: %s" % (e.get("id"), json.dumps(e)[:400]))
    s = e.get("slow") or {}
    if "timing" in s:
        slow.append("slow probe %s: %s, warm-up draw %.0f ms, checked draws %.0f ms, limit %.0f ms" % (
            e["id"], "stopped" if s.get("pass") else "NOT stopped", s["timing"].get("warm_ms", -1),
            s["timing"].get("reader_ms", -1), s["timing"].get("limit_ms", -1)))
n = "%d figures, %d exercises" % (len(v.get("figures", [])), len(v.get("exercises", [])))
print(("FAIL " + "; ".join(bad) if bad else "ok") + " (" + n + ")" + ("; " + "; ".join(slow) if slow else ""))
')
    load=$(cut -d' ' -f1 /proc/loadavg)
    echo "run $run/$runs $(basename "$page"): $verdict [load $load]"
    case "$verdict" in ok*) ;; *) run_ok=0 ;; esac
  done
  [ "$run_ok" = 1 ] || failed_runs=$((failed_runs + 1))
done
rm -rf "$profile_root"
echo "passed $((runs - failed_runs)) of $runs runs with $busy busy processes"
[ "$failed_runs" = 0 ]
