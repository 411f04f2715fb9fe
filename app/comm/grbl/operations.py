"""The operator's calls on a GRBL machine besides jobs: jog, overrides, homing, unlock,
check mode, settings and the ``$#``/``$G`` reads. A mixin of ``GrblSession``.

- ``jog(axis, distance, feed)``: ``$J=G91 G21 <axis><distance> F<feed>`` (a jog never
  changes the parser's modes), answered as ``JOG`` as the frame protocol does;
  ``jog_to_limit(axis, direction, feed)`` jogs towards the end of the travel for
  hold-to-jog (needs ``$13x`` and homing, else ``JOG_SPAN_MM``), ``jog_cancel()`` sends
  0x85 (on key release); ``jog_hold(keys, feed)`` is the window's hold-to-jog on both
  (one or two keys; also while the stream waits at a program stop: the touch-off).
- ``set_feed_override(percent)`` / ``set_spindle_override`` send the fewest
  0x90-0x94 / 0x99-0x9D bytes from the value of the last report, within the ranges of
  the session's ``capabilities`` (``driver.Capabilities.override_range``, what the
  window's sliders take);
  ``set_rapid_override(100|50|25)``.
- ``home()`` ``$H`` (answered as ``HOME``); ``unlock_advice()`` says why the machine is locked (say it before
  ``unlock()``, ``$X``); ``set_check_mode(on)`` toggles ``$C``.
- Settings: ``read_settings()`` ``$$``; ``write_setting(n, value)`` send-and-wait;
  ``settings_diff(wanted)`` and ``restore_settings(wanted)`` for a backup file
  (``settings.py``); ``read_offsets()`` ``$#``, ``read_parser_state()`` ``$G``.
"""

from __future__ import annotations

import math

from app.comm.grbl import protocol as p
from app.comm.grbl.codes import unlock_advice
from app.comm.grbl.dialect import axis_range
from app.comm.grbl.settings import SettingChange, diff_settings, format_value, homing_enabled
from app.comm.hold_jog import directions
from app.i18n import msg

JOG_SPAN_MM = 1000.0  # hold-to-jog distance when the travel is unknown


def _override_bytes(current: int, target: int, reset: bytes, tens: tuple[bytes, bytes],
                    ones: tuple[bytes, bytes]) -> bytes:
    """The bytes that take an override from ``current`` % to ``target`` % (the caller keeps
    ``target`` within what the machine takes)."""
    target = int(target)
    if target == current:
        return b""
    start, out = current, b""
    if abs(target - 100) + 1 < abs(target - current):
        start, out = 100, reset
    delta = target - start
    up = delta > 0
    n10, n1 = divmod(abs(delta), 10)
    return out + (tens[0] if up else tens[1]) * n10 + (ones[0] if up else ones[1]) * n1


