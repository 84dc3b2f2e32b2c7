#!/usr/bin/env bash
# Run benchmarks/bench_verify_job.py inside FreeCAD (headless) and print its figures.
#
#   benchmarks/bench_verify_job.sh          FreeCAD 1.1
#   benchmarks/bench_verify_job.sh 1.0      another label of `scripts/freecad-roots list`
#
# shapely for FreeCAD's Python comes from the host (tests/freecad_shapely.py,
# PyPI's wheel of the version requirements-test.txt pins; needs .venv, or PYTHON=
# an interpreter with the test requirements).

set -euo pipefail

cd "$(dirname "$(readlink -f "$0")")/.."
. benchmarks/freecad_run.sh
share="$(mktemp -d "${TMPDIR:-/tmp}/freecad-groove-bench.XXXXXX")"
trap "rm -rf '$share'" EXIT
chmod 755 "$share"
"${PYTHON:-.venv/bin/python}" -c "import sys; sys.path[:0] = ['tests']; import freecad_shapely; freecad_shapely.provide(sys.argv[1])" "$share"
CODE="$(bench_code bench_verify_job.py)"
FREECAD_GROOVE_PYLIB=pylib scripts/freecad-roots run "${1:-1.1}" --share "$share" -- \
    sh -c 'exec freecadcmd -M "$FREECAD_GROOVE_CHECKOUT" -c "$1"' sh "$CODE" >"$share/freecad.log" 2>&1 || true
if [ -f "$share/bench_verify_job.txt" ]; then
    cat "$share/bench_verify_job.txt"
else
    tail -n 30 "$share/freecad.log" >&2
    exit 1
fi
