"""Reader for LinuxCNC ``rs274 -g`` canonical output, as recorded by ``record.py``.

No dependency beyond the standard library, so the GUI or a bench can reuse it::

    from tests.oracle.canon import read_record
    rec = read_record("tests/oracle/data/arcs_circles.canon")
    rec.moves      # list of dicts in the ``cnc-gcode moves`` format (mm)
    rec.error_line # 1-based physical line where rs274 refused the program, or None

``rs274 -g`` prints one canonical call per line::

        12 N17    STRAIGHT_FEED(10.0000, 2.0000, 3.0000, 0.0000, 0.0000, 0.0000)

a running counter, the block's ``N`` word as written in the source (``N.....`` when
there is none) and the call. ``record.py`` feeds rs274 a copy of the program whose
line ``k`` carries the word ``N<k>``, so the ``N`` column is the physical line.

Values are printed with ``%.4f`` in the *program's* units at the time of the call
(``USE_LENGTH_UNITS``); ``canon_to_moves`` converts them to millimetres. The feed rate
is converted with the units in force when ``SET_FEED_RATE`` was called, as LinuxCNC's
motion layer does (a G20/G21 switch does not re-scale an earlier F).
Positions are printed in program coordinates; the offsets in force
(``SET_G5X_OFFSET``, ``SET_G92_OFFSET``, ``USE_TOOL_LENGTH_OFFSET``) and the XY rotation
(``SET_XY_ROTATION``) are applied as LinuxCNC's canon layer does (rotate(p + G92) + G5x +
tool), so the moves are in the machine's work frame (G54 with zero offsets is the work zero).

``ARC_FEED(first_end, second_end, first_axis, second_axis, rotation, axis_end_point,
a, b, c)``: the first/second axes are X/Y in G17, Z/X in G18, Y/Z in G19; ``first_axis``
and ``second_axis`` are the centre; ``rotation`` < 0 is clockwise, its magnitude is
1 + the number of extra full turns; ``axis_end_point`` is the third axis (helix).
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

MM_PER_INCH = 25.4

# "   12 N17    STRAIGHT_FEED(1.0000, ...)" ; N digits are padded to 6, longer ones are not.
_CALL = re.compile(r"^\s*(\d+)\s+N(\d+|\.+)\s*([A-Z_0-9]+)\((.*)\)\s*$")

PLANES = {"CANON_PLANE_XY": "XY", "CANON_PLANE_XZ": "XZ", "CANON_PLANE_YZ": "YZ"}
UNITS = {"CANON_UNITS_MM": 1.0, "CANON_UNITS_INCHES": MM_PER_INCH, "CANON_UNITS_CM": 10.0}


class CanonError(ValueError):
    """A line of canonical output that this reader does not understand."""


@dataclass(frozen=True)
class CanonCall:
    """One canonical call: ``seq`` is rs274's counter, ``line`` the N column (None for N.....)."""

    seq: int
    line: int | None
    name: str
    args: tuple[str, ...]

    def floats(self) -> list[float]:
        return [float(a) for a in self.args]


@dataclass
class CanonRecord:
    """A recorded rs274 run: header fields, the calls, and where it stopped with an error."""

    path: Path | None
    header: dict[str, str] = field(default_factory=dict)
    calls: list[CanonCall] = field(default_factory=list)
    error_line: int | None = None
    error_message: str | None = None

    @property
    def source(self) -> str | None:
        return self.header.get("source")

    @property
    def moves(self) -> list[dict]:
        return canon_to_moves(self.calls)


def split_args(text: str) -> tuple[str, ...]:
    """Arguments of a call: comma separated, except inside a quoted string (COMMENT("a, b"))."""
    text = text.strip()
    if not text:
        return ()
    if text.startswith('"'):
        return (text,)
    return tuple(a.strip() for a in text.split(","))


