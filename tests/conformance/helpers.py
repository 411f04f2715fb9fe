"""A simulated machine behind a ``sim://`` port for the kit's tests, patched or not."""

from __future__ import annotations

import contextlib

import serial

from app.comm.conformance.__main__ import open_port
from app.comm.conformance.result import FAIL
from app.comm.conformance.runner import run
from backend_sim.simulator import Simulator
from tests.backend_sim.conftest import FAST_HOMING

SPEED = 10.0


@contextlib.contextmanager
def sim_port(tmp_path, patch=None):
    """A started simulator (``patch(sim)`` applied first) and a ``sim://`` port on it."""
    sim = Simulator(FAST_HOMING, sd_dir=tmp_path / "sd", seed=7)
    if patch is not None:
        patch(sim)
    sim.start(SPEED)
    open_port("loop://").close()  # registers the handler package, as the kit's CLI does
    port = serial.serial_for_url("sim://", do_not_open=True)
    port.simulator = sim
    port.open()
    port.timeout = 0.01
    try:
        yield sim, port
    finally:
        port.close()
        sim.stop()


def failures(tmp_path, sections, patch=None, quick=True) -> dict:
    """Run the kit's ``sections`` against a (patched) simulator: {check id: result} of the failures."""
    with sim_port(tmp_path, patch) as (sim, port):
        results = run(port, quick=quick, sections=sections, cover=sim.panel.set_cover)
    return {r.id: r for r in results if r.outcome == FAIL}
