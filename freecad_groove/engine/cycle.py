"""The cycle protocol: the base class of every registered cycle.

Everything the registry, the translator, the command line and verify read of
a cycle is declared here, once, with its default: a cycle class derives from
:class:`Cycle` (as a frozen dataclass, its words the fields), sets the class
attributes that differ and overrides the hooks it has. Nothing outside the
cycle asks whether a cycle has an attribute (``tests/test_cycle_protocol.py``
fails on a ``getattr``/``hasattr`` probe); ``registry.register`` checks the
declaration when the class is registered.

How the call is written over blocks is declared too: ``BLOCKS`` names a block
form (``block_forms.py``: one block, ``retract_block.RetractBlock``,
``region_blocks.RegionBlocks``) and the translator hands the cycle's blocks to
it; a program memory (``MEMORY``, ``program_memory.py``) and parameter blocks
(``PARAMETERS``, ``parameter_blocks.py``) are declared beside it.
"""

from typing import ClassVar, Dict, List, Optional, Tuple, Type

from .blade_limits import BladeEntry
from .block_forms import BlockForm, SingleBlock
from .moves import MachineState, Move
from .settings import DEFAULT_SETTINGS, Settings
from .warnings import CycleWarning

__all__ = ["CALL", "FORMS", "G_WORD", "REQUIRED_HOOKS", "Cycle", "Memory", "gives_hook"]

CALL = "call"  # FORM: the Siemens call syntax NAME(p1, p2, ...)
G_WORD = "g-word"  # FORM: the G code NAME among letter-and-number words
FORMS = (CALL, G_WORD)

Memory = Dict[str, float]  # what a call leaves for the next one of its program memory: word -> value


class Cycle:
    """A canned cycle: its declaration (class attributes) and its hooks (methods).

    A subclass is a frozen dataclass whose fields are the call's words; it
    sets NAME, KEY, DIALECTS, TITLE, FORM and WORD_HELP, and gives parse,
    emit and expand. Everything else has the default written here.
    """

    # -- the declaration: what the registry, the reader and the command line read ----------------

    NAME: ClassVar[str] = ""  # required: the code as the control writes it: "CYCLE93", "G77"
    KEY: ClassVar[str] = ""  # required: its name on the command line: "cycle93", "ab-g77"
    ALIASES: ClassVar[Tuple[str, ...]] = ()  # other command-line names: ("g77",)
    DIALECTS: ClassVar[Tuple[str, ...]] = ()  # required: the dialects whose programs call it: ("ab9",)
    TITLE: ClassVar[str] = ""  # required: one line for help texts
    FORM: ClassVar[str] = ""  # required: how its block is recognised: CALL or G_WORD
    WORD_HELP: ClassVar[Tuple[Tuple[str, str], ...]] = ()  # (word, help text), in the order emit() writes them
    COUNTED: ClassVar[Tuple[str, ...]] = ()  # words that are integers in least input increments (Fanuc P, Q)

    # -- the declaration: how the translator runs it -------------------------------------------------

    NEEDS_BLADE: ClassVar[bool] = False  # its moves depend on the blade: expanded only with a known one (CYCLE93)
    MILL: ClassVar[bool] = False  # mill-style moves (X plain, Y set): a mill-style dialect's, on the mill twins
    C_AXIS: ClassVar[bool] = False  # milled with a live tool turning C (GSK G7.1): no turned section to check
    Z_ONLY: ClassVar[bool] = False  # one rapid of Z alone: needs no start point, only the units (Milltronics G31)
    FROM_UNKNOWN_Z: ClassVar[bool] = False  # runs with the Z before the call not known (Milltronics G33/G34)
    BLOCKS: ClassVar[Type[BlockForm]] = SingleBlock  # how its call is written over blocks (block_forms.py)
    RETRACT_BLOCK: ClassVar[str] = ""  # BLOCKS = RetractBlock: the letter of the first block "NAME R(e)"
    MEMORY: ClassVar[str] = ""  # a program memory's key: the words a call omits come from the previous call
    MEMORY_WHAT: ClassVar[str] = "the words %s takes from the cycle before"  # the memory, for messages (%s: NAME)
    PARAMETERS: ClassVar[Tuple[str, ...]] = ()  # P parameters set by assignment blocks "P151=1", kept in MEMORY

    # -- the hooks ---------------------------------------------------------------------------------

    @classmethod
    def parse(cls, text: str) -> "Cycle":
        """Required: the call read from its text (its blocks, one a line); CycleError naming the word."""
        raise NotImplementedError("%s.parse" % cls.__name__)

    def emit(self) -> str:
        """Required: the call as the control writes it (its blocks, one a line); parse(emit()) == self."""
        raise NotImplementedError("%s.emit" % type(self).__name__)

    def validate(self, settings: Settings = DEFAULT_SETTINGS) -> "Cycle":
        """CycleError on the first rule the call breaks, with the control's alarm; returns self.
        Default: parse() checked everything."""
        return self

    def expand(self, state: MachineState, settings: Settings = DEFAULT_SETTINGS) -> List[Move]:
        """Required: the moves of the call from ``state`` (radius X, absolute Z; mill style: X, Y plain)."""
        raise NotImplementedError("%s.expand" % type(self).__name__)

    def warnings(self, state: MachineState, settings: Settings = DEFAULT_SETTINGS) -> List[CycleWarning]:
        """What the expansion from the same state cannot do as programmed but does anyway. Default: none."""
        return []

    def note(self, state: MachineState, settings: Settings) -> Optional[str]:
        """What the call did that its words do not say, for the translated program's comment (G32: the Z
        used); None: nothing."""
        return None

    def blade_depth(self, settings: Settings) -> Optional[Tuple[float, str]]:
        """(how deep the blade cuts below the surface, as a radius; the word that says it) for the blade's
        reach check (tool_table.reach_problem); None: the call does not say (the pecking cycles' programs
        do not say where the surface is). Default: None."""
        return None

    def blade_entry(self, state: MachineState, settings: Settings, moves: List[Move]) -> Optional[BladeEntry]:
        """Where the blade's first plunge of the expansion ``moves`` (from ``state``) cuts, for the holder's
        limits (blade_limits.limits_problem: a face-grooving blade's first-cut diameters, an internal bar's
        smallest bore); None: the call does not say where the part is. Default: None."""
        return None

    # program memory (MEMORY set): program_memory.py

    def with_earlier(self, memory: Memory, state: MachineState) -> "Cycle":
        """The call with the words it omits taken from ``memory`` (what the previous call left), in the
        distance mode of ``state``. Default (no memory): the call as it is."""
        return self

    def remembered(self, state: MachineState) -> Memory:
        """What the next call of the memory takes from this one. Default (no memory): nothing."""
        return {}

    # a region over several blocks (BLOCKS = RegionBlocks): region_blocks.py

    @classmethod
    def region_ends(cls, text: str) -> bool:
        """Whether the block ``text`` is the cancel block that closes the region. Default: no region."""
        return False

    @classmethod
    def check_region_block(cls, text: str, context: Optional[object]) -> Optional[object]:
        """CycleError when the path block ``text`` may not be in the region, checked as it is read;
        ``context`` is what the block before returned (None first). Default: nothing to check."""
        return context


REQUIRED_HOOKS = ("parse", "emit", "expand")  # the hooks a cycle must give (register() checks)


def gives_hook(cycle: type, name: str) -> bool:
    """Whether the cycle class (or a base class of it below Cycle) defines the hook ``name`` itself,
    rather than taking Cycle's default."""
    return any(name in vars(klass) for klass in cycle.__mro__ if klass is not Cycle and issubclass(klass, Cycle))
