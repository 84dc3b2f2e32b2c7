# Sourced by the FreeCAD benchmark scripts: run one benchmark inside a FreeCAD
# of scripts/freecad-roots and print its figures.
#
#   run_benchmark NAME LABEL SCRIPT [ARG ...]
#
# runs `sh -c SCRIPT sh ARG...` in the root LABEL (1.1, 1.0) with a temporary
# shared folder; the benchmark writes its figures to $SHARE/NAME.txt, which is
# printed. FreeCAD's own output goes to a log shown only when it fails.
#
#   bench_code FILE
#
# prints the freecadcmd -c text that runs benchmarks/FILE with benchmarks/ on
# sys.path (for figures.py). Short: FreeCAD 1.1 crashes on a -c text of 256
# characters or more.

bench_code() {
    printf '%s' "import os, sys; B = os.environ['FREECAD_GROOVE_CHECKOUT'] + '/benchmarks'; sys.path.insert(0, B); exec(open(B + '/$1').read())"
}

run_benchmark() {
    local name="$1" label="$2" script="$3"
    shift 3
    local share rc
    share="$(mktemp -d "${TMPDIR:-/tmp}/freecad-groove-bench.XXXXXX")"
    # shellcheck disable=SC2064  # expand now: the folder of this call
    trap "rm -rf '$share'" EXIT
    chmod 755 "$share"
    set +e
    scripts/freecad-roots run "$label" --share "$share" -- sh -c "$script" sh "$@" >"$share/freecad.log" 2>&1
    rc=$?
    set -e
    if [ -f "$share/$name.txt" ]; then
        cat "$share/$name.txt"
    fi
    if [ "$rc" -ne 0 ] || [ ! -f "$share/$name.txt" ]; then
        echo "$name: FreeCAD $label exited with status $rc; the end of its output:" >&2
        tr '\r' '\n' <"$share/freecad.log" | grep -v '^[[:space:]]*$' | tail -n 30 >&2
        exit 1
    fi
}
