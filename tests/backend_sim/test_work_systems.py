"""Six work coordinate systems on the machine (docs/protocol.md "Work coordinate systems")."""

from __future__ import annotations

import json

from app.comm.frame import Status
from backend_sim.simulator import Simulator
from tests.backend_sim.conftest import FAST_HOMING
from tests.backend_sim.helpers import Host


def _value(host: Host, name: str) -> float:
    return float(host.ok(f"GET {name}").info.split()[1])


def test_each_system_holds_its_row_and_the_active_one_moves_every_work_position(tmp_path):
    host = Host(Simulator(FAST_HOMING, sd_dir=tmp_path / "sd", seed=1))
    host.home()
    assert _value(host, "WCS") == 54
    host.ok("SET G55_X 40")
    host.ok("SET G55_Y 30.5")
    host.ok("SET G55_Z 10")
    assert _value(host, "G55_Y") == 30.5
    assert _value(host, "OFFSET_X") == 0.0  # G54 still active
    host.ok("SET WCS 55")
    assert [_value(host, f"OFFSET_{a}") for a in "XYZ"] == [40.0, 30.5, 10.0]
    machine = host.sim.cnc.mc.measured_mm
    host.command("STATUS")
    host.wait(lambda f: isinstance(f, Status) and abs(f.x - (machine[0] - 40.0)) < 1e-3
              and abs(f.y - (machine[1] - 30.5)) < 1e-3 and abs(f.z - (machine[2] - 10.0)) < 1e-3)
    host.ok("JOG X 12 600")
    assert host.ok("ZERO X").info.startswith("X12.000 Y30.500 Z10.000")  # G55 row
    assert _value(host, "G55_X") == 12.0 and _value(host, "G54_X") == 0.0


def test_rows_and_the_active_system_survive_reset_and_restart(tmp_path):
    sim = Simulator(FAST_HOMING, sd_dir=tmp_path / "sd", seed=2)
    host = Host(sim)
    host.ok("SET G57_Z -3.25")
    host.ok("SET WCS 57")
    host.ok("RESET")
    sim.run_for(0.1)
    again = Host(Simulator(FAST_HOMING, sd_dir=tmp_path / "sd", seed=3))
    assert _value(again, "WCS") == 57 and _value(again, "OFFSET_Z") == -3.25
    assert again.sim.cnc.offset[2] == -3.25
    saved = json.loads((tmp_path / "sd" / ".flash.json").read_text())
    assert saved["active"] == 57 and saved["offset"][2] == -3.25


def test_a_flash_of_one_offset_reads_as_g54(tmp_path):
    (tmp_path / "sd").mkdir()
    (tmp_path / "sd" / ".flash.json").write_text(json.dumps({"offset": [1, 2, 3]}))
    host = Host(Simulator(FAST_HOMING, sd_dir=tmp_path / "sd", seed=4))
    assert [_value(host, f"G54_{a}") for a in "XYZ"] == [1.0, 2.0, 3.0]
    assert _value(host, "G59_Z") == 20.0  # the profile's default offset


def test_bad_values_and_busy_are_refused(tmp_path):
    host = Host(Simulator(FAST_HOMING, sd_dir=tmp_path / "sd", seed=5))
    assert host.refused("SET WCS 60").code == "BAD_ARGS"
    assert host.refused("SET WCS 54.5").code == "BAD_ARGS"
    assert host.refused("SET G56_X 100001").code == "BAD_ARGS"
    assert host.refused("GET G60_X").code == "BAD_PARAM"
    assert host.refused("SET G54_W 1").code == "BAD_PARAM"
    host.home()
    host.command("JOG X 50 300")
    host.wait(lambda f: isinstance(f, Status) and f.state == "JOG")
    assert host.refused("SET WCS 56").code == "BUSY"
    assert host.refused("SET G54_X 5").code == "BUSY"
    assert _value(host, "WCS") == 54
