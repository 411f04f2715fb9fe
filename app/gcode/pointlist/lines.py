"""Byte-level line tables with numpy: where each line starts and ends, how many
whitespace-separated tokens it holds, whether it is made of number characters only.

The separators of a point list (spaces, tabs, commas, ``\\r``) become spaces and
``#`` comments are blanked first, so a token is a run of anything else.
"""

from __future__ import annotations

import re
import warnings
from dataclasses import dataclass

import numpy as np

from ..limits import MAX_NUMBER

_COMMENT = re.compile(rb"#[^\n]*")
_SEPARATORS = bytes.maketrans(b"\t,\r", b"   ")
_NUMBER_CHARS = np.zeros(256, bool)
_NUMBER_CHARS[list(b"0123456789.+-eE \n")] = True


@dataclass
class LineTable:
    """``data`` (cleaned bytes) and per line: ``start``, ``end`` (exclusive, without the
    newline), ``tokens`` (count) and ``numeric`` (only number characters)."""

    data: bytes
    start: np.ndarray
    end: np.ndarray
    tokens: np.ndarray
    numeric: np.ndarray

    def text(self, k: int) -> str:
        """Line ``k`` (0-based) as text."""
        return self.data[self.start[k]:self.end[k]].decode("utf-8", "replace")

    def numbers(self, first: int, stop: int) -> np.ndarray | None:
        """The floats of lines ``first`` up to ``stop`` (exclusive), or None if one of
        them does not read as a number below the loader's ``MAX_NUMBER`` in size."""
        if stop <= first:
            return np.empty(0)
        chunk = self.data[self.start[first]:self.end[stop - 1]]
        expected = int(self.tokens[first:stop].sum())
        with warnings.catch_warnings():  # older numpy warns and stops at the first bad token
            warnings.simplefilter("ignore")
            try:
                values = np.fromstring(chunk, dtype=np.float64, sep=" ")
            except ValueError:  # newer numpy refuses it
                return None
        if len(values) != expected or not (np.abs(values) < MAX_NUMBER).all():  # NaN too
            return None
        return values


def table(raw: bytes) -> LineTable:
    """The line table of ``raw`` (comments blanked, separators made spaces)."""
    data = raw.translate(_SEPARATORS)
    if b"#" in data:
        data = _COMMENT.sub(lambda m: b" " * len(m.group()), data)
    if not data.endswith(b"\n"):
        data += b"\n"
    b = np.frombuffer(data, np.uint8)
    newline = np.flatnonzero(b == 10)
    start = np.concatenate(([0], newline[:-1] + 1))
    word = (b != 32) & (b != 10)
    begins = np.flatnonzero(word[1:] & ~word[:-1]) + 1
    if len(word) and word[0]:
        begins = np.concatenate(([0], begins))
    tokens = np.bincount(np.searchsorted(newline, begins), minlength=len(newline))
    odd_lines = np.searchsorted(newline, np.flatnonzero(~_NUMBER_CHARS[b]))
    numeric = np.ones(len(newline), bool)
    numeric[odd_lines] = False
    return LineTable(data, start, newline, tokens, numeric)
