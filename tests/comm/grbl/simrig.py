"""A sans-IO GRBL session driven against the simulated GRBL machine on one simulated
clock: no threads, no pty, no wall-clock waits (each ``until`` is bounded in simulated
seconds). The machine is the one of ``backend_sim.grbl``, with its own parser and
planner, so what the session sends is what a GRBL would run."""

from __future__ import annotations

from app.comm.grbl.session import GrblSession
from backend_sim.grbl.simulator import GrblSimulator
from tests.comm.grbl.harness import Recorder

STEP_S = 0.005  # the host reads every 5 ms of simulated time


class SimRig:
    def __init__(self, settings: dict[int, float] | None = None) -> None:
        self.sim = GrblSimulator()
        self.port = self.sim.host_port
        self.port.timeout = 0
        if settings:  # the machine powers up again with them (as after a power cycle)
            self.sim.machine.settings.update(settings)
            self.sim.machine.power_up()
            self.sim.run_for(0.05)
            self.port.read(self.port.in_waiting)  # the session meets it by its reports
        self.rec = Recorder()
        self.session = GrblSession(None, self.rec, lambda: self.sim.clock.now)
        self.session.attach(self.port.write)
        self.until(lambda: self.session.status is not None and not self.session._queue
                   and not len(self.session.counter), what="the connect-time reads")
        self.fresh_report()

    def fresh_report(self) -> None:
        """Run until a status report after this moment has been read."""
        mark = self.session.reports
        self.until(lambda: self.session.reports > mark, what="a status report")

    @property
    def machine(self):
        return self.sim.machine

    def step(self) -> None:
        self.sim.run_for(STEP_S)
        data = self.port.read(self.port.in_waiting)
        if data:
            self.session.feed(data)
        else:
            self.session.tick()

    def until(self, predicate, limit_s: float = 120.0, what: str = "") -> None:
        """Run until ``predicate()``; fails after ``limit_s`` simulated seconds."""
        end = self.sim.clock.now + limit_s
        while not predicate():
            assert self.sim.clock.now < end, f"{what or predicate} not within {limit_s} simulated s"
            self.step()

    def run(self, seconds: float) -> None:
        end = self.sim.clock.now + seconds
        while self.sim.clock.now < end:
            self.step()

    def command(self, text: str):
        """Send ``text`` and run until it is answered; its ``CommandResult``."""
        cid = self.session.command(text)
        found = lambda: [r for r in self.rec.of("on_command_done") if r.id == cid]  # noqa: E731
        self.until(lambda: bool(found()), what=f"the answer to {text}")
        return found()[0]

    def executed_since(self, mark: int) -> list[str]:
        """The G-code lines the machine accepted since ``mark`` (a length of ``executed``),
        without the lines every job adds."""
        return [line for line in self.machine.executed[mark:] if line not in ("G21 G90 G94 G17", "G4 P0")]
