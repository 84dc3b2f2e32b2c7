"""The Groove op: CYCLE93 grooves on faces of a turned part.

    op.py          ObjectGroove, the op's proxy (documents store its class path), Create(), SetupProperties()
    properties.py  its properties, declared once, which CYCLE93 parameter each sets, the error naming them
    plan.py        one groove's plan: its start point, the engine's moves, the link to it
    links.py       the safe envelope around the Job's model and the link rapids along it
    path.py        the op's Path from its plans
    cutting.py     its lathe feeds and speeds (its own, the tool controller's, the defaults)
    bounds.py      the range of each numeric property (docs/op-bounds.md), checked before it plans
    reach.py       the grooving blade's free reach (CuttingEdgeHeight) against the groove's Depth
    cache.py       its plans kept in the saved document, with the fingerprint of their inputs
    model.py       a groove read from the modelled part (the turned section's notch)
    api.py         make_groove(): a Groove in a Job from a script
    gui/           command.py, view.py (the view provider), panel.py (the task panel; tool_page.py its
                   tool page), preview.py (the grooves drawn while the panel is open)

A picked face is read by freecad/faces.py (shared: the Cylinder slot names its elements the same way).
"""

from ..registry import OpKind

KIND = OpKind(
    name="Groove",
    package=__name__,
    proxy="op.ObjectGroove",
    setup_properties="op.SetupProperties",
    view_provider="gui.view.ViewProviderGroove",
    command="gui.command.CommandGroove",
    icon="groove.svg",
)
