"""The blade corner a post's words measure (``--reference-corner``) against the op's own.

A groove plan's words are for the op's ReferenceCorner; when the post writes
the other corner, every word moves by the blade's width along the groove's
axis (Z for longitudinal grooves, X for face grooves), the blade does not.
The engine's native-call decision does the same (engine/native/cycle93_pecking.py).
"""

from ...engine.native.cycle93_pecking import Shift, corner_settings, corner_shift, shifted

__all__ = ["Shift", "corner_settings", "corner_shift", "shifted"]
