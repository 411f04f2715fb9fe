"""``cnc-sim`` options: fault-rate flags, profile errors, exec log through the pty."""

from __future__ import annotations

import serial

from app.comm.frame import Finished
from backend_sim.__main__ import _apply_faults, build_parser, load_profile_for_sim
from backend_sim.simulator import Simulator
from tests.backend_sim.serial_host import SerialHost, start_sim, stop_sim


def test_fault_flags_set_seeded_rates_on_the_chosen_hop(tmp_path):
    args = build_parser().parse_args(
        ["--pty", "--corrupt-rate", "0.01", "--drop-rate", "0.002", "--seed", "4", "--fault-hop", "uart"])
    sim = Simulator(sd_dir=tmp_path, seed=args.seed)
    _apply_faults(sim, args)
    assert sim.wires["uart_down"].faults.rates == {"corrupt": 0.01, "drop": 0.002}
    assert sim.wires["uart_up"].faults.rates == {"corrupt": 0.01, "drop": 0.002}
    assert sim.wires["usb_down"].faults.rates == {}


def test_bad_profile_is_reported_and_its_default_used(tmp_path, capsys):
    bad = tmp_path / "bad.toml"
    bad.write_text("[axis]\nlead_mm = -3\n")
    assert load_profile_for_sim(str(bad)).axis.lead_mm == 8.0  # issue 14: the simulator still starts
    assert "lead_mm" in capsys.readouterr().err


def test_exec_log_through_the_pty(tmp_path):
    log = tmp_path / "exec.log"
    proc, first = start_sim(tmp_path, "--speed", "50", "--exec-log", str(log))
    try:
        port = serial.Serial(first.split()[1], timeout=0.01)
        host = SerialHost(port, 50.0)
        host.ok("SET CHECK 0")
        host.ok("HOME", timeout=60)
        host.ok("JOB 2")
        host.data(0, "G00 Z5")
        host.data(1, "G01 X3 F600")
        host.wait(lambda f: isinstance(f, Finished) and f.seq == 1, timeout=30)
        port.close()
    finally:
        code, _ = stop_sim(proc)
    assert code == 0
    assert log.read_text() == "0\tG00 Z5\n1\tG01 X3 F600\n"


def test_bad_speed_and_rate_are_refused(capsys):
    import pytest

    for argv in (["--pty", "--speed", "0"], ["--pty", "--drop-rate", "2"], ["--speed", "2"]):
        with pytest.raises(SystemExit):
            build_parser().parse_args(argv)
    capsys.readouterr()
