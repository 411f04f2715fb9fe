"""What the console client prints: a ``SessionListener`` that writes the traffic (``> ``
sent, ``< `` received; with ``quiet`` no D/A/F/S frame that checked out), logs, alarms,
link changes with the resend rate of the last minute, progress (at most every 0.5 s,
and the last line) and every hold, stop or alarm the machine explains (``why``) that
this console did not ask for, to ``out``; it keeps the command results, finished jobs,
errors, unanswered program stops and unanswered holds for the console to wait on. It
never raises and never blocks.
"""

from __future__ import annotations

import time

from app.comm.events import FrameEvent, HoldEvent
from app.comm.listener import SessionListener
from app.i18n import localize

QUIET = frozenset("DAFS")


class Printer(SessionListener):
    """Prints traffic, logs, alarms, errors and throttled progress."""

    def __init__(self, out, quiet: bool) -> None:
        self.out, self.quiet = out, quiet
        self.results, self.jobs, self.errors = [], [], []
        self.stops: list = []  # program stops not answered yet
        self.holds: list[HoldEvent] = []  # holds this console did not ask for, not answered yet
        self._last_progress = 0.0

    def on_frame(self, event: FrameEvent):
        if event.kind != "L" and not (self.quiet and event.kind in QUIET and event.ok):
            print(("> " if event.direction == "tx" else "< ") + event.text, file=self.out)

    def on_progress(self, event):
        now = time.monotonic()
        if now - self._last_progress >= 0.5 or event.done + 1 == event.total:
            self._last_progress = now
            print(f"progress {event.kind}: {event.done + 1}/{event.total} done, "
                  f"{event.acked + 1} queued, {event.resends} resends", file=self.out)

    def on_log(self, event):
        print(f"[{event.source} {event.level}] {event.text}", file=self.out)

    def on_alarm(self, event):
        print(f"ALARM {event.code} {event.text}", file=self.out)

    def on_link_changed(self, event):
        health = (f", resends {event.resend_rate:.1%} of {event.sent_last_min} frames in the last minute"
                  if event.sent_last_min else "")
        poor = " (poor quality)" if event.quality_warning else ""
        print(f"link {event.state}{health}{poor}", file=self.out)

    def on_hold(self, event: HoldEvent):
        if not event.why:
            print("machine: running again", file=self.out)
        elif not event.asked:
            what = "HOLDS" if event.state == "HOLD" else f"stopped ({event.state})"
            print(f"machine {what} [{event.why}, {event.source}]: {localize(event.text)}", file=self.out)
            if event.state == "HOLD" and event.why != "PROG":  # a program stop has its own prompt
                self.holds.append(event)

    def on_command_done(self, event):
        self.results.append(event)

    def on_job_finished(self, event):
        self.jobs.append(event)

    def on_error(self, event):
        self.errors.append(event)

    def on_program_stop(self, event):
        self.stops.append(event)
