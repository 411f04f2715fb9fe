"""Seeded soak: >= 100,000 lines in check mode at a 1e-4 per-byte error rate on both hops.

Every byte on each of the four channels (USB and UART, down and up) is dropped,
corrupted, duplicated or followed by a noise byte with a total probability of 1e-4.
The oracle: the CNC MCU executed 0..N-1 once each, in order, byte-identical. The seed
is printed on failure; ``SOAK_SEED`` and ``SOAK_LINES`` override it and the size.
"""

import os
import time

import pytest

from app.comm.listener import SessionListener, SessionState
from tests.comm.simlink import SimLink, assert_oracle, dialect_program

SEED = int(os.environ.get("SOAK_SEED", "20261122"))
LINES = int(os.environ.get("SOAK_LINES", "100000"))
RATE = 1e-4


class Quiet(SessionListener):
    """Keeps only what the soak asserts on (the Recorder would hold every frame)."""

    def __init__(self) -> None:
        self.jobs, self.errors, self.progress = [], [], None

    def on_job_finished(self, event):
        self.jobs.append(event)

    def on_error(self, event):
        self.errors.append(event)

    def on_progress(self, event):
        self.progress = event


@pytest.mark.slow
def test_seeded_soak(tmp_path):
    link = SimLink(seed=SEED, sd_dir=tmp_path)
    quiet = Quiet()
    link.session.listener = quiet
    share = RATE / 4
    link.sim.faults.set_rates(seed=SEED, drop=share, corrupt=share, duplicate=share, noise=share)
    lines = dialect_program(LINES, seed=SEED % 97)
    started, sim_start = time.perf_counter(), link.now
    assert link.session.start_job(lines)
    done = link.run_until(lambda: link.session.state is SessionState.READY, LINES / 50, dt=0.005)
    summary = (f"seed {SEED}: {LINES} lines, {link.now - sim_start:.0f} simulated s, "
               f"{time.perf_counter() - started:.0f} s wall, progress {quiet.progress}, "
               f"faults {link.sim.faults.counts()}, errors {quiet.errors[:3]}")
    print(summary)
    assert done and quiet.jobs and quiet.jobs[-1].completed, summary
    try:
        assert_oracle(link.executed(), lines)
    except AssertionError as exc:
        raise AssertionError(f"{summary}: {exc}") from exc
    assert sum(link.sim.faults.counts()[w].get("rate_corrupt", 0) for w in link.sim.wires) > 0, summary
