"""The 128x64 SH1106 OLED as a 1-bit numpy framebuffer, written with the 5x7 font.

Contract: ``render(lines)`` draws up to 8 rows of up to 21 characters (6x8 cells) and
returns a (64, 128) bool array; a row starting with ``INVERT`` (``"\\x01"``) is drawn
inverted (the menu cursor). ``read_text(fb)`` reads the rows back through the same
font (unknown cells read as ``?``), so tests check what the operator would see.
"""

from __future__ import annotations

import numpy as np

from backend_sim.font5x7 import CELL_H, CELL_W, GLYPHS

WIDTH, HEIGHT = 128, 64
COLS, ROWS = WIDTH // CELL_W, HEIGHT // CELL_H
INVERT = "\x01"


def _glyph_bitmap(columns: tuple[int, ...]) -> np.ndarray:
    cell = np.zeros((CELL_H, CELL_W), dtype=bool)
    for x, byte in enumerate(columns):
        for y in range(7):
            cell[y, x] = bool(byte >> y & 1)
    return cell


_BITMAPS = {ch: _glyph_bitmap(cols) for ch, cols in GLYPHS.items()}
_BY_BYTES = {bm.tobytes(): ch for ch, bm in _BITMAPS.items()}


def render(lines: list[str]) -> np.ndarray:
    fb = np.zeros((HEIGHT, WIDTH), dtype=bool)
    for row, line in enumerate(lines[:ROWS]):
        inverted = line.startswith(INVERT)
        text = line.lstrip(INVERT)[:COLS]
        top = row * CELL_H
        for col, ch in enumerate(text):
            left = col * CELL_W
            fb[top:top + CELL_H, left:left + CELL_W] = _BITMAPS.get(ch, _BITMAPS["?"])
        if inverted:
            fb[top:top + CELL_H, :] = ~fb[top:top + CELL_H, :]
    return fb


def read_text(fb: np.ndarray) -> list[str]:
    """The text rows of a framebuffer (inverted rows read back as normal text)."""
    rows = []
    for row in range(ROWS):
        band = fb[row * CELL_H:(row + 1) * CELL_H, :]
        if band[:, -1].all():
            band = ~band
        chars = []
        for col in range(COLS):
            cell = np.ascontiguousarray(band[:, col * CELL_W:(col + 1) * CELL_W])
            chars.append(_BY_BYTES.get(cell.tobytes(), "?"))
        rows.append("".join(chars).rstrip())
    return rows
