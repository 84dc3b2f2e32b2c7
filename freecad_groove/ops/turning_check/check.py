"""verify_job(): the turning check of a CAM Job's Groove ops (FreeCAD layer, no Qt).

FreeCAD's CAM simulators mill; this sweeps each Groove op's blade along its
Path over the turned section of the Job's stock and judges what it cuts
against the model's section (freecad_groove.verify.turning has the figures).
Here the Job is read into plain data:

* the model's section: each model object's shape cut by the plane X = 0
  (through the turning axis, the global Z axis), its wires discretized to
  SECTION_DEFLECTION and taken at Y >= 0 (Y is then the radius);
* the stock's section, one of STOCKS (``stock=``, said in the result's
  notes): the Job's stock (STOCK_JOB, the default): a bar from its bounds
  (radius: its largest extent from the axis in X or Y, so a box stock counts
  as the bar that fits in it; Z: its Z range), or, for CAM's stock from an
  existing solid (a turned blank, the part itself), that solid's own
  section; a Job without stock: a bar of the model's largest radius over the
  model's Z range. Or the part as turned (STOCK_TURNED): the model's contour
  plus the material of the ops' planned grooves, what a grooving op assumes
  it starts from (a bar stock then shows no rapids through the material a
  turning op would have taken first);
* per op (in the Job's order, inactive ops left out): its Path's G0/G1/G4
  moves and arcs G2/G3 (G18: centre I, K from the start) split at its
  comments into one run per planned groove (groove/plan.py),
  each swept with the op's blade (ObjectGroove.settings, as the tool
  controller gives it now) in the groove's plunge direction; the planned
  finished groove and the engine's reach warnings; whether the groove is
  the design's though the model does not show it (programmed by its values
  on a plain face; never one in a face of a modelled groove: the model says
  what the op must leave there); the feeds and speeds
  (groove/cutting.py) with the tool controller's rapid rates (HorizRapid for X,
  VertRapid for Z); the blade's holder where its tool bit gives CuttingEdgeHeight
  and HolderWidth (verify/holder.py: a holder entering standing material is
  reported with the op and the move).

Each checked op's CycleTime becomes its machining time (HH:MM:SS, as
FreeCAD's ops write it) and the Job's CycleTime their sum. A recompute of
the op puts FreeCAD's own estimate (from the tool controller's feeds) back.

The check needs nothing FreeCAD does not ship: the column model of
freecad_groove.verify.turning runs on numpy (shapely, which FreeCAD does not
bundle, is only the tests' second oracle).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Optional

import FreeCAD

from ...engine.cycles.cycle93_reach import unreachable_regions
from ...engine.moves import ARC_CCW, ARC_CW, ARCS, DWELL, FEED, RAPID, Move
from ...freecad.units import feed_mm_per_min, length_mm
from ..groove.cutting import cutting_data

if TYPE_CHECKING:
    from ...verify.holder import Holder
    from ...verify.machining_time import Feeds
    from ...verify.turning import JobCheck, OpInput

SECTION_DEFLECTION = 1e-4  # mm: largest chord error of the model's discretized section
MOTION = {"G0": RAPID, "G00": RAPID, "G1": FEED, "G01": FEED, "G2": ARC_CW, "G02": ARC_CW, "G3": ARC_CCW,
          "G03": ARC_CCW}
MODAL = {"G18", "G90", "G21", "G40", "G80"}  # words that move nothing


STOCK_JOB = "job"
STOCK_TURNED = "turned"
STOCKS = {STOCK_JOB: "the Job's stock", STOCK_TURNED: "the part as turned"}  # verify_job(stock=...): in words


class TurningCheckError(ValueError):
    """A Job that cannot be checked at all (an op that cannot is reported in its OpCheck)."""


def _check_job(job: object) -> list:
    """The model objects' shapes; TurningCheckError when ``job`` is no CAM Job with a model."""
    if not all(hasattr(job, name) for name in ("Model", "Operations", "Proxy")):
        raise TurningCheckError("verify_job(): job=%r is not a CAM Job (it has no Model and Operations)" % (job,))
    shapes = [o.Shape for o in job.Model.Group if hasattr(o, "Shape") and not o.Shape.isNull()]
    if not shapes:
        raise TurningCheckError("verify_job(): the Job %s has no model with a shape to check against" % job.Label)
    return shapes


def model_rings(shapes: list) -> list[list[tuple[float, float]]]:
    """The shapes cut through the turning axis by the plane X = 0: closed
    rings of (z, y) points (both halves, y may be negative)."""
    rings = []
    for shape in shapes:
        for wire in shape.slice(FreeCAD.Vector(1, 0, 0), 0.0):
            points = wire.discretize(Deflection=SECTION_DEFLECTION)
            rings.append([(p.z, p.y) for p in points])
    return rings


