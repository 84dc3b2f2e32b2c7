#!/usr/bin/env bash
# Run benchmarks/bench_preview.py in FreeCAD's GUI (under Xvfb) and print its figures.
#
#   benchmarks/bench_preview.sh          FreeCAD 1.1
#   benchmarks/bench_preview.sh 1.0      another label of `scripts/freecad-roots list`
#
# FreeCAD comes from scripts/freecad-roots (as for benchmarks/bench_freecad.sh).
# FreeCAD's own output goes to a log shown only when the benchmark fails.

set -euo pipefail

cd "$(dirname "$(readlink -f "$0")")/.."

LABEL="${1:-1.1}"
SHARE="$(mktemp -d "${TMPDIR:-/tmp}/freecad-groove-bench.XXXXXX")"
trap 'rm -rf "$SHARE"' EXIT
chmod 755 "$SHARE"
set +e
scripts/freecad-roots run "$LABEL" --share "$SHARE" -- \
    sh -c 'exec xvfb-run -a -s "-screen 0 1600x1000x24" freecad -M "$FREECAD_GROOVE_CHECKOUT" "$FREECAD_GROOVE_CHECKOUT/benchmarks/bench_preview.py"' \
    >"$SHARE/freecad.log" 2>&1
rc=$?
set -e
if [ -f "$SHARE/bench_preview.txt" ]; then
    cat "$SHARE/bench_preview.txt"
fi
if [ "$rc" -ne 0 ] || [ ! -f "$SHARE/bench_preview.txt" ]; then
    echo "bench_preview: FreeCAD $LABEL exited with status $rc; the end of its output:" >&2
    tr '\r' '\n' <"$SHARE/freecad.log" | grep -v '^[[:space:]]*$' | tail -n 30 >&2
    exit 1
fi
