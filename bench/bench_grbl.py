"""Streaming to a GRBL machine: the 1 M-line file (``bench_gcode``'s ``big.ngc``) through
the GRBL simulator at 115200 baud, in check mode (``$C``: every line is parsed and
answered, nothing moves, so the link is what limits), with the sans-IO GRBL session
on the simulator's clock (simulated time: the baud rate and the converter's latency
are simulated byte by byte; the host reads what arrived every 2 ms, as the window's
worker does for GRBL: at 5 ms the share was 94 %).

Printed: lines, bytes, simulated seconds, the character-counting ceiling (the bytes
at 115200 baud, 10 bits a byte: the fastest any sender can go) and the share of it
reached (goal >= 95 %), and the wall time the run took. Then the window streaming
100,000 lines to ``cnc-sim --grbl --pty`` in real time (``grbl_window.py``): the GUI's
longest stall (goal <= 50 ms), what explains it, and the share reached through a real pty.
``BENCH_GRBL="[LINES] [stream|window|frame]" python -m bench bench_grbl`` limits the lines
or runs one part; ``frame`` runs the window part with GRBL, then with the mill's own
protocol for comparison. Figures only.
"""

from __future__ import annotations

import os
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
    if "window" not in argv and "frame" not in argv:
        bench_stream(limit)
    if "stream" not in argv:
        from bench.grbl_window import bench_window

        bench_window(limit or 100_000)
        if "frame" in argv:
            bench_window(limit or 100_000, "frame")


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
