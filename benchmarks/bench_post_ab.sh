#!/usr/bin/env bash
# Run benchmarks/bench_post_ab.py inside FreeCAD (headless) and print its line.
#
#   benchmarks/bench_post_ab.sh          FreeCAD 1.1
#   benchmarks/bench_post_ab.sh 1.0      another label of `scripts/freecad-roots list`

set -euo pipefail

cd "$(dirname "$(readlink -f "$0")")/.."
. benchmarks/freecad_run.sh

run_benchmark bench_post_ab "${1:-1.1}" 'freecadcmd -M "$FREECAD_GROOVE_CHECKOUT" -c "$1"' "$(bench_code bench_post_ab.py)"