def parse_call(line: str) -> CanonCall:
    m = _CALL.match(line)
    if not m:
        raise CanonError(f"not a canonical call: {line!r}")
    seq, n, name, args = m.groups()
    return CanonCall(int(seq), int(n) if n[0] != "." else None, name, split_args(args))


def parse_canon_lines(lines: Iterable[str]) -> list[CanonCall]:
    """Parse the stdout of ``rs274 -g``; blank lines are skipped."""
    return [parse_call(line) for line in lines if line.strip()]


def _mm(values: list[float], scale: float) -> list[float]:
    return [v * scale for v in values]


def canon_to_moves(calls: Iterable[CanonCall]) -> list[dict]:
    """Turn canonical calls into moves in the ``cnc-gcode moves`` JSON format, in mm.

    rapid: ``{"line", "kind": "rapid", "end"}``; feed: ``{..., "kind": "feed", "end", "feed"}``;
    arc: ``{..., "kind": "arc", "end", "center", "plane", "turn", "feed"}`` with ``center``
    in the plane's (first, second) axes; dwell: ``{"line", "kind": "dwell", "seconds"}``.
    Every move also carries ``"units"``: the canon units it was printed in ("mm"/"in"),
    which tells the comparison how finely rs274 printed it.
    """
    scale = 1.0
    plane = "XY"
    feed = 0.0
    moves: list[dict] = []
    frame = _Frame()
    for call in calls:
        name = call.name
        unit_name = "in" if scale == MM_PER_INCH else "mm"
        if name in _OFFSET_CALLS:
            setattr(frame, _OFFSET_CALLS[name], _offset_values(call, scale))
        elif name == "SET_XY_ROTATION":
            frame.rotation = float(call.args[0])
        elif name == "USE_LENGTH_UNITS":
            try:
                scale = UNITS[call.args[0]]
            except KeyError:
                raise CanonError(f"unknown units {call.args}") from None
        elif name == "SELECT_PLANE":
            try:
                plane = PLANES[call.args[0]]
            except KeyError:
                raise CanonError(f"unknown plane {call.args}") from None
        elif name == "SET_FEED_RATE":
            feed = float(call.args[0]) * scale
        elif name in ("STRAIGHT_TRAVERSE", "STRAIGHT_FEED"):
            end = frame.point(_mm(call.floats()[:3], scale))
            if name == "STRAIGHT_TRAVERSE":
                moves.append({"line": call.line, "kind": "rapid", "end": end, "units": unit_name})
            else:
                moves.append(
                    {"line": call.line, "kind": "feed", "end": end, "feed": feed, "units": unit_name}
                )
        elif name == "ARC_FEED":
            v = call.floats()
            first_end, second_end, first_axis, second_axis = _mm(v[:4], scale)
            rotation = int(v[4])
            axis_end = v[5] * scale
            if plane == "XY":
                end = [first_end, second_end, axis_end]
                axes = (0, 1)
            elif plane == "XZ":  # first = Z, second = X, third = Y
                end = [second_end, axis_end, first_end]
                axes = (2, 0)
            else:  # YZ: first = Y, second = Z, third = X
                end = [axis_end, first_end, second_end]
                axes = (1, 2)
            centre = list(end)
            centre[axes[0]], centre[axes[1]] = first_axis, second_axis
            end, centre = frame.point(end), frame.point(centre)
            first_axis, second_axis = centre[axes[0]], centre[axes[1]]
            moves.append(
                {
                    "line": call.line,
                    "kind": "arc",
                    "end": end,
                    "center": [first_axis, second_axis],
                    "plane": plane,
                    "turn": rotation,
                    "feed": feed,
                    "units": unit_name,
                }
            )
        elif name == "DWELL":
            moves.append({"line": call.line, "kind": "dwell", "seconds": float(call.args[0])})
        elif name in ("STRAIGHT_PROBE", "RIGID_TAP", "NURBS_FEED", "SPLINE_FEED"):
            raise CanonError(f"motion call {name} is not supported by this reader")
    return moves