def existing_solid_stock(job: object) -> Optional[object]:
    """The Job's stock when CAM made it from an existing solid (its StockType "Unknown", headless told by
    having none of the other kinds' properties: a clone of a turned blank, or of the part itself), else None."""
    import Path.Main.Stock as PathStock

    stock = getattr(job, "Stock", None)
    shape = getattr(stock, "Shape", None)
    if shape is None or shape.isNull() or not shape.Solids:
        return None
    return stock if PathStock.StockType.FromStock(stock) == PathStock.StockType.Unknown else None


def stock_section(job: object, shapes: list, inputs: list, stock: str) -> tuple[object, str]:
    """(the stock's section, the note saying which) of STOCKS ``stock``."""
    from ...verify.shapes import union_all
    from ...verify.turned_section import bar_section, groove_region, rings_section

    if stock == STOCK_TURNED:
        model = rings_section(model_rings(shapes))
        grooves = [groove_region(run.region) for op in inputs if not op.error for run in op.grooves]
        return union_all([model] + grooves), ("stock: the part as turned (the model's contour plus the material "
                                              "of the ops' planned grooves)")
    solid = existing_solid_stock(job)
    if solid is not None:
        return rings_section(model_rings([solid.Shape])), "stock: the Job's stock %s, its own section" % solid.Label
    radius, zmin, zmax, where = stock_bar(job, shapes)
    return bar_section(radius, zmin, zmax), "stock: a bar R%.3f from Z%.3f to Z%.3f (%s)" % (radius, zmin, zmax,
                                                                                              where)


def stock_bar(job: object, shapes: list) -> tuple[float, float, float, str]:
    """(radius, zmin, zmax, where from) of the stock's bar."""
    stock = getattr(getattr(job, "Stock", None), "Shape", None)
    if stock is not None and not stock.isNull() and stock.BoundBox.isValid():
        box = stock.BoundBox
        radius = max(box.XMax, -box.XMin, box.YMax, -box.YMin)
        return radius, box.ZMin, box.ZMax, "the Job's stock %s" % job.Stock.Label
    radius, zmin, zmax = 0.0, float("inf"), float("-inf")
    for shape in shapes:
        box = shape.BoundBox
        radius = max(radius, box.XMax, -box.XMin, box.YMax, -box.YMin)
        zmin, zmax = min(zmin, box.ZMin), max(zmax, box.ZMax)
    return radius, zmin, zmax, "no stock in the Job: the model's largest radius"


def path_runs(op: object) -> list[list[tuple[int, Move]]]:
    """The op's Path as runs of (command number, Move), a new run at each
    comment followed by motion (an arc G2/G3 with its centre, I and K from its
    start). TurningCheckError on a command the check cannot sweep (a Y move,
    another code) or a move before X and Z are known."""
    runs, comment, pos = [], True, [None, None]
    for number, command in enumerate(op.Path.Commands, 1):
        name, words = command.Name, command.Parameters
        if name.startswith("("):
            comment = True
            continue
        if name in MODAL:
            continue
        what = "%s: Path command %d (%s)" % (op.Label, number, command.toGCode().strip())
        if name not in MOTION and name != "G4":
            raise TurningCheckError("%s: not a move or dwell (G0, G1, G2, G3, G4): cannot be swept" % what)
        if abs(words.get("Y", 0.0)) > 1e-9 or abs(words.get("J", 0.0)) > 1e-9:
            raise TurningCheckError("%s: moves in Y; the lathe's moves are X (radius) and Z" % what)
        start, pos = pos, [words.get("X", pos[0]), words.get("Z", pos[1])]
        kind = MOTION.get(name, DWELL)
        if None in pos or (kind in ARCS and None in start):
            raise TurningCheckError("%s: where the tool is (X and Z) is not known yet" % what)
        if comment or not runs:
            runs.append([])
            comment = False
        centre = (start[0] + words.get("I", 0.0), start[1] + words.get("K", 0.0)) if kind in ARCS else None
        runs[-1].append((number, Move(kind, pos[0], pos[1], None, words.get("P", 0.0) if kind == DWELL else 0.0,
                                      centre=centre)))
    return runs


def _feeds(op: object) -> Feeds:
    from ...verify.machining_time import Feeds

    cutting = cutting_data(op)
    tc = getattr(op, "ToolController", None)
    rapid_x = feed_mm_per_min(length_mm(tc.HorizRapid)) if tc is not None else 0.0
    rapid_z = feed_mm_per_min(length_mm(tc.VertRapid)) if tc is not None else 0.0
    return Feeds(cutting.feed, cutting.per_rev, cutting.rpm, cutting.surface_speed, cutting.max_rpm,
                 rapid_x, rapid_z)


