"""``cnc-gcode feature KIND [options]``: one feature's program on standard output.

Kinds and options as issue 10 lists them; lengths in mm, feeds in mm/min, angles in
degrees. ``--macro fanuc21|fanuc31`` prints the parametric program for that control
instead (``fanuc.py``). A bad parameter is reported on standard error naming the option
and the rule (``--stepover: must be > 0 and <= 100 % (got 120)``), exit status 2.
"""

from __future__ import annotations

import argparse
import sys

from app.i18n import localize
from app.profile import MachineProfile

from . import kinds
from .contour import read_contour
from .cutting import Cutting
from .errors import FeatureError
from .fanuc import DIALECTS, write_fanuc
from .generate import program_moves
from .plain import write_plain

KIND_OPTIONS = {
    "face": ["x", "y", "width", "height"],
    "pocket-rect": ["x", "y", "width", "height", "corner-radius?", "angle?"],
    "pocket-circle": ["x", "y", "diameter"],
    "slot": ["x1", "y1", "x2", "y2", "width"],
    "profile": [],
    "holes-circle": ["x", "y", "diameter", "count", "start-angle?"],
    "holes-row": ["x", "y", "count", "pitch", "angle?"],
}
INTEGER = {"count"}


def _common(parser: argparse.ArgumentParser, profile: MachineProfile) -> None:
    add = parser.add_argument
    add("--macro", choices=DIALECTS, default=None, help="a parametric program for that control")
    add("--tool-diameter", type=float, required=True, metavar="D")
    add("--tool", type=int, default=1, metavar="T")
    add("--top", type=float, default=0.0, metavar="Z", help="stock top (default 0)")
    add("--depth", type=float, required=True, metavar="H", help="total depth below the top, positive")
    add("--stepdown", type=float, default=1.0, metavar="C")
    add("--stepover", type=float, default=40.0, metavar="B", help="percent of the tool diameter (default 40)")
    add("--finish-xy", type=float, default=0.0, metavar="U")
    add("--finish-z", type=float, default=0.0, metavar="W")
    add("--clearance", type=float, default=5.0, metavar="R")
    add("--feed", type=float, default=min(300.0, profile.motion.max_feed_mm_min), metavar="F")
    add("--plunge-feed", type=float, default=100.0)
    add("--rpm", type=float, default=profile.max_spindle_rpm(), metavar="S")
    side = parser.add_mutually_exclusive_group()
    side.add_argument("--climb", dest="climb", action="store_true", default=True)
    side.add_argument("--conventional", dest="climb", action="store_false")


def _parser(profile: MachineProfile) -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="cnc-gcode feature", description="G-code for a machining feature.")
    sub = parser.add_subparsers(dest="kind", required=True)
    for kind, names in KIND_OPTIONS.items():
        p = sub.add_parser(kind)
        for name in names:
            optional = name.endswith("?")
            name = name.rstrip("?")
            p.add_argument(f"--{name}", type=int if name in INTEGER else float,
                           required=not optional, default=0.0 if optional else None)
        if kind == "profile":
            p.add_argument("--contour", required=True, metavar="FILE")
            p.add_argument("--side", required=True, choices=["outside", "inside"])
            p.add_argument("--stock", type=float, default=0.0, metavar="M")
        if kind.startswith("holes"):
            p.add_argument("--peck", type=float, default=0.0, metavar="Q")
            p.add_argument("--dwell", type=float, default=0.0)
        _common(p, profile)
    return parser


def _cutting(args) -> Cutting:
    return Cutting(tool_diameter=args.tool_diameter, depth=args.depth, tool=args.tool, top=args.top,
                   stepdown=args.stepdown, stepover=args.stepover, finish_xy=args.finish_xy,
                   finish_z=args.finish_z, clearance=args.clearance, feed=args.feed,
                   plunge_feed=args.plunge_feed, rpm=args.rpm, climb=args.climb)


def build(args):
    """The feature the parsed ``args`` describe (raises ``FeatureError``)."""
    cut = _cutting(args)
    if args.kind == "face":
        return kinds.Face(args.x, args.y, args.width, args.height, cut)
    if args.kind == "pocket-rect":
        return kinds.PocketRect(args.x, args.y, args.width, args.height, cut, args.corner_radius, args.angle)
    if args.kind == "pocket-circle":
        return kinds.PocketCircle(args.x, args.y, args.diameter, cut)
    if args.kind == "slot":
        return kinds.Slot(args.x1, args.y1, args.x2, args.y2, args.width, cut)
    if args.kind == "profile":
        return kinds.Profile(read_contour(args.contour), args.side, cut, args.stock)
    if args.kind == "holes-circle":
        return kinds.holes_circle(args.x, args.y, args.diameter, args.count, cut, args.start_angle,
                                  args.peck, args.dwell)
    return kinds.holes_row(args.x, args.y, args.count, args.pitch, cut, args.angle, args.peck, args.dwell)


def main(argv: list[str], profile: MachineProfile | None = None) -> int:
    """Print the program of the feature ``argv`` describes; return the exit status."""
    profile = profile or MachineProfile()
    args = _parser(profile).parse_args(argv)
    try:
        feature = build(args)
        moves, title = program_moves([feature], profile), f"cnc-gcode feature {' '.join(argv)}"
        text = write_fanuc(moves, args.macro, title) if args.macro else write_plain(moves, title)
    except FeatureError as exc:
        print(f"cnc-gcode feature: --{exc.field.replace('_', '-')}: {localize(exc.rule)}", file=sys.stderr)

        return 2
    sys.stdout.write(text)
    return 0
