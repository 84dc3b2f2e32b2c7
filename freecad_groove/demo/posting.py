"""The demo's programs: every Job's ops through their posts, each native program checked for its cycle words.

Each post is the script post in ``postprocessors/`` loaded from its file, as
FreeCAD loads it, and called as FreeCAD calls it:
``export(objects, filename, arguments)``.
"""

import os
import re
import time

from .shaft import DOCUMENT

POST_DIR = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))),
                        "postprocessors")

# The machine's C axis and live tool codes, which no post can know (posts/live_tool.py): a GSK 980TDi's
# M14/M15 (C axis on/off), M13/M25 (live tool CW/stop); LinuxCNC's digital outputs M64/M65.
GSK_SWITCHES = "--c-axis-on M14 --c-axis-off M15 --live-tool-cw M13 --live-tool-stop M25"
LINUXCNC_SWITCHES = ("--c-axis-on 'M64 P0' --c-axis-off 'M65 P0' --live-tool-cw 'M64 P1' "
                     "--live-tool-stop 'M65 P1'")

# The native cycle words of each system's native posts: a native program must hold each as a block's first
# word, an expanded one none of them.
CYCLE_WORDS = {
    "sinumerik": ("CYCLE93",),
    "ab9": ("G77", "G76"),  # G76: the face groove
    "fanuc": ("G75", "G74"),
    "haas": ("G75", "G74"),
    "gsk": ("G7.1",),
    "ab9grind": ("G83",),
    "milltronics": ("G33", "G34"),
}

# (system, post, mode, post arguments, file name): one program each, in the order the summary lists them.
PROGRAMS = [
    ("groove", "sinumerik_lathe", "native", "", DOCUMENT + "_sinumerik_native.mpf"),
    ("groove", "sinumerik_lathe", "expanded", "--expand-cycles", DOCUMENT + "_sinumerik_expanded.mpf"),
    ("groove", "ab9_lathe", "native", "", DOCUMENT + "_ab9_native.nc"),
    ("groove", "ab9_lathe", "expanded", "--expand-cycles", DOCUMENT + "_ab9_expanded.nc"),
    ("groove", "fanuc_lathe", "native", "", DOCUMENT + "_fanuc_native.nc"),
    ("groove", "fanuc_lathe", "expanded", "--expand-cycles", DOCUMENT + "_fanuc_expanded.nc"),
    ("groove", "haas_lathe", "native", "", DOCUMENT + "_haas_native.nc"),
    ("groove", "haas_lathe", "expanded", "--expand-cycles", DOCUMENT + "_haas_expanded.nc"),
    ("groove", "linuxcnc_lathe", "expanded", "", DOCUMENT + "_linuxcnc.ngc"),
    ("slot", "gsk_lathe", "native", "--native-cycles " + GSK_SWITCHES, DOCUMENT + "_slot_gsk_native.nc"),
    ("slot", "linuxcnc_lathe", "expanded", LINUXCNC_SWITCHES, DOCUMENT + "_slot_linuxcnc.ngc"),
    ("grind", "ab9_grind", "native", "", DOCUMENT + "_grind_ab9_native.nc"),
    ("grind", "linuxcnc_grind", "expanded", "", DOCUMENT + "_grind_linuxcnc.ngc"),
    ("mill", "milltronics_mill", "native", "", DOCUMENT + "_mill_milltronics_native.nc"),
]
# The Groove programs as (dialect, mode, arguments, file name), as earlier releases listed them.
OUTPUTS = [(post.split("_")[0], mode, args, name) for system, post, mode, args, name in PROGRAMS
           if system == "groove"]
# (system, what it is, the cycle words the issue names for it), in the summary's order
SYSTEMS = [
    ("groove", "Groove ops (lathe grooving)", ("CYCLE93", "G77", "G75")),
    ("slot", "Cylinder slot op (C axis, live tool)", ("G7.1",)),
    ("grind", "Plunge grind op (surface grinder)", ("G83",)),
    ("mill", "CAM's Face and Pocket Shape ops (mill)", ("G33", "G34")),
]


def system_words(system):
    """Every cycle word of the native posts of ``system``: what its expanded programs (LinuxCNC's) must not hold."""
    words = []
    for name, post, mode, _args, _file in PROGRAMS:
        if name == system and mode == "native":
            words += [w for w in CYCLE_WORDS[dialect_of(post)] if w not in words]
    return tuple(words)


class CycleWordMissing(RuntimeError):
    """A native program without its cycle word, or an expanded one with it."""


def dialect_of(post):
    """The engine's dialect of a post: "ab9_grind" -> "ab9grind", "gsk_lathe" -> "gsk"."""
    return "ab9grind" if post == "ab9_grind" else post.split("_")[0]


def _call_pattern(word):
    """A block that starts with ``word`` (no line number in the demo's programs), not a longer word."""
    return re.compile(r"^%s(?![\d.])" % re.escape(word), re.M)


# Blocks that carry a cycle word but are not a call: Fanuc's first G75/G74 block (the peck retract e),
# GSK's G7.1 C0 (leaving the cylinder interpolation).
NOT_A_CALL = re.compile(r"^(G7[45] R-?[\d.]+|G7\.1 C0)$", re.M)


def native_calls(text, words):
    """{word: how many blocks call it} of ``words`` in ``text``."""
    cleaned = NOT_A_CALL.sub("", text)
    counts = {word: len(_call_pattern(word).findall(cleaned)) for word in words}
    return {word: n for word, n in counts.items() if n}


def check_cycle_words(filename, post, mode, calls):
    """CycleWordMissing unless a native program calls every cycle word of its post and an expanded one none."""
    words = CYCLE_WORDS.get(dialect_of(post), ())
    if mode == "native":
        missing = [w for w in words if w not in calls]
        if missing:
            raise CycleWordMissing("%s: the %s post wrote no %s block in its native program" % (
                filename, post, " or ".join(missing)))
    elif calls:
        raise CycleWordMissing("%s: the %s post wrote native %s in an expanded program" % (
            filename, post, ", ".join(sorted(calls))))


_POSTS = {}


def load_post_file(post):
    """postprocessors/<post>_post.py as a module, loaded from its file like FreeCAD loads a script post."""
    import importlib.util

    if post not in _POSTS:
        path = os.path.join(POST_DIR, post + "_post.py")
        spec = importlib.util.spec_from_file_location(post + "_post", path)
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        _POSTS[post] = module
    return _POSTS[post]


def load_post(name):
    """The lathe post of dialect ``name`` ("linuxcnc": postprocessors/linuxcnc_lathe_post.py)."""
    return load_post_file(name + "_lathe")


def post_program(objects, out_dir, program):
    """One program of PROGRAMS from ``objects`` into ``out_dir``, checked: its summary entry."""
    system, post, mode, args, filename = program
    path = os.path.join(out_dir, filename)
    t0 = time.perf_counter()
    text = load_post_file(post).export(objects, path, args)
    seconds = time.perf_counter() - t0
    dialect = dialect_of(post)
    calls = native_calls(text, CYCLE_WORDS.get(dialect) or system_words(system))
    check_cycle_words(filename, post, mode, calls)
    return {
        "system": system, "post": post, "dialect": dialect, "mode": mode, "args": args, "file": filename,
        "bytes": os.path.getsize(path), "lines": text.count("\n"), "native_calls": calls,
        "seconds": round(seconds, 4),
    }


def post_all(objects_of, out_dir):
    """Every program of PROGRAMS into ``out_dir``; ``objects_of``: {system: the objects its posts get}."""
    return [post_program(objects_of[program[0]], out_dir, program) for program in PROGRAMS]
