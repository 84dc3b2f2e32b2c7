"""Command-line fuzzing grown by the inputs of issue 20 (items 1, 2, 3 and 9), derandomized so CI runs the
same cases every time: the Milltronics seed's facing program as printed (no Z before G33), the grinder's
G83 call of the issue, GSK G7.1 regions in mm and inch for the three C-axis targets, CYCLE93's dwell.
Each run ends in a program (exit 0) or in one line naming the input (exit 2), never in "internal error";
and each holds the property its item is about."""


from hypothesis import given, settings
from hypothesis import strategies as st
from rs274 import rs274_path, run_rs274
from test_cli import ERROR_LINE, run_inline

DERANDOMIZED = settings(derandomize=True, max_examples=40, deadline=None)


def run_program(tmp_path_factory, text, argv):
    path = tmp_path_factory.mktemp("fuzz") / "program.nc"
    path.write_text(text)
    return run_inline([argv[0], str(path)] + argv[1:])


def assert_program_or_one_line(status, out, err):
    """Exit 0 with a program, or 2 with one line naming the input and line; never an internal error."""
    assert "internal error" not in err and "Traceback" not in err, err
    if status == 0:
        assert out, err
    else:
        assert status == 2 and out == "" and ERROR_LINE.match(err), (status, err)


# ---------------------------------------------------------------- item 1: the Milltronics seed as printed

SEED = ["N1 G20 G90", "N2 S1000 M3 D1 G43 H1", "N3 G0 X1 Y2", "N4 F20", "N5 P151=1", "N6 P152=3", "N7 P155=.1",
        "N8 G33 G99 G41 R.1 Z-.5 V-.3 Q.1 F5", "M30"]
CALL_CHANGES = st.sampled_from([("", ""), ("G99", "G98"), ("G99 ", ""), ("G33", "G34"), ("G41", "G42"),
                                ("V-.3 ", ""), ("R.1", "R2"), ("Z-.5", "Z.5"), ("Q.1", "Q0"), ("F5", "")])
BEFORE_CALL = st.sampled_from(["", "G0 Z1", "G0 Z-1", "G91", "G0 X3", "G4 X1", "T1 M6", "/G0 Z2", "G32", "G31"])


@DERANDOMIZED
@given(st.lists(st.integers(0, 7), max_size=2, unique=True), CALL_CHANGES, BEFORE_CALL,
       st.sampled_from(["linuxcnc", "fanuc", "milltronics"]))
def test_the_milltronics_seed_mutated_runs_or_is_refused_in_one_line(tmp_path_factory, dropped, change, before,
                                                                      target):
    lines = [line for index, line in enumerate(SEED) if index not in dropped]
    lines = [line.replace(*change) if "G33" in line else line for line in lines]
    if before:
        lines.insert(len(lines) - 2, before)
    text = "\n".join(lines) + "\n"
    status, out, err = run_program(tmp_path_factory, text, ["expand", "--dialect", "milltronics", "--tool-diameter",
                                                            ".25", "--to", target])
    assert_program_or_one_line(status, out, err)
    call = next((line for line in lines if "G33" in line or "G34" in line), "")
    known_z = before in ("G0 Z1", "G0 Z-1", "G31", "G32")  # the seed's lines set no Z; "/G0 Z2" may not run
    if "G98" in call and not known_z:
        assert status == 2, "a G98 from an unknown Z was expanded:\n" + out
    if status == 2 and "G98: returns to the Z before the call" in err:
        assert "G98" in call and not known_z, err


def test_the_seed_as_printed_runs_on_every_mill_output(tmp_path_factory):
    for target in ("linuxcnc", "fanuc", "milltronics"):
        status, out, err = run_program(tmp_path_factory, "\n".join(SEED) + "\n",
                                       ["expand", "--dialect", "milltronics", "--tool-diameter", ".25", "--to", target])
        assert (status, err) == (0, ""), err


# ---------------------------------------------------------------- item 2: G83's Q picks at I

G83_WORDS = {"X": ["50.", "-10.", "20."], "I": ["0.", "60.", None], "Y": ["-0.1", "-0.04", "0.2"],
             "J": ["0.05", "0.1"], "Z": ["10.", "0.", "-6."], "K": ["5.", "3."], "R": ["4.", None],
             "Q": ["0.03", "0.02", None], "L": [None, "1"], "F": ["10."], "E": ["2000.", None]}


