#!/usr/bin/env bash
# Run benchmarks/bench_first_hour.py in FreeCAD's GUI (under Xvfb) and print its figures: a session
# (the grooving tool controller, the first Job panel OK after reopening), then a FreeCAD just started
# (recomputing two Groove ops), then one more for the same with two of CAM's own Profile ops instead.
#
#   benchmarks/bench_first_hour.sh          FreeCAD 1.1
#   benchmarks/bench_first_hour.sh 1.0      another label of `scripts/freecad-roots list`
#
# FreeCAD's own output goes to a log shown only when the benchmark fails.

set -euo pipefail

cd "$(dirname "$(readlink -f "$0")")/.."
. benchmarks/freecad_run.sh

run_benchmark bench_first_hour "${1:-1.1}" '
gui() { xvfb-run -a -s "-screen 0 1600x1000x24" freecad "$@" "$FREECAD_GROOVE_CHECKOUT/benchmarks/bench_first_hour.py"; }
export FREECAD_GROOVE_BENCH_PHASE=session && gui -M "$FREECAD_GROOVE_CHECKOUT" &&
export FREECAD_GROOVE_BENCH_PHASE=fresh && gui -M "$FREECAD_GROOVE_CHECKOUT" &&
export FREECAD_GROOVE_BENCH_PHASE=cam && gui -M "$FREECAD_GROOVE_CHECKOUT"'
