"""Late bindings from an upper layer into a lower one, so imports still only
point down: the lower layer calls what the upper one set here.

view_provider_factory  set by the GUI layer when FreeCAD's GUI starts
                       (freecad_groove.gui.register); groove_op.Create calls
                       it with each new op, so ops made by scripts get the
                       view provider (icon, double-click opens the panel).
"""

view_provider_factory = None
slot_view_provider_factory = None  # the same for Cylinder slot ops (cylinder_slot_op.Create)
grind_view_provider_factory = None  # the same for Plunge grind ops (plunge_grind_op.Create)
