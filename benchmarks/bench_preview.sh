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
. benchmarks/freecad_run.sh

run_benchmark bench_preview "${1:-1.1}" \
    'exec xvfb-run -a -s "-screen 0 1600x1000x24" freecad -M "$FREECAD_GROOVE_CHECKOUT" "$FREECAD_GROOVE_CHECKOUT/benchmarks/bench_preview.py"'
