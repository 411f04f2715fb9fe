"""Streaming to a GRBL machine: the 1 M-line file (``bench_gcode``'s ``big.ngc``) through
the GRBL simulator at 115200 baud, in check mode (``$C``: every line is parsed and
answered, nothing moves, so the link is what limits), with the sans-IO GRBL session
on the simulator's clock (simulated time: the baud rate and the converter's latency
are simulated byte by byte; the host reads what arrived every 2 ms, as the window's
worker does for GRBL: at 5 ms the share was 94 %).

Printed: lines, bytes, simulated seconds, the character-counting ceiling (the bytes
at 115200 baud, 10 bits a byte: the fastest any sender can go) and the share of it
reached (goal >= 95 %), and the wall time the run took. Then the window streaming
100,000 lines to ``cnc-sim --grbl --pty`` in real time: the GUI's longest stall (goal
<= 50 ms) and the share reached through a real pty. ``BENCH_GRBL="[LINES] [stream|window]"
python -m bench bench_grbl`` limits the lines or runs one part. Figures only.
"""

from __future__ import annotations

import os
import sys
import time

from app.comm.grbl.events import GrblListener
from app.comm.grbl.session import GrblSession
from backend_sim.grbl.simulator import GrblSimulator
from bench.bench_gcode import build

BAUD = 115200
PUMP_S = 0.002  # app.comm.worker.GRBL_PUMP_MS


class _Ends(GrblListener):
    def __init__(self) -> None:
        self.jobs, self.results = [], []

    def on_job_finished(self, event):
        self.jobs.append(event)

    def on_command_done(self, event):
        self.results.append(event)


def stream(lines: list[str]) -> dict:
    sim = GrblSimulator()
    port = sim.host_port
    port.timeout = 0
    ends = _Ends()
    session = GrblSession(None, ends, lambda: sim.clock.now)
    session.attach(port.write)

    def pump(until, limit_s: float) -> bool:
        end = sim.clock.now + limit_s
        while not until():
            if sim.clock.now > end:
                return False
            sim.run_for(PUMP_S)  # the host reads every PUMP_S, as the window's worker does
            if port.in_waiting:
                session.feed(port.read(port.in_waiting))
            else:
                session.tick()
        return True

    pump(lambda: session.state.name == "READY" and not len(session.counter) and not session._queue, 10)
    session.command("$X")
    session.command("$C")
    pump(lambda: session.check_mode and not len(session.counter), 10)
    start_s, wall = sim.clock.now, time.perf_counter()
    session.start_job(lines)
    pump(lambda: bool(ends.jobs), 1e7)
    seconds = sim.clock.now - start_s
    job_bytes = sum(len(line) + 1 for line in lines)
    return {"lines": len(lines), "bytes": job_bytes, "seconds": seconds, "wall": time.perf_counter() - wall,
            "completed": ends.jobs[-1].completed, "overflowed": sim.machine.overflowed}


def main(argv: list[str] | None = None) -> None:
    argv = os.environ.get("BENCH_GRBL", "").split() if argv is None else argv
    limit = next((int(a) for a in argv if a.isdigit()), None)
    if "window" not in argv:
        bench_stream(limit)
    if "stream" not in argv:
        bench_window(limit or 100_000)


def bench_stream(limit: int | None) -> None:
    path, _ = build(far=False)
    from app.gcode import load

    lines = list(load(path).device_lines)
    from app.comm.grbl.dialect import grbl_lines

    lines = [line.text for line in grbl_lines(lines) if line.text][:limit]
    load_avg = os.getloadavg()[0]
    r = stream(lines)
    ceiling = r["bytes"] * 10 / BAUD
    print(f"GRBL stream, check mode, {BAUD} baud: {r['lines']:,} lines, {r['bytes']:,} bytes in "
          f"{r['seconds']:.1f} s simulated; ceiling {ceiling:.1f} s ({r['lines'] / ceiling:,.0f} lines/s); "
          f"share {ceiling / r['seconds']:.1%}; completed {r['completed']}, receive-buffer overflow "
          f"{r['overflowed']} bytes; wall {r['wall']:.1f} s (load average {load_avg:.1f})")


if __name__ == "__main__":
    main()


def _step(ok: bool, what: str) -> None:
    if not ok:
        raise RuntimeError(f"bench_grbl: no {what} from the GRBL simulator")


def bench_window(lines_limit: int = 100_000) -> None:
    """The window streaming bench_ui's 100,000-line job to ``cnc-sim --grbl --pty`` (real
    time, 115200 baud, check mode): the 10 ms timer's lateness (GUI stall, goal <= 50 ms)
    and the lines per second against the baud-rate ceiling."""
    import subprocess
    import tempfile
    from pathlib import Path

    from bench.bench_ui import _describe, _lateness, _wait, _window, job_file

    with tempfile.TemporaryDirectory() as config:
        app, window = _window(Path(config))
        binder = window.binder
        window.open_file(job_file())
        _wait(app, lambda: window.loaded is not None, 120)
        proc = subprocess.Popen([sys.executable, "-m", "backend_sim", "--grbl", "--pty"],
                                stdout=subprocess.PIPE, text=True)
        pty = proc.stdout.readline().split()[-1]
        try:
            window.connection.driver.setCurrentIndex(2)  # GRBL
            window.operator.connect_to(pty)
            _step(_wait(app, lambda: binder.status is not None, 30), "a status report")
            window.link.call("send_command", "$X")
            _step(_wait(app, lambda: binder.status.state == "IDLE", 30), "the unlock")
            window.controls.check_mode.setChecked(True)
            _step(_wait(app, lambda: window.link.worker.session.check_mode, 30), "check mode")
            idle = _lateness(app, 5.0)
            started = time.monotonic()
            window.operator.start()
            trace = os.environ.get("BENCH_UI_TRACE") == "1"  # where the GUI thread was when late
            busy = _lateness(app, 900.0, lambda: binder.last_job_event is not None, trace)
            took = time.monotonic() - started
            event = binder.last_job_event
        finally:
            window.close()
            proc.terminate()
            proc.wait(5)
    lines = window.loaded.program.device_lines
    sent = sum(len(line) + 1 for line in lines) + len("G21 G90 G94 G17\nG4 P0\n")
    ceiling = sent * 10 / BAUD
    print(f"window -> cnc-sim --grbl --pty, check mode: {len(lines):,} lines in {took:.1f} s "
          f"({len(lines) / took:,.0f} lines/s; ceiling {ceiling:.1f} s, share {ceiling / took:.1%}); "
          f"completed {event.completed if event else None}")
    print(f"  10 ms timer lateness while streaming: {_describe(busy)} (goal max <= 50 ms)")
    print(f"  same timer, window idle, 5 s before: {_describe(idle)}; load average {os.getloadavg()[0]:.1f}")
