"""Every choice the manuals leave open, as one named setting.

docs/choices.md lists each of these with its default and the manual text that
leaves it open; change them here, on the command line or in a post's options.
"""

from dataclasses import dataclass, replace
from typing import Optional

from .moves import GroovingTool

# The corner radius of a blade given by its width alone (--tool-width without --tool-radius).
DEFAULT_CORNER_RADIUS = 0.2


@dataclass(frozen=True)
class Settings:
    # The blade the cycles that need one (NEEDS_BLADE: CYCLE93, which places
    # its plunges with the width and checks WIDG against it) cut with. None:
    # unknown, and such a cycle is refused; there is no default width. The
    # translator takes a tool's own blade from a tool table first
    # (tool_table.blade_for); this one is then the blade of the tools the
    # table does not list.
    tool: Optional[GroovingTool] = None

    # Peck retract "e" of Allen-Bradley G77/G76 (AMP parameter) and of Haas
    # G75/G74 (setting 22 style), per side. None: 0.5 mm or 0.02 in.
    peck_retract: Optional[float] = None

    # CYCLE93: AXFA, DEPG, FAL1, FAL2 read as diameters (840D with DIAMON)
    # instead of radius values (the Siemens manual).
    cycle93_diameter_input: bool = False

    # CYCLE93: an optional shop limit on the contour's tilt (degrees away from
    # the groove's own axis); None: the Siemens manual's whole ANGC range 0..180 (only a
    # contour square to the groove's axis is refused, alarm 61603).
    cycle93_max_contour_tilt: Optional[float] = None

    # Allen-Bradley: True when G07 selects diameter mode and G08 radius mode;
    # the 9/Series manual uses both readings.
    ab_g07_is_diameter: bool = True

    # Clearance kept above the material top before a plunge and on traverses,
    # when the cycle itself has no retract parameter (per side).
    clearance: float = 1.0

    # Milltronics G33/G34: the end mill's diameter (None: unknown, and the
    # autoroutines are refused; there is no default tool).
    mill_tool_diameter: Optional[float] = None

    # Milltronics G33/G34: how far the tool rises above the depth just cut
    # before it goes to the next depth's start, in inches (the Milltronics manual's 0.1";
    # 2.54 mm in a metric program).
    milltronics_lift_inch: float = 0.1

    # Milltronics G31 without an earlier R in the program: the clearance
    # position (the control's parameter 140), and G32's tool change position
    # (set by the machine builder), as Z in inches (x 25.4 in a metric
    # program). The translated program's comment shows the Z used.
    milltronics_clearance_inch: float = 0.1
    milltronics_tool_change_inch: float = 4.0

    def retract_e(self, metric: bool = True) -> float:
        """The peck retract e in the program's units."""
        if self.peck_retract is not None:
            return self.peck_retract
        return 0.5 if metric else 0.02

    def with_tool(
        self, width: Optional[float] = None, corner_radius: Optional[float] = None, reference: Optional[str] = None
    ) -> "Settings":
        """These settings with the tool's given fields replaced (None: kept).

        Without a tool, ``width`` makes one (corner radius DEFAULT_CORNER_RADIUS
        and the minus reference corner unless given); with neither, the tool
        stays unknown: a radius or a reference corner alone is no blade.
        """
        tool = self.tool
        if tool is None:
            if width is None:
                return self
            tool = GroovingTool(width, DEFAULT_CORNER_RADIUS)
        tool = replace(
            tool,
            width=tool.width if width is None else width,
            corner_radius=tool.corner_radius if corner_radius is None else corner_radius,
            reference=tool.reference if reference is None else reference,
        )
        return replace(self, tool=tool)


DEFAULT_SETTINGS = Settings()
