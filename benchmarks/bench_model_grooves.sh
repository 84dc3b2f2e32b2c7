#!/usr/bin/env bash
# Run benchmarks/bench_model_grooves.py inside FreeCAD (headless) and print its figures.
#
#   benchmarks/bench_model_grooves.sh          FreeCAD 1.1
#   benchmarks/bench_model_grooves.sh 1.0      another label of `scripts/freecad-roots list`
#
# FreeCAD comes from scripts/freecad-roots (`scripts/freecad-roots ensure`
# builds it the first time; running it needs root or password-less sudo unless
# the host has that FreeCAD). FreeCAD's own output goes to a log that is shown
# only when the benchmark fails.

set -euo pipefail

cd "$(dirname "$(readlink -f "$0")")/.."
. benchmarks/freecad_run.sh

# Short: FreeCAD 1.1 crashes on a -c text of 256 characters or more.
CODE="$(bench_code bench_model_grooves.py)"
run_benchmark bench_model_grooves "${1:-1.1}" 'exec freecadcmd -M "$FREECAD_GROOVE_CHECKOUT" -c "$1"' "$CODE"