_OFFSET_CALLS = {"SET_G5X_OFFSET": "g5x", "SET_G92_OFFSET": "g92", "USE_TOOL_LENGTH_OFFSET": "tool"}


@dataclass
class _Frame:
    """The offsets in force (mm) and the XY rotation (degrees), as rs274 printed them."""

    g5x: list[float] = field(default_factory=lambda: [0.0, 0.0, 0.0])
    g92: list[float] = field(default_factory=lambda: [0.0, 0.0, 0.0])
    tool: list[float] = field(default_factory=lambda: [0.0, 0.0, 0.0])
    rotation: float = 0.0

    def point(self, p: list[float]) -> list[float]:
        """A program point in the machine's work frame: rotate(p + G92) + G5x + tool."""
        x, y, z = (a + b for a, b in zip(p, self.g92, strict=True))
        if self.rotation:
            c, s = math.cos(math.radians(self.rotation)), math.sin(math.radians(self.rotation))
            x, y = x * c - y * s, x * s + y * c
        g5x, tool = self.g5x, self.tool
        return [x + g5x[0] + tool[0], y + g5x[1] + tool[1], z + g5x[2] + tool[2]]


def _offset_values(call: CanonCall, scale: float) -> list[float]:
    """X Y Z of an offset call, in mm (``SET_G5X_OFFSET`` starts with the system number;
    ``USE_TOOL_LENGTH_OFFSET`` prints ``x y z, a b c, u v w``)."""
    if call.name == "SET_G5X_OFFSET":
        values = call.floats()[1:4]
    elif call.name == "USE_TOOL_LENGTH_OFFSET":
        values = [float(v) for v in call.args[0].split()]
    else:
        values = call.floats()[:3]
    return _mm(values, scale)


_COMMENTS = re.compile(r"\([^)]*\)|;.*$")
_AXIS_WORD = re.compile(r"[XYZ@^][+-]?[0-9.#\[]")  # a number, a parameter or an expression; @ ^: polar


def has_axis_word(source_line: str) -> bool:
    """True if the line (comments removed) has an X, Y or Z word."""
    text = _COMMENTS.sub("", source_line).upper().replace(" ", "").replace("\t", "")
    return bool(_AXIS_WORD.search(text))


def drop_axisless_moves(moves: list[dict], source_lines: list[str]) -> list[dict]:
    """Moves without the ones rs274 makes from a G0/G1 block with no axis word.

    LinuxCNC turns a block such as ``G1 F300`` (motion mode and feed, no X/Y/Z) into a
    zero-length ``STRAIGHT_FEED`` to where the tool already is. That moves nothing and is
    not a move of the ``cnc-gcode moves`` format, so it is dropped before comparing. A
    zero-length move that does name an axis (Gcodetools closes each path with one) stays,
    and so does a move of a block without axis words that goes somewhere (G28, G30).
    """
    out = []
    here = None
    for move in moves:
        line = move.get("line")
        if (
            move["kind"] in ("rapid", "feed")
            and line is not None
            and 1 <= line <= len(source_lines)
            and not has_axis_word(source_lines[line - 1])
            and (here is None or all(abs(a - b) < 0.002 for a, b in zip(move["end"], here, strict=True)))
        ):
            continue
        here = move.get("end", here)
        out.append(move)
    return out


def parse_record(text: str, path: Path | None = None) -> CanonRecord:
    """Parse a ``.canon`` file written by ``record.py``.

    Lines starting with ``#`` are the header (``# key: value``); the rest is rs274's stdout.
    """
    rec = CanonRecord(path)
    body: list[str] = []
    for raw in text.splitlines():
        if raw.startswith("#"):
            key, sep, value = raw[1:].strip().partition(":")
            if sep:
                rec.header.setdefault(key.strip(), value.strip())
        else:
            body.append(raw)
    rec.calls = parse_canon_lines(body)
    if "error_line" in rec.header:
        rec.error_line = int(rec.header["error_line"])
        rec.error_message = rec.header.get("error")
    return rec