@st.composite
def g83_call(draw):
    words = {letter: draw(st.sampled_from(values)) for letter, values in G83_WORDS.items()}
    return "G83 " + " ".join(letter + value for letter, value in words.items() if value is not None), words


@DERANDOMIZED
@given(g83_call())
def test_every_generated_g83_picks_q_only_at_the_secondary_reversal_point(tmp_path_factory, case):
    call, words = case
    text = "G90 G94 G21\nG0 X20. Y0. Z0.\n%s\nM30\n" % call
    status, out, err = run_program(tmp_path_factory, text, ["expand", "--dialect", "ab9grind", "--to", "linuxcnc"])
    assert_program_or_one_line(status, out, err)
    if status != 0 or rs274_path() is None:
        return
    canon = [move for move in run_rs274(out, xyz=True) if move[0] == "G1"]
    secondary = float(words["I"]) if words["I"] is not None else 20.0  # I omitted: the start point
    ys = [canon[0][2]] + [move[2] for move in canon]
    picks = [move for before, move in zip(ys[1:], canon[1:]) if abs(move[2] - before) > 1e-9]
    assert all(abs(move[1] - secondary) < 1e-6 for move in picks), (call, picks)


# ---------------------------------------------------------------- item 3: G7.1 feeds on every C target

GSK_UNITS = {"G20": ("X2.", ".8", ["J-.2 R.1 K.02 L2", "J-.1 R.1 K.01 L1", ""], ["C90. F4.", "Z-.3 C45. F4.",
                                                                               "Z-.4 F3.", "C0. F2."]),
             "G21": ("X50.", "20.", ["J-4. R2. K.4 L2", ""], ["C90. F100.", "Z-10. C45. F80.", "Z-5. F50."])}


@DERANDOMIZED
@given(st.sampled_from(sorted(GSK_UNITS)), st.data())
def test_a_g7_1_region_is_written_for_every_c_target_alike(tmp_path_factory, units, data):
    x, radius, type_ii, blocks = GSK_UNITS[units]
    words = data.draw(st.sampled_from(type_ii))
    path = data.draw(st.lists(st.sampled_from(blocks), min_size=1, max_size=3))
    start_x = x if words else "X%s" % format(2 * float(radius), ".1f")  # Type I runs on the cylinder
    text = "%s G98\nG0 %s Z.2 C0.\nG7.1 C%s %s\n%s\nG7.1 C0\nM30\n" % (
        units, start_x, radius, words, "\n".join("G1 " + block for block in path))
    results = {}
    for target in ("linuxcnc-c", "fanuc-c", "gsk"):
        status, out, err = run_program(tmp_path_factory, text, ["expand", "--dialect", "gsk", "--to", target])
        assert_program_or_one_line(status, out, err)
        assert "cannot be written" not in err, (target, err)
        results[target] = status
        feeds = [float(word[1:]) for word in out.split() if word.startswith("F")]
        assert all(0 < feed < 100000 for feed in feeds), (target, feeds)
    assert len(set(results.values())) == 1, results  # one target writes it: every one does


# ---------------------------------------------------------------- item 9: one dwell bound for every output

CYCLE93 = ["--axfa", "20", "--axsa", "-10", "--widg", "6", "--depg", "3", "--fal1", ".2", "--fal2", ".2", "--idep",
           "2", "--typ", "5", "--tool-width", "3", "--tool-radius", ".2"]
DWELLS = st.sampled_from(["0", "1.5", "99999", "99999.0001", "100000", "99999999", "1" + "0" * 308, "9" * 309,
                          "-1", "1e5", "nan", "inf", "0x10", "1,5"])


@DERANDOMIZED
@given(DWELLS)
def test_emit_writes_a_dwell_natively_only_where_the_expansion_writes_it(dwt):
    native = run_inline(["emit", "cycle93"] + CYCLE93 + ["--dwt", dwt])
    expanded = run_inline(["emit", "cycle93"] + CYCLE93 + ["--dwt", dwt, "--expand", "--start-x", "50", "--start-z",
                                                          "5", "--feed", ".1", "--spindle", "500"])
    for status, _out, err in (native, expanded):
        assert "internal error" not in err and "Traceback" not in err, err
        assert status in (0, 2), err
    assert native[0] == expanded[0], (dwt, native[2], expanded[2])
    if native[0] == 0:
        assert 0 <= float(dwt) <= 99999
