#!/usr/bin/env bash
# Run benchmarks/bench_freecad.py, then bench_freecad_fresh.py twice, inside FreeCAD (headless) and print
# their figures.
#
#   benchmarks/bench_freecad.sh          FreeCAD 1.1
#   benchmarks/bench_freecad.sh 1.0      another label of `scripts/freecad-roots list`
#
# FreeCAD comes from scripts/freecad-roots (`scripts/freecad-roots ensure`
# builds it the first time; running it needs root or password-less sudo unless
# the host has that FreeCAD). FreeCAD's own output goes to a log that is shown
# only when the benchmark fails. FREECAD_GROOVE_BENCH_GROOVES=N posts N
# grooves instead of 500.

set -euo pipefail

cd "$(dirname "$(readlink -f "$0")")/.."
. benchmarks/freecad_run.sh

# Short: FreeCAD 1.1 crashes on a -c text of 256 characters or more.
CODE="$(bench_code bench_freecad.py)"
FRESH="$(bench_code bench_freecad_fresh.py)"
# (a), (b), then (c): a fresh FreeCAD for each post's first post after opening the document (b) saved
run_benchmark bench_freecad "${1:-1.1}" 'freecadcmd -M "$FREECAD_GROOVE_CHECKOUT" -c "$1" &&
    FREECAD_GROOVE_BENCH_FRESH=ours freecadcmd -M "$FREECAD_GROOVE_CHECKOUT" -c "$2" &&
    FREECAD_GROOVE_BENCH_FRESH=freecad freecadcmd -M "$FREECAD_GROOVE_CHECKOUT" -c "$2"' "$CODE" "$FRESH"
