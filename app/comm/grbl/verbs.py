"""The frame protocol's machine commands on a GRBL machine, so the window and the console
can send the same words to either driver (a mixin of ``GrblSession``).

``send_command(text)``: ``SPINDLE <rpm>`` / ``SPINDLE OFF`` -> ``M3 S<rpm>`` / ``M5``;
``ZERO X Y Z`` (any of them) -> ``G10 L20 P<n> X0 ..`` (work zero here, in the active
system ``$G`` names), answered with the new zero once a report carries it;
the work systems as the frame protocol names them (docs/protocol.md "Work coordinate
systems"): ``GET WCS`` reads ``$#`` and ``$G`` and answers ``WCS 54``..``59``; ``GET
G55_X`` answers from the last ``$#``; ``SET WCS 55`` sends ``G55``, ``SET G55_X v`` sends
``G21 G10 L2 P2 X..`` and reads ``$#`` again (both answered once a report has come after:
its ``WCO`` is the new one). Their values are machine millimetres from the near end of
GRBL's travel, as ``GET OFFSET_X`` (below);
``SET CHECK 1|0`` -> ``$C`` when the mode differs; ``SET OPTSTOP 1|0`` is the host's own
switch; ``GET OFFSET_X|Y|Z`` is answered from the live ``WCO``, as machine millimetres
from the near end of GRBL's travel (the frame protocol's machine frame), once ``$$`` and a
report have come; ``HOME``
``$H``; ``JOG X 10 300`` a ``$J=`` jog; ``STATUS``/``PING`` answered by the next report;
other ``SET``/``GET`` and the SD verbs are refused with ``UNSUPPORTED`` (no such thing on
GRBL). Any other line goes to the machine as it is (``G0 X10``, ``$$``, ``$H``; a write
of GRBL's EEPROM, ``$n=``, ``$Nn=``, ``$RST=``, alone and waited for), but
``?``: the operator's own status query goes as the real-time byte it is, and the next
report answers it (shown in the console as kind "report", where the polls' "<" are not).
"""

from __future__ import annotations

import re

from app.comm.events import CommandResult, FrameEvent, JobEvent
from app.comm.grbl import protocol as p
from app.comm.grbl.dialect import axis_range
from app.i18n import msg

_AXES = ("X", "Y", "Z")
_ROW = re.compile(r"G(5[4-9])_([XYZ])")
_SYSTEMS = tuple(f"G{n}" for n in range(54, 60))
_EEPROM_WRITE = re.compile(r"\$(\d+|N\d+|RST)=", re.IGNORECASE)  # sent alone, waited for


