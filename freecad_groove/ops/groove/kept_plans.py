"""A Groove op's plans kept for the posts while what they were planned from
stays the same: in the session (the last recompute's, checked against the op's
state, its tool and the other objects it reads: cache.inputs, each read again
only after it changed, freecad/changes.py) and in the saved document (cache.py:
the plans with the fingerprint of their inputs, reused after reopening while
it matches).

ObjectGroove (op.py) takes this in; its plan(), _parent_job(), tool_changed()
and ``error`` are what it uses.

FreeCAD layer: FreeCAD only.
"""

from typing import Optional

import FreeCAD

from ...freecad import changes
from . import cache
from .cutting import CuttingData, cutting_data
from .plan import GroovePlan


class KeptPlans:
    """The plan keeping of the Groove op's proxy."""

    def current_plan(self, obj: object) -> list[GroovePlan]:
        """plan(obj) as the last recompute made it, while nothing it was planned
        from has changed since: the op untouched, its tool the same, the other
        objects it reads (tool controller, tool bit, model, stock: cache.inputs)
        the same (planning checks every link rapid against the model, the
        costly part of posting); after reopening the document, the plans it
        saved while their fingerprint still matches (cache.py); otherwise
        a fresh plan, kept (with its fingerprint, for the saved document too)
        while the op stays untouched: a post after reopening a document whose
        saved plans no longer match, or that saved none, plans once, not at
        every post."""
        plans = getattr(self, "_plans", None)
        if plans is not None and self._plans_current(obj):
            return plans
        untouched = self._untouched(obj)
        if untouched and plans is None:
            plans = self._restored_plans(obj)
            if plans is not None:
                return plans
        plans = self.plan(obj)
        if untouched:
            self._keep_plans(obj, plans)
        return plans

    def current_cutting(self, obj: object) -> CuttingData:
        """cutting_data(obj) (the posts ask twice an op), kept with the plans while they are current: it reads
        the op and its tool controller's feeds and speeds, which tool_changed and cache.inputs watch."""
        kept = getattr(self, "_cutting", None)
        if kept is not None and self._plans_current(obj):
            return kept
        cutting = cutting_data(obj)
        if self._plans_current(obj):
            self._cutting = cutting
        return cutting

    def _untouched(self, obj: object) -> bool:
        """The op without an error, untouched since its last recompute, its tool the same."""
        return getattr(self, "error", None) is None and not ({"Touched", "Invalid"} & set(obj.State)) \
            and not self.tool_changed(obj)

    def _plans_current(self, obj: object) -> bool:
        """Whether the kept plans are what plan(obj) would make now: the op untouched, its tool the same, the
        objects it reads the same; not checked again while no document object changed since (changes.py)."""
        if getattr(self, "_plans", None) is None:
            return False
        now = changes.last_change()
        if getattr(self, "_current_at", None) == now:
            return True
        current = self._untouched(obj) and not self._inputs_changed(obj)
        self._current_at = now if current else None
        return current

    # -- the plans kept in the document (cache.py) ---------------------------
    def _keep_plans(self, obj: object, plans: list[GroovePlan], cutting: Optional[CuttingData] = None) -> None:
        """Keep ``plans`` (and the op's ``cutting`` data when known) for the posts, with what they were planned
        from (cache.inputs); their fingerprint for the saved document is taken when it is saved
        (_saved_fingerprint), not at every recompute."""
        self._plans, self._planned_op, self._fingerprint, self._cutting = plans, obj, None, cutting
        self._current_at = None
        try:
            self._inputs = cache.inputs(obj, self._parent_job(obj))
        except Exception as e:  # never a reason to fail the op: the next post plans again
            self._inputs = None
            FreeCAD.Console.PrintLog("%s: plans not kept for the saved document: %s\n" % (obj.Label, e))

    def _saved_fingerprint(self) -> Optional[str]:
        """The fingerprint the kept plans are saved with (cache.fingerprint), taken once: the op's own
        values now are those they were planned from while the op is untouched (any change of a property
        touches it until the next recompute, which plans again), the other objects' while cache.inputs is
        the same. None (nothing saved: the next post after reopening plans) when either changed."""
        obj = getattr(self, "_planned_op", None)
        if getattr(self, "_fingerprint", None) is None and obj is not None:
            try:
                if not ({"Touched", "Invalid"} & set(obj.State)) and not self.tool_changed(obj) \
                        and not self._inputs_changed(obj):
                    self._fingerprint = cache.fingerprint(obj, None, shared=self._inputs)
            except Exception as e:  # an op FreeCAD deleted, a broken document: nothing saved
                FreeCAD.Console.PrintLog("Groove: plans not saved: %s: %s\n" % (type(e).__name__, e))
        return getattr(self, "_fingerprint", None)

    def _inputs_changed(self, obj: object) -> bool:
        """Whether an object the kept plans were planned from (cache.inputs: not the op itself) changed since
        (a Job's stock changed recomputes no op); each read again only after it changed, and not at all while
        no document object changed since the last check (changes.py: the next ops of a post)."""
        if getattr(self, "_inputs", None) is None:
            return True
        if getattr(self, "_inputs_checked", None) == changes.last_change():
            return False
        try:
            changed = cache.inputs(obj, self._parent_job(obj), changes.unchanged_memo()) != self._inputs
        except Exception:  # plan again, which says what is wrong
            return True
        if not changed:
            self._inputs_checked = changes.last_change()
        return changed

    def _restored_plans(self, obj: object) -> Optional[list[GroovePlan]]:
        """The plans the opened document saved, when their fingerprint is that
        of the op's inputs now (kept from then on); None otherwise. The Job's
        other Groove ops that still hold saved plans are checked at the same
        time (a post reads them next), the inputs they share read once."""
        if not getattr(self, "_saved_plans", None):
            return None
        try:
            job = self._parent_job(obj)
        except ValueError as e:
            self._saved_plans = None
            FreeCAD.Console.PrintLog("%s: saved plans not used: %s\n" % (obj.Label, e))
            return None
        memo = changes.unchanged_memo()  # the digests of the shared inputs, read once
        self._restore(obj, job, memo)
        for other in getattr(getattr(job, "Operations", None), "Group", None) or []:
            proxy = getattr(other, "Proxy", None)
            if isinstance(proxy, KeptPlans) and getattr(proxy, "_saved_plans", None) \
                    and getattr(proxy, "_plans", None) is None and getattr(proxy, "error", None) is None \
                    and not ({"Touched", "Invalid"} & set(other.State)):
                proxy._restore(other, job, memo)
        return getattr(self, "_plans", None)

    def _restore(self, obj: object, job: object, memo: dict) -> None:
        """Take the saved plans as the op's plans when their fingerprint matches (then, or never)."""
        saved, self._saved_plans = self._saved_plans, None
        try:
            shared = cache.inputs(obj, job, memo)
            stamp = cache.fingerprint(obj, job, shared=shared)
            if stamp == saved.fingerprint:
                self._plans, self._fingerprint, self._inputs, self._cutting = saved.plans, stamp, shared, None
                self._current_at = None
                self._inputs_checked = changes.last_change()  # the next current_plan: nothing to read again
        except Exception as e:  # plan again
            FreeCAD.Console.PrintLog("%s: saved plans not used: %s\n" % (obj.Label, e))

    def dumps(self) -> Optional[dict]:
        """The proxy's saved state: the op's plans with their fingerprint
        (cache.py), or what the opened document held when they were not
        needed yet."""
        plans = getattr(self, "_plans", None)
        stamp = self._saved_fingerprint() if plans is not None and getattr(self, "error", None) is None else None
        if stamp:
            return {"plans": cache.pack(plans, stamp)}
        saved = getattr(self, "_saved_plans", None)
        return {"plans": saved.text} if saved else None

    def loads(self, state: object) -> None:
        """Read the saved plans as the document opens (cache.read), so
        that the first post only checks their fingerprint (_restored_plans)."""
        try:
            self._saved_plans = cache.read(state.get("plans") if isinstance(state, dict) else None)
        except Exception as e:  # never a reason not to open the document: the post plans again
            self._saved_plans = None
            FreeCAD.Console.PrintLog("Groove: saved plans not read: %s: %s\n" % (type(e).__name__, e))
