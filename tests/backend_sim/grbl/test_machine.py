"""The simulated GRBL machine on its own (no host session): the documented behaviour a
driver relies on, checked byte by byte on the simulated clock."""

from __future__ import annotations

import pytest

from backend_sim.grbl.simulator import GrblSimulator


@pytest.fixture
def grbl():
    sim = GrblSimulator()
    port = sim.host_port
    port.timeout = 0
    sim.run_for(0.1)
    assert port.read(port.in_waiting).endswith(b"[MSG:'$H'|'$X' to unlock]\r\n")

    def say(data: bytes, seconds: float = 0.2) -> str:
        port.write(data)
        sim.run_for(seconds)
        return port.read(port.in_waiting).decode()

    sim.say = say
    return sim


def test_locked_until_unlocked_then_gcode_runs(grbl):
    assert grbl.say(b"G0 X1\n") == "error:9\r\n"
    assert grbl.say(b"$X\n") == "[MSG:Caution: Unlocked]\r\nok\r\n"
    assert grbl.say(b"G0 X1\n") == "ok\r\n"


@pytest.mark.parametrize("line, code", [
    (b"G1 X10\n", 22), (b"G5 X1\n", 20), (b"G1 G0 X1 F100\n", 21), (b"G1 X1 X2 F100\n", 25),
    (b"X\n", 2), (b"5\n", 1), (b"$Q\n", 3), (b"G2 X10 Y0 F100\n", 35), (b"G0 X1 Q2\n", 20),
    (b"G1 X1 F100 " + b"0" * 80 + b"\n", 11), (b"$J=X10\n", 16), (b"$110=-5\n", 4),
])
def test_bad_lines_get_grbl_error_numbers(grbl, line, code):
    grbl.say(b"$X\n")
    assert grbl.say(line) == f"error:{code}\r\n"


def test_receive_buffer_holds_128_bytes_and_loses_the_rest(grbl):
    grbl.say(b"$X\n")
    line = b"G1 X10 Y10 F100\n"  # a long move: the planner fills and reading stops
    grbl.host_port.write(line * 40)
    grbl.run_for(1.0)
    assert grbl.machine.overflowed > 0
    assert len(grbl.machine.rx) <= 128


def test_status_report_fields_follow_dollar_10(grbl):
    grbl.say(b"$X\n")
    assert grbl.say(b"?").startswith("<Idle|MPos:")
    assert grbl.say(b"$10=2\n") == "ok\r\n"
    report = grbl.say(b"?")
    assert "|WPos:" in report and "|Bf:15,128" in report


def test_work_offset_from_g10_shows_in_wco(grbl):
    grbl.say(b"$X\n")
    grbl.say(b"G10 L2 P1 X-100 Y-100 Z-20\n")
    report = grbl.say(b"?")
    assert "WCO:-100.000,-100.000,-20.000" in report
    assert "[G54:-100.000,-100.000,-20.000]" in grbl.say(b"$#\n")


def test_safety_door_holds_and_cycle_start_resumes_once_closed(grbl):
    grbl.say(b"$X\n")
    grbl.say(b"G1 X30 F300\n", 1.0)
    assert grbl.say(b"\x84", 1.0).startswith("[MSG:Check Door]")
    held = grbl.say(b"?")
    assert held.startswith("<Door:1") and "Pn:D" in held
    assert grbl.say(b"G0 X1\n") == "error:13\r\n"  # nothing more while the door is open
    grbl.say(b"~", 0.5)
    assert grbl.say(b"?").startswith("<Door:1")  # cycle start does nothing while it is open
    grbl.set_door(False)
    assert grbl.say(b"?").startswith("[MSG:Check Door]\r\n<Door:0")  # closed: ready to resume
    grbl.say(b"~", 0.1)
    assert grbl.say(b"?").startswith("<Run")


def test_soft_limit_jog_is_refused_and_a_move_alarms(grbl):
    grbl.say(b"$H\n", 60.0)
    assert grbl.machine.homed
    assert grbl.say(b"$20=1\n") == "ok\r\n"
    assert grbl.say(b"$J=G91 X-500 F600\n") == "error:15\r\n"
    out = grbl.say(b"G0 X-500\n")
    assert "ALARM:2" in out and "[MSG:Reset to continue]" in out


def test_after_a_hard_limit_nothing_is_read_until_the_reset(grbl):
    grbl.say(b"$X\n")
    grbl.trip_limit("X")
    assert "ALARM:1" in grbl.say(b"", 0.5)
    assert grbl.say(b"$#\n$X\n", 1.0) == ""  # GRBL 1.1 blocks everything but a reset
    out = grbl.say(b"\x18", 0.5)
    assert "Grbl 1.1h" in out and "[G54:" not in out  # the reset emptied its buffer


def test_reset_while_moving_is_alarm_3(grbl):
    grbl.say(b"$X\n")
    grbl.say(b"G1 X20 F300\n", 1.0)
    out = grbl.say(b"\x18", 0.5)
    assert "Grbl 1.1h" in out and "ALARM:3" in out


def test_jog_cancel_flushes_the_jog(grbl):
    grbl.say(b"$X\n")
    assert grbl.say(b"$J=G91 X100 F300\n", 1.0) == "ok\r\n"
    assert grbl.say(b"?").startswith("<Jog")
    grbl.say(b"\x85", 2.0)
    assert grbl.say(b"?").startswith("<Idle")


def test_a_setting_write_is_deaf_until_its_eeprom_write_ends_then_answers(grbl):
    port = grbl.host_port
    port.write(b"$110=500\n")
    grbl.run_for(0.005)  # the line is read: the EEPROM write has begun
    port.write(b"$111=500\n?")  # sent without waiting: lost, as on the real part
    grbl.run_for(0.2)
    assert port.read(port.in_waiting).decode() == "ok\r\n"
    assert grbl.machine.lost_to_eeprom == len(b"$111=500\n?")
    assert grbl.machine.settings[110] == 500 and grbl.machine.settings[111] != 500
    assert grbl.say(b"$111=500\n") == "ok\r\n"


def test_a_reset_brings_the_overrides_back_to_100(grbl):
    grbl.say(b"$X\n")
    grbl.say(bytes([0x91, 0x91, 0x9B]))
    assert grbl.machine.overrides == [120, 100, 90]
    grbl.say(b"\x18")
    assert grbl.machine.overrides == [100, 100, 100]


def test_settings_and_parameters_wait_for_idle_or_alarm_as_grbl_does(grbl):
    grbl.say(b"$X\n")
    assert grbl.say(b"$C\n").endswith("ok\r\n")
    assert grbl.say(b"$#\n") == "error:8\r\n" and grbl.say(b"$1=30\n") == "error:8\r\n"
    assert grbl.say(b"$$\n").endswith("ok\r\n")  # only a cycle or a hold blocks the print-out
    grbl.say(b"$C\n")  # leaving check mode resets
    grbl.say(b"$X\n")
    assert grbl.say(b"G1 X100 F300\n", 0.3) == "ok\r\n"
    assert grbl.say(b"$$\n") == "error:8\r\n" and grbl.say(b"$#\n") == "error:8\r\n"
