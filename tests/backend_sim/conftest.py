"""Fixtures of the simulator tests: a fresh simulator on a temporary SD card, and a host."""

from __future__ import annotations

import pytest

from app.profile import MachineProfile, with_overrides
from backend_sim.simulator import Simulator
from tests.backend_sim.helpers import Host

FAST_HOMING = with_overrides(MachineProfile(), {"motion": {"homing_mm_min": 900}})


@pytest.fixture
def sim(tmp_path):
    """A simulator on a temporary SD card; homing at 900 mm/min keeps the tests short."""
    simulator = Simulator(FAST_HOMING, sd_dir=tmp_path / "sd", seed=1)
    yield simulator
    simulator.stop()


@pytest.fixture
def host(sim):
    """A host that has said hello (the main MCU relays nothing before the first frame)."""
    h = Host(sim)
    h.send("C 999999 PING")
    h.wait(lambda f: f.KIND == "S")
    return h
