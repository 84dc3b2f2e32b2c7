"""Native cycle calls: whether a cycle call is written as the target control's
own cycle, and as which call; else the one-line reason it is written as moves.

The one decision the lathe posts and ``expand --native-cycles`` share:

* ``result.py``: :class:`NotNative` (the reason, the project's one such
  type; the Milltronics post's recognition raises it too) and
  :class:`NativeCall` (the target's call, the rapids around it, the notes
  it needs, the moves it makes);
* ``cycle93_pecking.py``: plain CYCLE93 grooves as the pecking cycles
  (Allen-Bradley G77/G76, Fanuc/GSK/Haas G75/G74), as the posts write them;
* ``pecking_convert.py``: a pecking call as another control's pecking cycle
  or as CYCLE93, when both cut the same moves;
* ``compare.py``: the comparison of move lists that proves it;
* ``decide.py``: :class:`NativeOutput`, the decision call by call for one
  translated program and target;
* ``pairs.py``: which pairs are native, for the command line's help.

The decision never formats output: the writer writes the call
(``engine/output/native.py``) or the moves.
"""

from .decide import NativeOutput, family_of
from .pairs import native_pairs
from .result import NativeCall, NotNative, Point

__all__ = ["NativeCall", "NativeOutput", "NotNative", "Point", "family_of", "native_pairs"]
