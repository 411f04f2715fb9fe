"""Helpers shared by the tests of the scan's parallel paths (helper process, forked child)."""

import re
from pathlib import Path

import numpy as np

from app.gcode import bulk
from app.gcode.source import CHUNK_BYTES

SAMPLES = Path(__file__).resolve().parents[2] / "resources" / "samples"


def big_program() -> bytes:
    """About 3 MB of real Inkscape output (a dozen chunks; the samples without their
    ends), with lines the general path refuses near the end (the part another process
    scans)."""
    lines = [line for p in sorted(SAMPLES.glob("*.ngc")) for line in p.read_bytes().splitlines()
             if not re.match(rb"\s*(%|M0?2\b|M30\b)", line, re.IGNORECASE)]
    text = b"\n".join(lines) + b"\nG21\n"
    copies = text * (3 * CHUNK_BYTES * 4 // len(text) + 1)
    return copies + b"G1 X1 Y2 X3\n(unclosed\nG91.1 G2 X1 I1\n" + text + b"M2\n"


def assert_same_scan(a: bulk.Scan, b: bulk.Scan) -> None:
    """Every column of the two scans is equal."""
    np.testing.assert_array_equal(a.simple, b.simple)
    np.testing.assert_array_equal(a.g, b.g)
    np.testing.assert_array_equal(a.units, b.units)
    np.testing.assert_array_equal(a.deleted, b.deleted)
    for letter in a.values:
        np.testing.assert_array_equal(a.values[letter], b.values[letter])


def reference_load(text: str, **options):
    """``load_text(text, **options)`` through the reference path only: every line lexed and
    interpreted by ``lexer`` + ``interp`` (the scan is run, then no line is left to it)."""
    from unittest import mock

    real = bulk.scan_stream

    def nothing_simple(*args, **kwargs):
        for result, ready in real(*args, **kwargs):
            result.simple[:] = False
            yield result, ready

    with mock.patch.object(bulk, "scan_stream", nothing_simple):
        from app.gcode import load_text

        return load_text(text, **options)