def read_record(path: str | Path) -> CanonRecord:
    path = Path(path)
    return parse_record(path.read_text(encoding="utf-8"), path)


# --- comparing moves ---------------------------------------------------------------------

TOL_MM = 0.001
# rs274 prints %.4f in the program's units: half a unit of the last digit, in mm
PRINT_STEP = {"mm": 0.00005, "in": 0.00005 * MM_PER_INCH}


def _close(a, b, tol: float) -> bool:
    try:
        return len(a) == len(b) and all(abs(float(x) - float(y)) <= tol for x, y in zip(a, b, strict=True))
    except (TypeError, ValueError):
        return False


def _fmt(v) -> str:
    try:
        return "[" + ", ".join(f"{float(x):.4f}" for x in v) + "]"
    except (TypeError, ValueError):
        return repr(v)


def compare_move(ours: dict, theirs: dict, tol_mm: float = TOL_MM) -> str | None:
    """None if the move ``ours`` (``cnc-gcode moves`` format) matches rs274's ``theirs``
    (from ``canon_to_moves``), else a short description of the first difference.

    Same kind and source line; end points and arc centres within ``tol_mm`` plus rs274's
    print resolution; feed within the same; dwell within 0.0001 s; arcs in the same plane
    and direction (sign of ``turn``; its magnitude too when rs274 gives extra turns).
    """
    kind = theirs["kind"]
    if ours.get("kind") != kind:
        return f"kind {ours.get('kind')!r}, rs274 {kind!r}"
    if ours.get("line") != theirs["line"]:
        return f"line {ours.get('line')}, rs274 {theirs['line']}"
    if kind == "dwell":
        seconds = ours.get("seconds")
        if not isinstance(seconds, int | float) or abs(seconds - theirs["seconds"]) > 0.0001:
            return f"dwell {seconds} s, rs274 {theirs['seconds']} s"
        return None
    tol = tol_mm + PRINT_STEP[theirs["units"]]
    if not _close(ours.get("end"), theirs["end"], tol):
        return f"end {_fmt(ours.get('end'))}, rs274 {_fmt(theirs['end'])}"
    if kind in ("feed", "arc"):
        feed = ours.get("feed")
        if not isinstance(feed, int | float) or abs(feed - theirs["feed"]) > tol:
            return f"feed {feed}, rs274 {theirs['feed']:.4f}"
    if kind == "arc":
        if ours.get("plane") != theirs["plane"]:
            return f"plane {ours.get('plane')}, rs274 {theirs['plane']}"
        if not _close(ours.get("center"), theirs["center"], tol):
            return f"centre {_fmt(ours.get('center'))}, rs274 {_fmt(theirs['center'])}"
        turn = ours.get("turn")
        if not isinstance(turn, int | float) or turn == 0 or (turn < 0) != (theirs["turn"] < 0):
            return f"turn {turn}, rs274 {theirs['turn']}"
        if abs(theirs["turn"]) > 1 and abs(turn) != abs(theirs["turn"]):
            return f"turn {turn}, rs274 {theirs['turn']}"
    return None


def compare_moves(ours: list[dict], theirs: list[dict], limit: int = 8) -> list[str]:
    """Differences between two move lists, move by move (at most ``limit``); [] if equal."""
    problems = []
    for i, (a, b) in enumerate(zip(ours, theirs, strict=False)):
        why = compare_move(a, b)
        if why:
            problems.append(f"move {i} (rs274: source line {b.get('line')}): {why}")
            if len(problems) >= limit:
                return problems
    if len(ours) != len(theirs):
        extra = ours[len(theirs) :] or theirs[len(ours) :]
        who = "ours" if len(ours) > len(theirs) else "rs274's"
        problems.append(f"{len(ours)} moves, rs274 {len(theirs)}; first extra is {who}: {extra[0]}")
    return problems