def _holder(op: object) -> Optional[Holder]:
    """The blade's holder the check draws: its tool bit's CuttingEdgeHeight and HolderWidth, when both are given
    (freecad/blade_holder.py); None: not drawn."""
    from ...freecad.blade_holder import holder_outline
    from ...verify.holder import Holder

    bit = getattr(getattr(op, "ToolController", None), "Tool", None)
    outline = holder_outline(bit) if bit is not None and getattr(bit, "Width", None) is not None else None
    return Holder(*outline) if outline is not None else None


def op_input(op: object) -> OpInput:
    """The verify.turning.OpInput of Groove op ``op`` (its error when it cannot be checked)."""
    from ...freecad.addon_op import op_error
    from ...verify.turning import GrooveRun, OpInput

    try:
        error = op_error(op)
        if error:
            raise TurningCheckError("the op has an error: %s" % error)
        plans = op.Proxy.current_plan(op)
        tool = op.Proxy.settings(op).tool
        runs = path_runs(op)
        if len(runs) != len(plans):
            raise TurningCheckError("its Path has %d groove section(s) but the op plans %d groove(s): recompute it"
                                    % (len(runs), len(plans)))
        programmed = not op.ModelGroove and not op.Proxy.in_modelled_groove(op)
        holder = _holder(op)
        grooves = [GrooveRun([m for _n, m in run], [n for n, _m in run], tool, plan.cycle.plunge_direction(),
                             plan.geometry.region_world(), sum(u.area for u in unreachable_regions(plan.geometry)),
                             programmed, holder)
                   for run, plan in zip(runs, plans)]
        first = runs[0][0][1] if runs else Move(RAPID, 0.0, 0.0)
        return OpInput(op.Label, (first.x, first.z), grooves, _feeds(op))
    except ValueError as e:  # TurningCheckError, GrooveInputError, CycleError: the op's message
        return OpInput(op.Label, error=str(e).replace(op.Label + ": ", "", 1))


def groove_ops(job: object) -> tuple[list, list[str]]:
    """The Job's active Groove ops in order, and notes on the ops left out."""
    from ..groove.op import ObjectGroove

    ops, notes = [], []
    for op in job.Operations.Group:
        if not isinstance(getattr(op, "Proxy", None), ObjectGroove):
            notes.append("%s: not a Groove op, not simulated" % op.Label)
        elif getattr(op, "Active", True) is False:
            notes.append("%s: inactive, not simulated" % op.Label)
        else:
            ops.append(op)
    return ops, notes


def _set_cycle_times(job: object, ops: list, result: JobCheck) -> None:
    from ...verify.machining_time import clock_text

    for op, check in zip(ops, result.ops):
        if check.time is not None and hasattr(op, "CycleTime"):
            op.CycleTime = clock_text(check.time.total)
    try:
        job.Proxy.getCycleTime()  # the Job's total, as FreeCAD's ops update it
    except Exception as e:  # an older CAM without it: the ops' times stand
        FreeCAD.Console.PrintLog("verify_job: the Job's CycleTime not updated: %s\n" % e)


def verify_job(job: object, tol: Optional[float] = None, stock: str = STOCK_JOB) -> JobCheck:
    """Check the Groove ops of CAM Job ``job`` in a turned section of its stock: ``stock`` "job" (STOCK_JOB:
    the Job's stock) or "turned" (STOCK_TURNED: the part as turned, the model's contour plus the grooves'
    material); the result's first note says which.

    Returns a verify.turning.JobCheck: per op (OpCheck) material removed,
    gouge (area, depth, where), leftover the blade could reach, unreachable
    material, rapids through standing stock, machining time; ``summary()``
    prints them. Sets each checked op's CycleTime. An op that cannot be
    checked carries its reason in ``error``. Raises TurningCheckError (a
    ValueError) when ``job`` is no Job with a model.
    """
    if stock not in STOCKS:
        raise TurningCheckError("verify_job(): stock=%r: must be %s" % (stock, " or ".join(
            "%r (%s)" % item for item in STOCKS.items())))
    from ...verify.turned_section import rings_section
    from ...verify.turning import DEFAULT_TOL, check_ops

    shapes = _check_job(job)
    ops, notes = groove_ops(job)
    inputs = [op_input(op) for op in ops]
    section, note = stock_section(job, shapes, inputs, stock)
    notes.insert(0, note)
    result = check_ops(inputs, section, rings_section(model_rings(shapes)), DEFAULT_TOL if tol is None else tol,
                       notes)
    _set_cycle_times(job, ops, result)
    return result
