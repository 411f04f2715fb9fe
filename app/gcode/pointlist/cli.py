"""``cnc-gcode import FILE [--fit] [--scale S] [--cut-z Z] [--feed F] [--clearance R]``:
the G-code of a point list on standard output, the summary (scale, offset, bounds)
on standard error; a malformed file: its line and what was expected, exit status 1."""

from __future__ import annotations

import argparse
import contextlib
import sys

from app.i18n import localize
from app.profile import MachineProfile

from ..features.errors import FeatureError
from ..reading import SourceError, read_source
from .convert import ImportOptions, to_gcode
from .formats import PointListError, read_points


def main(argv: list[str], profile: MachineProfile | None = None) -> int:
    """Convert the file ``argv`` names; return the exit status."""
    profile = profile or MachineProfile()
    parser = argparse.ArgumentParser(prog="cnc-gcode import", description="G-code from a point list.")
    parser.add_argument("file")
    parser.add_argument("--fit", action="store_true", help="scale and centre X Y into the travel")
    parser.add_argument("--scale", type=float, default=1.0, metavar="S")
    parser.add_argument("--cut-z", type=float, default=None, metavar="Z")
    parser.add_argument("--feed", type=float, default=min(300.0, profile.motion.max_feed_mm_min), metavar="F")
    parser.add_argument("--clearance", type=float, default=5.0, metavar="R")
    args = parser.parse_args(argv)
    try:
        raw = read_source(args.file)
        points = read_points(raw, args.file)
        options = ImportOptions(args.fit, args.scale, args.cut_z, args.feed, args.clearance,
                                profile.max_spindle_rpm())
        text, placement = to_gcode(points, options, profile)
    except SourceError as exc:
        print(f"cnc-gcode import: {localize(exc.args[0])}", file=sys.stderr)
        return 1
    except FeatureError as exc:
        print(f"cnc-gcode import: --{exc.field.replace('_', '-')}: {localize(exc.rule)}", file=sys.stderr)
        return 2
    except PointListError as exc:
        print(f"cnc-gcode import: {exc.localized()}", file=sys.stderr)

        return 1
    print(placement.describe(points, options), file=sys.stderr)
    with contextlib.suppress(BrokenPipeError):
        sys.stdout.write(text)
    return 0
