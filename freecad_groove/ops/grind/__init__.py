"""The Plunge grind op: an Allen-Bradley 9/Series G83/G83.1 plunge surface
grind of one flat face.

    op.py          ObjectPlungeGrind, the op's proxy (documents store its class path), Create(),
                   SetupProperties()
    properties.py  its properties, declared once, which G83 word each sets, the error naming them
    plan.py        what it grinds: the call, the wheel's start, the expansion (GrindPlan); the face read
    clearance.py   what the wheel's body sweeps, checked against the part
    path.py        the op's Path from its plan
    api.py         make_plunge_grind(): a Plunge grind in a Job from a script
    gui/           command.py, view.py (the view provider), panel.py (the task panel; its page class is
                   stored in the view provider's state), preview.py (the strokes drawn while it is open)

The grinding wheel tool bit: freecad/wheel_toolbit.py; the grinder posts: freecad/posts/grind.py.
"""

from ..registry import OpKind

KIND = OpKind(
    name="PlungeGrind",
    package=__name__,
    proxy="op.ObjectPlungeGrind",
    setup_properties="op.SetupProperties",
    view_provider="gui.view.ViewProviderPlungeGrind",
    command="gui.command.CommandPlungeGrind",
    icon="plunge_grind.svg",
)
