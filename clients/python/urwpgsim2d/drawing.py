"""Debug drawings and printed output a strategy sends with its decisions (run --debug-draw, --strategy-log)."""

import io
import math
from typing import List, Optional, Sequence, Union

MAX_SHAPES = 128
"""Shapes the server keeps per team and cycle; this client sends no more."""

MAX_TEXT = 4096
"""Characters of text (drawings' texts together, and printed output) the server keeps per team and cycle."""

Colour = Union[None, int, str]


class Drawing:
    """The shapes of one cycle: points, lines, circles and texts in field coordinates (mm).

    Given to the strategy as ``self.draw`` while it decides. When the server did not ask for
    drawings (run without --debug-draw), ``on`` is False and every call returns at once; test it
    before building an expensive text. ``fish`` is the index of one of the strategy's fish in
    ``snapshot.fish`` (None: the team's); ``colour`` is 0xRRGGBB or "#rrggbb" (None: the team's).
    """

    def __init__(self, on: bool = False, fish: Sequence[int] = ()):
        self.on = on
        self._fish = set(fish)
        self.shapes: List[dict] = []
        self.dropped = 0
        self._text = 0

    def point(self, at, fish: Optional[int] = None, colour: Colour = None) -> None:
        """A dot at ``at`` (x, y)."""
        self._add({"kind": "point", "at": _point(at)}, fish, colour)

    def line(self, start, end, fish: Optional[int] = None, colour: Colour = None) -> None:
        """A segment from ``start`` to ``end``."""
        self._add({"kind": "line", "from": _point(start), "to": _point(end)}, fish, colour)

    def circle(self, center, radius: float, fish: Optional[int] = None, colour: Colour = None) -> None:
        """A circle of ``radius`` mm about ``center``."""
        r = float(radius)
        self._add({"kind": "circle", "center": _point(center), "radius": r if math.isfinite(r) and r >= 0 else None}, fish, colour)

    def text(self, at, text: str, fish: Optional[int] = None, colour: Colour = None) -> None:
        """One line of ``text`` starting at ``at``; what passes the cycle's 4,096 characters is cut."""
        if not self.on or text is None:
            return
        room = MAX_TEXT - self._text
        line = str(text).replace("\n", " ")
        if room <= 0:
            self.dropped += 1
            return
        self._text += min(len(line), room)
        self._add({"kind": "text", "at": _point(at), "text": line[:room]}, fish, colour)

    def _add(self, shape: dict, fish: Optional[int], colour: Colour) -> None:
        if not self.on:
            return
        values = [v for k, v in shape.items() if k != "kind" and k != "text"]
        if any(v is None for v in values) or len(self.shapes) >= MAX_SHAPES:
            self.dropped += 1  # not finite, or past the bound
            return
        if fish is not None and int(fish) in self._fish:
            shape["fish"] = int(fish)
        if colour is not None:
            shape["color"] = _colour(colour)
        self.shapes.append(shape)


class Output(io.TextIOBase):
    """What a strategy prints while it decides, kept up to MAX_TEXT characters (the rest counted)."""

    def __init__(self):
        super().__init__()
        self._parts: List[str] = []
        self._length = 0
        self.dropped = 0

    def writable(self) -> bool:
        return True

    def write(self, s: str) -> int:
        room = MAX_TEXT - self._length
        if len(s) > room:
            self.dropped += len(s) - max(room, 0)
            s = s[:max(room, 0)]
        if s:
            self._parts.append(s)
            self._length += len(s)
        return len(s)

    def text(self) -> str:
        return "".join(self._parts)


def _point(p) -> Optional[list]:
    x, y = float(p[0]), float(p[1])
    return [x, y] if math.isfinite(x) and math.isfinite(y) else None


def _colour(c: Colour) -> str:
    if isinstance(c, str):
        if len(c) == 7 and c[0] == "#" and all(ch in "0123456789abcdefABCDEF" for ch in c[1:]):
            return c.lower()
        raise ValueError("a colour is 0xRRGGBB or '#rrggbb', got %r" % c)
    n = int(c)
    if not 0 <= n <= 0xFFFFFF:
        raise ValueError("a colour is 0xRRGGBB, got %r" % c)
    return "#%06x" % n
