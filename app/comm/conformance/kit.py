"""The state every check shares: the link, the results, and the verbs of judging.

``Kit.check(...)`` records one rule's outcome; ``expect_ok``/``expect_error`` send a
command and judge its answer; ``got(start)`` shows what came back since a reply
index (the periodic statuses left out unless asked for). ``ensure_*`` put the machine
in the state a check needs (idle, check mode on or off, homed), using only the verbs
of docs/protocol.md.
"""

from __future__ import annotations

from collections.abc import Callable

from app.comm.conformance.link import Link
from app.comm.conformance.result import FAIL, PASS, SKIP, Result
from app.comm.conformance.wire import Reply

HOME_TIMEOUT_S = 180.0


class Kit:
    def __init__(self, link: Link, quick: bool = False, cover: Callable[[bool], None] | None = None) -> None:
        self.link, self.quick, self.cover = link, quick, cover
        self.results: list[Result] = []
        self.homed_once = False
        self.expected_losses = 0  # host losses the kit caused on purpose
        self.pace = 1.0  # machine seconds per wall second, as a jog measured it (a simulator may run faster)

    # -- judging ---------------------------------------------------------------------------
    def check(
        self, cid: str, section: str, rule: str, ok: bool, sent: str = "", got: str = "", note: str = ""
    ) -> bool:
        self.results.append(Result(cid, section, rule, PASS if ok else FAIL, sent, got, note))
        return ok

    def skip(self, cid: str, section: str, rule: str, why: str) -> None:
        self.results.append(Result(cid, section, rule, SKIP, note=why))

    def got(self, start: int, statuses: bool = False, limit: int = 8) -> str:
        shown = [
            str(r) for r in self.link.replies[start:] if statuses or r.kind != "S" or r.problem is not None
        ]
        more = f" ... (+{len(shown) - limit})" if len(shown) > limit else ""
        return " | ".join(shown[:limit]) + more if shown else "(nothing)"

    def expect_ok(
        self,
        cid: str,
        section: str,
        rule: str,
        text: str,
        info: Callable[[str], bool] | None = None,
        timeout: float = 5.0,
    ) -> Reply | None:
        """``C <id> text`` must be answered ``O <id> <VERB> [info]`` (``info`` judges the info)."""
        start = len(self.link.replies)
        _, answer = self.link.command(text, timeout)
        verb = text.split()[0]
        ok = (
            answer is not None
            and answer.kind == "O"
            and answer.fields[1] == verb
            and (info is None or info(answer.text))
        )
        self.check(cid, section, rule, ok, f"C <id> {text}", self.got(start))
        return answer if ok else None

    def expect_error(
        self, cid: str, section: str, rule: str, text: str, code: str, timeout: float = 5.0
    ) -> Reply | None:
        """``C <id> text`` must be refused ``E <id> <code> ...``."""
        start = len(self.link.replies)
        _, answer = self.link.command(text, timeout)
        ok = answer is not None and answer.kind == "E" and answer.fields[1] == code
        self.check(cid, section, rule, ok, f"C <id> {text}", self.got(start))
        return answer

    # -- putting the machine in a state -------------------------------------------------
    def status_until(self, match, seconds: float = 1.5):
        """The first status (asked every 0.2 s for up to ``seconds``) that ``match``es,
        else the last one (the main MCU's answer may be a second old: "Machine
        conventions")."""
        deadline = self.link.clock() + seconds
        status = self.link.status()
        while (status is None or not match(status)) and self.link.clock() < deadline:
            self.link.idle(0.2)
            status = self.link.status()
        return status

    def ensure_idle(self) -> None:
        """No job, nothing moving: ``STOP`` unless the status is IDLE with nothing open."""
        status = self.link.status()
        if status is None or status.state != "IDLE" or status.has("S") or status.acc != status.done:
            self.link.command("STOP", 30.0)

    def check_mode(self, on: bool) -> bool:
        _, answer = self.link.command(f"SET CHECK {int(on)}")
        return answer is not None and answer.kind == "O"

    def ensure_homed(self) -> bool:
        status = self.link.status()
        if status is not None and status.has("H"):
            return True
        _, answer = self.link.command("HOME", HOME_TIMEOUT_S)
        self.homed_once = answer is not None and answer.kind == "O"
        return self.homed_once

    def fresh_stretch(self) -> bool:
        """End any bad stretch the machine may be in (its ``N`` is sent once per bad
        stretch, and a stretch ends with the frame it expects): a one-line job in check
        mode. True when the line finished."""
        self.ensure_idle()
        if not self.check_mode(True):
            return False
        _, answer = self.link.command("JOB 1")
        if answer is None or answer.kind != "O":
            return False
        start = len(self.link.replies)
        self.link.send("D 0 G04 P0")
        done = self.link.wait(lambda r: r.kind == "F" and r.int(0) >= 0, 3.0, start)
        self.check_mode(False)
        return done is not None
