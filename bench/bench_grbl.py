"""Streaming to a GRBL machine: the 1 M-line file (``bench_gcode``'s ``big.ngc``) through
the GRBL simulator at 115200 baud, in check mode (``$C``: every line is parsed and
answered, nothing moves, so the link is what limits), with the sans-IO GRBL session
on the simulator's clock (simulated time: the baud rate and the converter's latency
are simulated byte by byte, the host answers at once).

Printed: lines, bytes, simulated seconds, the character-counting ceiling (the bytes
at 115200 baud, 10 bits a byte: the fastest any sender can go) and the share of it
reached (goal >= 95 %), and the wall time the run took. ``python -m bench bench_grbl
[LINES]`` limits the lines. Figures only; nothing is asserted.
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
            sim.run_until(lambda: port.in_waiting > 0, 0.05)
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
    argv = sys.argv[1:] if argv is None else argv
    limit = int(argv[0]) if argv and argv[0].isdigit() else None
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
