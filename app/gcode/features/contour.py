"""A closed contour of G00/G01/G02/G03 lines (the paper's figure 4) -> segments, polygon.

The first line must position (G00/G01 X Y); each later line is a line or an XY arc
(``R`` or ``I J``, ``R`` < 0 for the long way), modal G and coordinates as G-code
has them; blank lines, ``( )`` and ``;`` comments are ignored. Errors name the
contour's file, line and column: a word other than G0-G3/X/Y/R/I/J/N/F, an arc
whose radius cannot reach its end, a contour that does not end where it began, one
that crosses itself. One full circle (``G02``/``G03`` back to its start with I J) is a
contour.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

from shapely.geometry import LinearRing, Polygon

from app.i18n import msg

from ..lexer import lex_line
from ..reading import SourceError, clean_bytes, read_source, text_problem
from .errors import FeatureError
from .ranges import COORD

CHORD_TOL = 0.002  # mm, chord error when arcs become polygon edges


@dataclass(frozen=True)
class Segment:
    """A line (``center`` None) or arc from ``start`` to ``end``; ``line`` in the file."""

    start: tuple[float, float]
    end: tuple[float, float]
    center: tuple[float, float] | None = None
    cw: bool = False
    line: int = 0

    def points(self, tol: float = CHORD_TOL) -> list[tuple[float, float]]:
        """Points after ``start`` up to ``end`` (arcs as chords within ``tol``)."""
        if self.center is None:
            return [self.end]
        cx, cy = self.center
        radius = math.dist(self.start, self.center)
        a0 = math.atan2(self.start[1] - cy, self.start[0] - cx)
        sweep = sweep_angle(self.start, self.end, self.center, self.cw)
        step = 2 * math.acos(max(-1.0, 1 - tol / radius)) if radius > tol else math.pi / 2
        count = max(2, math.ceil(abs(sweep) / step))
        angles = [a0 + sweep * k / count for k in range(1, count)]
        pts = [(cx + radius * math.cos(a), cy + radius * math.sin(a)) for a in angles]
        return pts + [self.end]


def sweep_angle(start, end, center, cw: bool) -> float:
    """Signed sweep (radians, < 0 clockwise) of an arc; a full circle when start == end."""
    a0 = math.atan2(start[1] - center[1], start[0] - center[0])
    a1 = math.atan2(end[1] - center[1], end[0] - center[0])
    sweep = a1 - a0
    if cw:
        while sweep >= -1e-12:
            sweep -= 2 * math.pi
    else:
        while sweep <= 1e-12:
            sweep += 2 * math.pi
    return sweep


@dataclass(frozen=True)
class Contour:
    """The segments of a closed contour and its polygon (arcs as chords)."""

    name: str
    segments: tuple[Segment, ...]

    def polygon(self, tol: float = CHORD_TOL) -> Polygon:
        pts = [self.segments[0].start]
        for seg in self.segments:
            pts += seg.points(tol)
        return Polygon(pts[:-1])


def _fail(name: str, line: int, column: int, what: str) -> FeatureError:
    return FeatureError("contour", msg("{name}, line {line}, column {column}: {what}", name=name, line=line,
                                       column=column, what=what))


def _arc_center(start, end, radius: float, cw: bool, where) -> tuple[float, float]:
    chord = math.dist(start, end)
    if chord < 1e-9 or chord > 2 * abs(radius) + 1e-6:
        raise where(msg("an arc of radius {radius:g} cannot reach from {start} to {end}", radius=abs(radius),
                        start=str(start), end=str(end)))
    mx, my = (start[0] + end[0]) / 2, (start[1] + end[1]) / 2
    h = math.sqrt(max(0.0, radius * radius - chord * chord / 4))
    ux, uy = (end[0] - start[0]) / chord, (end[1] - start[1]) / chord
    side = 1.0 if (cw == (radius < 0)) else -1.0  # centre left of the chord for G03 with R > 0
    return mx - uy * h * side, my + ux * h * side


def _segment(words: dict, state: dict, line: int, name: str, columns: dict) -> Segment | None:
    start = state["pos"]
    x, y = words.get("X", start[0]), words.get("Y", start[1])
    end = (x, y)
    mode = state["g"]
    where = lambda what: _fail(name, line, columns.get("R", columns.get("G", 1)), what)  # noqa: E731
    if mode in (0, 1):
        return None if math.dist(start, end) < 1e-9 else Segment(start, end, None, False, line)
    cw = mode == 2
    if "R" in words:
        return Segment(start, end, _arc_center(start, end, words["R"], cw, where), cw, line)
    if "I" in words or "J" in words:
        center = (start[0] + words.get("I", 0.0), start[1] + words.get("J", 0.0))
        if abs(math.dist(center, start) - math.dist(center, end)) > 0.002:
            raise where(msg("the arc's end is not on the circle of its I J centre"))
        return Segment(start, end, center, cw, line)
    raise where(msg("G0{mode} needs R or I J", mode=mode))


def parse_contour(text: str, name: str = "<contour>") -> Contour:
    """The closed contour in ``text``; raises ``FeatureError("contour", ...)``."""
    state = {"g": None, "pos": None}
    segments: list[Segment] = []
    first_line = 0
    for line_no, raw in enumerate(text.splitlines(), 1):
        lexed = lex_line(raw, line_no)
        if lexed.error is not None:
            raise _fail(name, line_no, lexed.error.column, lexed.error.message)
        if not lexed.words:
            continue
        words, columns = {}, {}
        for w in lexed.words:
            if w.letter == "G":
                if w.value not in (0, 1, 2, 3):
                    raise _fail(name, line_no, w.column, msg("G{code:g}: a contour has only G00-G03",
                                                             code=float(w.value)))
                state["g"] = int(w.value)
            elif w.letter in "XYRIJ":
                if not abs(w.value) <= COORD:
                    raise _fail(name, line_no, w.column, msg("{letter}{value:g} is beyond {limit:g} mm",
                                                             letter=w.letter, value=float(w.value),
                                                             limit=COORD))
                words[w.letter], columns[w.letter] = w.value, w.column
            elif w.letter not in "NF":
                raise _fail(name, line_no, w.column, msg("{letter}: a contour has only G, X, Y, R, I, J",
                                                         letter=w.letter))
            columns.setdefault("G", w.column)
        if state["g"] is None:
            raise _fail(name, line_no, 1, msg("expected G00/G01/G02/G03 first"))
        if state["pos"] is None:
            if "X" not in words or "Y" not in words:
                raise _fail(name, line_no, 1, msg("the first line must give the start point, X and Y"))
            state["pos"], first_line = (words["X"], words["Y"]), line_no
            continue
        seg = _segment(words, state, line_no, name, columns)
        if seg is not None:
            segments.append(seg)
            state["pos"] = seg.end
    return _closed(Contour(name, tuple(segments)), first_line)


def read_contour(path) -> Contour:
    """The contour in the file ``path``, after the loader's own file checks (a regular
    file within its size, UTF-8 text without NUL bytes); ``FeatureError("contour", ...)``."""
    try:
        raw = clean_bytes(read_source(path))
    except SourceError as exc:
        raise FeatureError("contour", exc.args[0]) from None
    problem = text_problem(raw)
    if problem:
        raise FeatureError("contour", msg("{path}: {problem}", path=str(path), problem=problem))
    return parse_contour(raw.decode("utf-8"), Path(path).name)


def _closed(contour: Contour, first_line: int) -> Contour:
    segs = contour.segments
    if not segs or (len(segs) == 1 and segs[0].center is None):  # one full circle is a contour
        raise FeatureError("contour", msg("{name}: a contour needs at least two segments or one full "
                                          "circle", name=contour.name))
    gap = math.dist(segs[0].start, segs[-1].end)
    if gap > 0.001:
        raise FeatureError("contour", msg("{name}, line {line}: the contour is not closed: it ends at "
                                          "({x:g}, {y:g}), {gap:.3f} mm from its start on line {first}",
                                          name=contour.name, line=segs[-1].line, x=float(segs[-1].end[0]),
                                          y=float(segs[-1].end[1]), gap=float(gap), first=first_line))
    ring = LinearRing(contour.polygon().exterior.coords)
    if not ring.is_simple or not contour.polygon().is_valid:
        raise FeatureError("contour", msg("{name}: the contour crosses itself", name=contour.name))

    return contour
