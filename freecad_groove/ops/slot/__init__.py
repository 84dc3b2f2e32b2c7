"""The Cylinder slot op: a slot milled on a cylinder by a live end mill on a
lathe with a C axis, as a GSK G7.1 Type II region.

    op.py          ObjectCylinderSlot, the op's proxy (documents store its class path), Create(),
                   SetupProperties()
    properties.py  its properties, declared once, and the error naming them
    plan.py        what it cuts: the region, its start, the safe radius, the moves (SlotPlan)
    developed.py   the picked face and the slot's edges (or a sketch) developed into Z and C
    reach.py       whether the end mill reaches the slot's bottom and clears the part
    path.py        the op's Path from its plan
    api.py         make_cylinder_slot(): a Cylinder slot in a Job from a script
    gui/           command.py, view.py (the view provider: the Path drawn wrapped on the cylinder),
                   panel.py (the task panel), preview.py (the developed path drawn in the panel)

In the posts: freecad/posts/slots.py (and live_tool.py, the live tool and C axis switches).
"""

from ..registry import OpKind

KIND = OpKind(
    name="CylinderSlot",
    package=__name__,
    proxy="op.ObjectCylinderSlot",
    setup_properties="op.SetupProperties",
    view_provider="gui.view.ViewProviderCylinderSlot",
    command="gui.command.CommandCylinderSlot",
    icon="cylinder_slot.svg",
)