class GrblOperations:
    """See the module docstring."""

    _held_jog = ""  # the directions of the hold-to-jog under way ("" none)

    # ------------------------------------------------------------------ jog

    def jog(self, axis: str, distance_mm: float, feed_mm_min: float) -> int:
        """Jog one axis by ``distance_mm`` at ``feed_mm_min``; the command id."""
        axis = axis.upper()
        if axis not in ("X", "Y", "Z") or not math.isfinite(distance_mm):
            raise ValueError(msg("jog axis must be X, Y or Z with a finite distance, not {axis} {distance}",
                                 axis=axis, distance=distance_mm))
        if not (math.isfinite(feed_mm_min) and feed_mm_min > 0):
            raise ValueError(msg("jog feed must be above 0 mm/min, not {feed}", feed=feed_mm_min))
        return self.as_verb("JOG", (axis, f"{distance_mm:g}", f"{feed_mm_min:g}"),
                            f"$J=G91 G21 {axis}{distance_mm:.3f} F{feed_mm_min:.0f}")

    def jog_to_limit(self, axis: str, direction: int, feed_mm_min: float) -> int:
        """Hold-to-jog: jog towards the end of the travel (``jog_cancel`` on release)."""
        k = "XYZ".index(axis.upper())
        return self.jog(axis, math.copysign(self._room(k, direction), direction), feed_mm_min)

    def _room(self, k: int, direction: int) -> float:
        """How far axis ``k`` may jog in ``direction`` (see ``jog_to_limit``)."""
        if self.homed and 130 + k in self.settings and self.grbl_status is not None:
            lo, hi = axis_range(self.settings, k)
            here = self.grbl_status.mpos[k]
            return max(0.0, max(0.0, (hi - here) if direction > 0 else (here - lo)) - 0.01)
        return JOG_SPAN_MM

    def jog_hold(self, keys: tuple[str, ...], feed_mm_min: float) -> bool:
        """The keys held now (``()`` on release): a press jogs towards the end of the travel
        along them (``$J=``; two keys the diagonal), a change or release cancels it (0x85).
        False (nothing sent) without a link or during a job, except while its stream waits
        at a program stop (the touch-off, docs/protocol.md "Program stops")."""
        dirs = directions(keys)
        if dirs == self._held_jog:
            return True
        if self._held_jog:
            self._held_jog = ""
            self.jog_cancel()
        at_stop = self.job is not None and self.job.stop_at is not None
        if not dirs or not self.attached or self.busy and not at_stop:
            return not dirs
        signs = {dirs[i]: 1 if dirs[i + 1] == "+" else -1 for i in range(0, len(dirs), 2)}
        room = min(self._room("XYZ".index(axis), sign) for axis, sign in signs.items())
        if room <= 0.0:
            return False
        self._held_jog = dirs
        words = " ".join(f"{axis}{sign * room:.3f}" for axis, sign in signs.items())
        self.as_verb("JOG", (dirs, f"{feed_mm_min:g}"), f"$J=G91 G21 {words} F{feed_mm_min:.0f}")
        return True

    def jog_cancel(self) -> None:
        self._realtime(p.JOG_CANCEL)

    # ------------------------------------------------------------------ overrides

    def set_feed_override(self, percent: int) -> None:
        self._step_override(0, "FEED", percent, p.FEED_100, (p.FEED_PLUS_10, p.FEED_MINUS_10),
                            (p.FEED_PLUS_1, p.FEED_MINUS_1))

    def set_spindle_override(self, percent: int) -> None:
        self._step_override(2, "SPINDLE", percent, p.SPINDLE_100, (p.SPINDLE_PLUS_10, p.SPINDLE_MINUS_10),
                            (p.SPINDLE_PLUS_1, p.SPINDLE_MINUS_1))

    def _step_override(self, index: int, verb: str, percent: int, reset: bytes, tens, ones) -> None:
        """The fewest bytes from what the machine has (or will have, once it reads what was
        sent before: ``ReportMerger.overrides_now``) to ``percent``, kept within the range
        the session's ``capabilities`` give (the one the window's sliders take)."""
        allowed = self.capabilities.override_range(verb)
        target = max(allowed[0], min(allowed[-1], int(percent)))
        data = _override_bytes(self.merger.overrides_now()[index], target, reset, tens, ones)
        if data and self.attached:
            self.merger.expect(index, target)
        for byte in data:
            self._realtime(bytes([byte]))

    def set_rapid_override(self, percent: int) -> None:
        byte = {100: p.RAPID_100, 50: p.RAPID_50, 25: p.RAPID_25}.get(int(percent))
        rates = sorted(self.capabilities.override_range("RAPID"), reverse=True)
        if byte is None or int(percent) not in rates:
            raise ValueError(msg("the machine's rapid override is {allowed} %, not {percent}",
                                 allowed=", ".join(map(str, rates)), percent=percent))
        self._realtime(byte)

    # ------------------------------------------------------------------ machine commands

    def home(self, mode: str = "NORMAL", then=None) -> int:
        """``$H``, answered as ``HOME mode`` (GRBL has one homing cycle: ``mode`` is the
        frame protocol's and changes nothing)."""
        return self.as_verb("HOME", (mode,), "$H", then)

    @property
    def homing_enabled(self) -> bool:
        """The machine has a homing cycle (``$22``); without one it starts unlocked, ``$H``
        is refused (error 5) and nothing waits for a homing."""
        return homing_enabled(self.settings)

    @property
    def position_trusted(self) -> bool:
        """Homed since the last reset, or a machine without homing (nothing to home): the
        status's ``H`` flag, what Start and Start here ask for."""
        return self.homed or not self.homing_enabled

    def unlock_advice(self):
        """Why the machine is locked, to show before ``unlock``."""
        return unlock_advice(self.alarm or None, self.homing_enabled)

    def unlock(self, then=None) -> int:
        return self.command("$X", then=then)

    def set_check_mode(self, on: bool, then=None) -> int | None:
        """``$C`` if check mode is not already ``on`` (None then). Leaving it resets GRBL."""
        if bool(on) == self.check_mode:
            return None
        return self.command("$C", then=then)

    def refresh(self) -> None:
        """Read build info, settings, offsets and parser state (at connect, after a reset)."""
        for text in ("$I", "$$", "$#", "$G"):
            self.command(text)

    # ------------------------------------------------------------------ settings

    def read_settings(self, then=None) -> int:
        return self.command("$$", then=then)

    def read_offsets(self, then=None) -> int:
        return self.command("$#", then=then)

    def read_parser_state(self, then=None) -> int:
        return self.command("$G", then=then)

    def write_setting(self, number: int, value, then=None) -> int:
        """``$n=value`` sent alone and waited for (GRBL writes its EEPROM meanwhile)."""
        return self.command(f"${int(number)}={format_value(value)}", exclusive=True, then=then)

    def settings_diff(self, wanted: dict[int, str]) -> list[SettingChange]:
        return diff_settings(self.settings, wanted)

    def restore_settings(self, wanted: dict[int, str], then=None) -> list[SettingChange]:
        """Write every setting of ``wanted`` that differs, one at a time; ``then`` gets
        each result. Returns the changes (show them first: ``settings_diff``)."""
        changes = self.settings_diff(wanted)
        for change in changes:
            if change.new is not None:
                self.write_setting(change.number, change.new, then=then)
        return changes