class FrameVerbs:
    """See the module docstring."""

    def send_command(self, text: str) -> int | None:
        """A line typed by the operator or a frame-protocol verb (see the module); None if empty."""
        words = text.strip().split()
        if not words:
            return None
        if words == ["?"]:
            return self.ask_report()
        handler = getattr(self, f"_verb_{words[0].lower()}", None)
        if handler is None or not (words[0].isalpha() and words[0].isupper()):
            return self.command(text, exclusive=_EEPROM_WRITE.match(text.strip()) is not None)
        return handler(words[0].upper(), [w.upper() for w in words[1:]])

    def ask_report(self) -> int:
        """The operator's ``?``: answered (``info`` and ``rows``: the report's text) by the next
        status report, which the console shows (kind "report")."""
        if not self.attached:
            return self._local("?", (), False, msg("the machine is not connected"), "LINK_LOST")
        cid = self._reserve_id()
        self._asked_reports.append(cid)
        self.listener.on_frame(FrameEvent("tx", "command", "?"))
        self._realtime(p.STATUS_QUERY, quiet=True)
        return cid

    def answer_asked_reports(self, text: str) -> None:
        asked, self._asked_reports = self._asked_reports, []
        for cid in asked:
            self._command_done(CommandResult(cid, "?", (), True, text, rows=(text,)))

    def _local(self, verb: str, args, ok: bool = True, info: str = "", code: str = "") -> int:
        cid = self._reserve_id()
        self._command_done(CommandResult(cid, verb, tuple(args), ok, info, code))
        return cid

    def _unsupported(self, verb: str, args) -> int:
        what = " ".join([verb, *args])
        return self._local(verb, args, False, msg("a GRBL machine has no {what}", what=what), "UNSUPPORTED")

    def as_verb(self, verb: str, args, text: str, then=None) -> int:
        """Send the GRBL line ``text`` and answer it as the frame protocol's ``verb args``
        (what the window waits for), with the line's own outcome."""
        cid = self._reserve_id()
        args = tuple(str(a) for a in args)

        def answered(result) -> None:
            mine = CommandResult(cid, verb, args, result.ok, result.info, result.code, result.rows)
            self._command_done(mine)
            if then is not None:
                then(mine)

        self.command(text, then=answered)
        return cid

    def _verb_spindle(self, verb: str, args) -> int:
        if not args or args[0] == "OFF":
            return self.as_verb(verb, args, "M5")
        return self.as_verb(verb, args, f"M3 S{float(args[0]):g}")

    def _verb_zero(self, verb: str, args) -> int:
        """``G10 L20 P1`` here; answered (as the frame protocol does, with the new work zero
        ``X.. Y.. Z..`` in machine millimetres) once a report after it carries the new WCO."""
        axes = "".join(args) or "XYZ"
        words = " ".join(f"{a}0" for a in _AXES if a in axes)
        cid = self._reserve_id()
        after: list = []

        def written(result) -> None:
            if not result.ok:
                self._deferred = [d for d in self._deferred if d[0] != cid]
                self._command_done(CommandResult(cid, verb, tuple(args), False, result.info, result.code))
            else:
                after.append(self.reports)

        self._deferred.append((cid, verb, tuple(args), lambda: self._work_zero_text() if after and
                               self.reports > after[0] else None))
        self.command(f"G10 L20 P{self.active_system() - 53} {words}", then=written)
        return cid

    def _verb_home(self, verb: str, args) -> int:
        return self.home(*args[:1])

    def _verb_jog(self, verb: str, args) -> int:
        return self.jog(args[0], float(args[1]), float(args[2]))

    def _verb_status(self, verb: str, args) -> int:
        return self._local(verb, args, info=self.status.state if self.status else "")

    _verb_ping = _verb_status

    def _verb_set(self, verb: str, args) -> int:
        if args[:1] == ["CHECK"] and len(args) > 1:
            cid = self.set_check_mode(args[1] not in ("0", "OFF"))
            return cid if cid is not None else self._local(verb, args, info=f"CHECK {args[1]}")
        if args[:1] == ["OPTSTOP"] and len(args) > 1:
            self.optional_stop = args[1] not in ("0", "OFF")
            return self._local(verb, args, info=f"OPTSTOP {int(self.optional_stop)}")
        if args[:1] == ["WCS"] and args[1:2] and args[1] in {s[1:] for s in _SYSTEMS}:
            return self._chain(verb, args, [f"G{args[1]}", "$G"], lambda: f"WCS {self.active_system()}")
        row = _ROW.fullmatch(args[0]) if len(args) == 2 else None
        if row is not None:
            return self._set_row(verb, args, int(row[1]), "XYZ".index(row[2]))
        return self._unsupported(verb, args)

    def _set_row(self, verb: str, args, system: int, k: int) -> int:
        try:
            value = float(args[1])
        except ValueError:
            value = float("nan")
        if not (abs(value) < 1e6) or 130 + k not in self.settings:
            return self._local(verb, args, False, msg("{name}: {value} is not a work offset in millimetres",
                                                      name=args[0], value=args[1]), "BAD_ARGS")
        grbl = value + axis_range(self.settings, k)[0]
        line = f"G21 G10 L2 P{system - 53} {_AXES[k]}{grbl:.3f}"
        return self._chain(verb, args, [line, "$#"], lambda: self._row_text(args[0], system, k))

    def _verb_get(self, verb: str, args) -> int:
        """``GET OFFSET_X|Y|Z``: answered once the machine has reported its travel ($$) and a
        WCO; ``GET WCS`` and ``GET G5x_A`` (see the module); anything else is not on GRBL."""
        name = args[0] if args else ""
        if name == "WCS":  # a firmware without $# (error 3) has no work systems to show
            return self._chain(verb, args, ["$#", "$G"], lambda: f"WCS {self.active_system()}",
                               unknown=("error:3",))
        row = _ROW.fullmatch(name)
        if row is not None:
            system, k = int(row[1]), "XYZ".index(row[2])
            return self._deferred_answer(verb, args, lambda: self._row_text(name, system, k))
        if name not in ("OFFSET_X", "OFFSET_Y", "OFFSET_Z"):
            return self._unsupported(verb, args)
        k = "XYZ".index(name[-1])
        return self._deferred_answer(verb, args, lambda: f"{name} {self._work_zero()[k]:.3f}"
                                     if self._work_zero() is not None else None)

    def _deferred_answer(self, verb: str, args, answer) -> int:
        """A local command answered (``answer()`` not None) once the machine has reported it."""
        cid = self._reserve_id()
        self._deferred.append((cid, verb, tuple(args), answer))
        self.answer_deferred()
        return cid

    def _chain(self, verb: str, args, lines: list[str], answer, unknown: tuple[str, ...] = ()) -> int:
        """Send ``lines`` one after the other (each once the one before is answered ok), then
        answer ``verb args`` with ``answer()`` once a report has come after the last: a
        failed line ends it with that line's refusal (``UNSUPPORTED`` for a code of
        ``unknown``: the machine has no such thing, rather than not now)."""
        cid = self._reserve_id()
        args = tuple(args)

        def send(index: int) -> None:
            def answered(result) -> None:
                if not result.ok:
                    code = "UNSUPPORTED" if result.code in unknown else result.code
                    self._command_done(CommandResult(cid, verb, args, False, result.info, code))
                elif index + 1 < len(lines):
                    send(index + 1)
                else:
                    mark = self.reports
                    fresh = lambda: answer() if self.reports > mark else None  # noqa: E731
                    self._deferred.append((cid, verb, args, fresh))
                    self.answer_deferred()

            self.command(lines[index], then=answered)

        send(0)
        return cid

    def active_system(self) -> int:
        """The work system in force (54..59) as the last ``$G`` said; 54 before one."""
        words = self.parser_state.split()
        return next((int(w[1:]) for w in words if w in _SYSTEMS), 54)

    def system_offset(self, system: int):
        """The zero of ``G<system>`` from the last ``$#``, in millimetres from the near end of
        GRBL's travel (as ``_work_zero``), or None before ``$#`` and ``$$``."""
        values = self.parameter_mm(f"G{system}")
        if values is None or len(values) < 3 or any(130 + k not in self.settings for k in range(3)):
            return None
        return tuple(v - axis_range(self.settings, k)[0] for k, v in enumerate(values[:3]))

    def parameter_mm(self, name: str) -> tuple[float, ...] | None:
        """The values of ``$#``'s ``[name:x,y,z]`` (``G54``..``G59``, ``G92``, ``TLO``) in
        millimetres (``$13=1`` prints inches), or None before ``$#`` or if unreadable."""
        text = self.parameters.get(name)
        if text is None:
            return None
        try:
            values = [float(v) for v in text.split(":")[0].split(",")]
        except ValueError:
            return None
        scale = 25.4 if self.settings.get(13) == "1" else 1.0
        return tuple(v * scale for v in values)

    def _row_text(self, name: str, system: int, k: int):
        offset = self.system_offset(system)
        return None if offset is None or len(offset) <= k else f"{name} {offset[k]:.3f}"

    def _work_zero(self):
        """The work zero in millimetres from the near end of GRBL's travel (the frame
        protocol's machine frame), or None before ``$$`` and a report."""
        if self.grbl_status is None or any(130 + k not in self.settings for k in range(3)):
            return None
        return tuple(self.grbl_status.wco[k] - axis_range(self.settings, k)[0] for k in range(3))

    def _work_zero_text(self):
        zero = self._work_zero()
        return None if zero is None else " ".join(f"{a}{v:.3f}" for a, v in zip(_AXES, zero, strict=True))

    def answer_deferred(self) -> None:
        """Answer the local commands that were waiting for what the machine reports."""
        for item in list(self._deferred):
            cid, verb, args, answer = item
            info = answer()
            if info is not None:
                self._deferred.remove(item)
                self._command_done(CommandResult(cid, verb, args, True, info))

    def _reserve_id(self) -> int:
        cid = self._next_id
        self._next_id += 1
        return cid

    def _verb_sd(self, verb: str, args) -> int:
        return self._unsupported(verb, args)

    # ------------------------------------------------------------------ the SD calls

    def list_sd(self) -> int:
        return self._unsupported("SD", ["LIST"])

    def delete_sd(self, name: str) -> int:
        return self._unsupported("SD", ["DEL", name])

    def run_from_sd(self, name: str) -> int:
        return self._unsupported("SD", ["RUN", name])

    def upload_to_sd(self, name: str, lines) -> bool:
        self._error("UNSUPPORTED", msg("a GRBL machine has no SD card"))
        self.listener.on_job_finished(JobEvent("upload", False, msg("a GRBL machine has no SD card"), -1, 0,
                                               name))
        return False

    def resume_after_reconnect(self) -> bool:
        """GRBL cannot resume exactly: the offer is always a restart (``confirm_restart``)."""
        self._error("REFUSED", msg("GRBL cannot resume exactly: start again at the offered line"))
        return False
