#!/usr/bin/env bash
# Run benchmarks/bench_plunge_grind_op.py inside FreeCAD (headless) and print its figures.
#
#   benchmarks/bench_plunge_grind_op.sh          FreeCAD 1.1
#   benchmarks/bench_plunge_grind_op.sh 1.0      another label of `scripts/freecad-roots list`

set -euo pipefail

cd "$(dirname "$(readlink -f "$0")")/.."
. benchmarks/freecad_run.sh

# Short: FreeCAD 1.1 crashes on a -c text of 256 characters or more.
CODE="$(bench_code bench_plunge_grind_op.py)"
run_benchmark bench_plunge_grind_op "${1:-1.1}" 'exec freecadcmd -M "$FREECAD_GROOVE_CHECKOUT" -c "$1"' "$CODE"
