"""The OLED pages and the button menu of the main MCU, usable with no host at all.

Pages (explicit ``Page`` enum): STATUS (state, flags, X/Y/Z, measured spindle rpm, PID
gains, links, notice), MENU (Run SD file, Pause, Resume, Stop, Home, Overrides),
FILES (the SD card; OK runs the file), OVERRIDES (``menu_overrides.py``). UP/DOWN move
the cursor, OK selects, EXIT goes back. Two screens take over the STATUS page: COVER
OPEN (close to continue) while the cover is open, and PROGRAM STOP / TOOL CHANGE while
a job holds at ``M00``/``M01``/``M06`` (OK continues with ``RESUME``, EXIT stops the
job). ``lines()`` gives the 8 text rows the OLED shows now; the cursor row starts with
``oled.INVERT``.
"""

from __future__ import annotations

import enum

from app.comm.frame import Error, Frame
from backend_sim import main_sd
from backend_sim.menu_overrides import OverridesPage
from backend_sim.oled import INVERT, ROWS
from backend_sim.sd_card import SdError

BUTTONS = ("UP", "DOWN", "OK", "EXIT")


class Page(enum.Enum):
    STATUS = "status"
    MENU = "menu"
    FILES = "files"
    OVERRIDES = "overrides"


class Menu:
    ITEMS = ("Run SD file", "Pause", "Resume", "Stop", "Home", "Overrides")

    def __init__(self, main, cnc) -> None:
        self.main, self.cnc = main, cnc
        self.reset()

    def reset(self) -> None:
        self.page = Page.STATUS
        self.cursor = 0
        self.files: list[str] = []
        self.overrides = OverridesPage(self.main, self.cnc)

    # ------------------------------------------------------------------ buttons

    def press(self, button: str) -> None:
        if self.page is Page.STATUS and self._waiting() is not None and button in ("OK", "EXIT"):
            self._command("RESUME" if button == "OK" else "STOP")
            return
        if self.page is Page.OVERRIDES:
            if not self.overrides.press(button):
                self._back_to_menu()
            return
        _PRESS[self.page][button](self)

    def _waiting(self):
        """The program stop the job holds at (a parsed move), else None."""
        return self.cnc.mc.waiting

    def _enter_menu(self) -> None:
        self.page, self.cursor = Page.MENU, 0

    def _back_to_status(self) -> None:
        self.page, self.cursor = Page.STATUS, 0

    def _back_to_menu(self) -> None:
        self.page, self.cursor = Page.MENU, 0

    def _nothing(self) -> None:
        pass

    def _up(self) -> None:
        self.cursor = max(0, self.cursor - 1)

    def _down(self) -> None:
        self.cursor = min(max(0, len(self._items()) - 1), self.cursor + 1)

    def _select(self) -> None:
        if self.page is Page.MENU:
            _ACTIONS[self.ITEMS[self.cursor]](self)
        elif self.files:
            self._run_file(self.files[self.cursor])

    def _items(self) -> list[str]:
        return list(self.ITEMS) if self.page is Page.MENU else self.files

    # ------------------------------------------------------------------ actions

    def _show_files(self) -> None:
        self.files = self.main.sd.names()
        self.page, self.cursor = Page.FILES, 0

    def _run_file(self, name: str) -> None:
        try:
            main_sd.start_job(self.main, name, self._answered)
        except SdError as exc:
            self.main.notice = exc.code
        self._back_to_status()

    def _command(self, verb: str, *args: str) -> None:
        if verb == "STOP":
            main_sd.stop_job(self.main, "stopped on the panel")
        self.main.send_cnc_own(verb, *args, callback=self._answered)
        self.main.notice = verb
        self._back_to_status()

    def _answered(self, frame: Frame) -> None:
        if isinstance(frame, Error):
            self.main.notice = frame.code
        else:
            self.main.notice = f"{frame.verb} ok"

    # ------------------------------------------------------------------ drawing

    def lines(self) -> list[str]:
        if self.page is Page.STATUS:
            if self.cnc.cover_open:
                return ["COVER OPEN", "", "close the cover", "to continue", "", "spindle stopped",
                        "", self.main.notice[:21]]
            waiting = self._waiting()
            if waiting is not None:
                return self._stop_lines(waiting)
            return self._status_lines()
        if self.page is Page.OVERRIDES:
            return self.overrides.lines()
        title = "MENU" if self.page is Page.MENU else "SD FILES"
        items = self._items() or ["(empty)"]
        top = max(0, self.cursor - (ROWS - 2))
        rows = [title]
        for i, item in enumerate(items[top:top + ROWS - 1], start=top):
            rows.append((INVERT if i == self.cursor else "") + " " + item)
        return rows

    def _status_lines(self) -> list[str]:
        main = self.main
        s = main.merged_status()
        kp, ki, kd = (self.cnc.mc.get_param(f"{g}_X") for g in ("KP", "KI", "KD"))
        link = f"HOST {'LOST' if main.host_lost else 'OK' if main.host_connected else '--'}"
        link += f" UART {'LOST' if main.uart_lost else 'OK'}"
        return [
            f"{s.state:<7}{s.flags or '-':<6}{s.boot[-8:]:>8}",
            f"X {s.x:10.3f}",
            f"Y {s.y:10.3f}",
            f"Z {s.z:10.3f}",
            f"S{s.rpm} P{kp:g} I{ki:g} D{kd:g}"[:21],
            link,
            self._job_line(),
            main.notice[:21],
        ]

    def _stop_lines(self, waiting) -> list[str]:
        tool = waiting.source.startswith(("M06", "M6"))
        title = "TOOL CHANGE" if tool else "PROGRAM STOP"
        what = (f"fit tool T{waiting.tool}" if waiting.tool >= 0 else "fit the next tool") if tool else ""
        return [title, f"line {waiting.stop_of}: {waiting.source}"[:21], what, "",
                "OK   continue", "EXIT stop job", self._job_line(), self.main.notice[:21]]

    def _job_line(self) -> str:
        job = self.main.sd_job
        if job is None:
            return "OK: menu"
        return f"SD {job.name[:12]} {job.progress * 100:3.0f}%"


_PRESS = {
    Page.STATUS: {"UP": Menu._nothing, "DOWN": Menu._nothing, "OK": Menu._enter_menu,
                  "EXIT": Menu._nothing},
    Page.MENU: {"UP": Menu._up, "DOWN": Menu._down, "OK": Menu._select, "EXIT": Menu._back_to_status},
    Page.FILES: {"UP": Menu._up, "DOWN": Menu._down, "OK": Menu._select, "EXIT": Menu._back_to_menu},
}

_ACTIONS = {
    "Run SD file": Menu._show_files,
    "Pause": lambda m: m._command("PAUSE"),
    "Resume": lambda m: m._command("RESUME"),
    "Stop": lambda m: m._command("STOP"),
    "Home": lambda m: m._command("HOME", "NORMAL"),
    "Overrides": lambda m: setattr(m, "page", Page.OVERRIDES),
}
