"""Full detail a slice at a time: the whole path drawn into a frame buffer of its own
between frames, so the GUI thread never draws millions of segments at once.

A software renderer draws about ten million short segments a second; a frame of two
million would hold the window for a fifth of a second, and a job's progress redraws
it at the status rate. ``FullFrame`` keeps the picture of the whole path for one
camera, and the POSES before it (a preset or a fit the camera comes back to is shown
at once): ``prepare`` starts it again when no kept picture has this camera, model and
size with less finished (a new run shrinks it), ``overdraw`` draws the segments finished since
the last frame over what is drawn already (O(new segments): progress never redraws
the rest), ``slice`` the next ``slice_segments``, sized so that the renderer takes
about SLICE_S for one (``tune``); ``blit`` copies it to the widget. Until
``complete``, the caller shows a level of detail instead.

What it draws is a ``FullSource``: the whole path as one line strip (units: segments,
``draw(a, b)`` draws segments a+1..b, done up to the finished vertex), or a level of
detail that looks the same at this zoom (units: spans, ``draw(a, b)`` spans a..b-1,
done: the spans ending at or before the finished vertex, a prefix); of either only
the chunks the camera sees (``chunks``), their units counted one run after the other.
"""

from __future__ import annotations

import ctypes
from collections.abc import Callable
from dataclasses import dataclass
from itertools import accumulate

from PySide6.QtCore import QSize
from PySide6.QtOpenGL import QOpenGLFramebufferObject

SLICE_SEGMENTS = 250_000  # the first slice; then sized to SLICE_S
SLICE_S = 0.02  # rendering a slice (the window's stall budget is 50 ms: room for a renderer that slows)
MIN_SLICE, MAX_SLICE = 50_000, 4_000_000
POSES = 3  # pictures kept besides the one shown (the camera comes back to a preset, a fit)
GL_COLOR_BUFFER_BIT, GL_DEPTH_BUFFER_BIT = 0x4000, 0x0100
GL_LINES, GL_LINE_STRIP, GL_UNSIGNED_INT = 0x0001, 0x0003, 0x1405


@dataclass(frozen=True)
class FullSource:
    name: tuple  # ("strip",) or ("level", index): part of the picture's key
    total: int  # units
    done: int  # units finished
    draw: Callable[[int, int], None]  # draw(first, last) with the bound program and buffers

    @classmethod
    def strip(cls, f, runs, done_vertex: int) -> FullSource:
        """The segments of ``runs`` (``chunks.visible_runs``) as line strips."""
        return cls._of_runs(("strip",), runs, done_vertex,
                            lambda first, last: f.glDrawArrays(GL_LINE_STRIP, first, last - first + 1))

    @classmethod
    def spans(cls, draw_elements, level, index: int, runs, done_vertex: int) -> FullSource:
        """``level``'s spans of ``runs`` from its index buffer (bound), drawn by
        ``draw_elements`` (glDrawElements with a byte offset into the bound buffer)."""
        def draw(first: int, last: int) -> None:
            draw_elements(GL_LINES, 2 * (last - first), GL_UNSIGNED_INT, ctypes.c_void_p(8 * first))

        return cls._of_runs(("level", index), runs, level.spans_done(done_vertex), draw)

    @classmethod
    def _of_runs(cls, name: tuple, runs, done: int, draw_units) -> FullSource:
        """Units counted along ``runs`` one after the other (the ones off screen left out)."""
        offsets = list(accumulate((last - first for first, last in runs), initial=0))  # (ints: ctypes)

        def draw(first: int, last: int) -> None:
            for (a, b), at in zip(runs, offsets, strict=False):
                low, high = max(first, at), min(last, at + b - a)
                if high > low:
                    draw_units(a + low - at, a + high - at)

        seen_done = sum(min(max(done - a, 0), b - a) for a, b in runs)
        return cls(name, offsets[-1], seen_done, draw)


class FullFrame:
    def __init__(self, slice_segments: int = SLICE_SEGMENTS):
        self.slice_segments = slice_segments
        self.fbo: QOpenGLFramebufferObject | None = None
        self.key = None
        self.next = 0  # units up to this one are drawn
        self.total = 0  # units of the picture
        self.done = -1  # the finished units drawn so far
        self._kept: list[tuple] = []  # earlier pictures (fbo, key, next, total, done), oldest first

    @property
    def complete(self) -> bool:
        return self.fbo is not None and self.next >= self.total

    def _state(self) -> tuple:
        return self.fbo, self.key, self.next, self.total, self.done

    def prepare(self, f, key, size: QSize, total: int, done: int) -> None:
        """Go on with this picture if a buffer holds (part of) it: the one drawn last, or
        one of the POSES before (the camera came back); else begin it again in the
        buffer used longest ago."""
        if self.fbo is not None and self.fbo.size() != size:
            self.forget()
        if self._holds(self._state(), key, total, done):
            return
        kept = next((p for p in self._kept if self._holds(p, key, total, done)), None)
        if self.key is not None:
            self._kept.append(self._state())
        if kept is not None:
            self._kept.remove(kept)
            self.fbo, self.key, self.next, self.total, self.done = kept
            return
        self.fbo = self._kept.pop(0)[0] if len(self._kept) > POSES else None
        if self.fbo is None:
            self.fbo = QOpenGLFramebufferObject(size, QOpenGLFramebufferObject.Attachment.Depth)
        self.key, self.total, self.next, self.done = key, total, 0, done
        self.fbo.bind()
        f.glClearColor(0.0, 0.0, 0.0, 1.0)
        f.glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT)
        self.fbo.release()

    @staticmethod
    def _holds(picture: tuple, key, total: int, done: int) -> bool:
        fbo, its_key, _, its_total, its_done = picture
        return fbo is not None and its_key == key and its_total == total and done >= its_done

    def overdraw(self, draw, done: int) -> None:
        """``draw(first, last)`` (a ``FullSource``'s) draws the units finished since the last
        call, over what is drawn already (the rest of them is drawn finished by the slices
        to come)."""
        if done > self.done:
            low, high = max(self.done, 0), min(done, self.next)
            if high > low:
                self.fbo.bind()
                draw(low, high)
                self.fbo.release()
            self.done = done

    def slice(self, draw) -> int:
        """Draw the next slice; returns its segments (0 when the picture is whole)."""
        if self.next >= self.total:
            return 0
        end = min(self.next + self.slice_segments, self.total)
        self.fbo.bind()
        draw(self.next, end)
        self.fbo.release()
        sliced, self.next = end - self.next, end
        return sliced

    def tune(self, seconds: float, segments: int) -> None:
        """Size the next slices by how long the renderer took for ``segments``."""
        rate = segments / max(seconds, 1e-4)
        wanted = min(rate * SLICE_S, 2.0 * self.slice_segments)  # grow at most twofold a frame
        self.slice_segments = int(min(MAX_SLICE, max(MIN_SLICE, wanted)))

    def blit(self) -> None:
        """Copy the picture into the frame being drawn (colour only)."""
        QOpenGLFramebufferObject.blitFramebuffer(None, self.fbo)

    def forget(self) -> None:
        self.fbo = None
        self.key = None
        self._kept = []
