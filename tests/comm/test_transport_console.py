"""Transports (sim://, loop://) and the console client, end to end on the in-process simulator."""

import pytest
import serial

from app.comm import deframer as dfr
from app.comm import frame as fr
from app.comm.console import main, split_commands
from app.comm.transport import list_ports, open_transport
from backend_sim.protocol_sim import url_options

SAMPLE = "resources/samples/star_passes.ngc"


def test_loop_url_goes_through_pyserial():
    port = open_transport("loop://")
    try:
        wire = fr.encode(fr.Command(1, "PING"))
        assert port.write(wire) == len(wire)
        assert port.read(100) == wire
    finally:
        port.close()


def test_port_list_is_what_the_os_reports():
    assert all(not port.url.startswith("sim://") for port in list_ports())


def test_sim_url_options():
    assert url_options("sim://?speed=20&sd=/tmp/x") == {"speed": "20", "sd": "/tmp/x"}
    assert url_options(None) == {}
    with pytest.raises(serial.SerialException, match="speed"):
        open_transport("sim://?speed=fast")
    with pytest.raises(serial.SerialException, match="nosuch"):
        open_transport("nosuch://x")


def test_app_comm_does_not_import_the_simulator():
    import ast
    from pathlib import Path

    for path in Path("app/comm").glob("*.py"):
        for node in ast.walk(ast.parse(path.read_text())):
            names = [a.name for a in getattr(node, "names", [])] + [getattr(node, "module", None) or ""]
            if isinstance(node, ast.Import | ast.ImportFrom):
                assert not any(n.startswith("backend_sim") for n in names), path


def test_any_pyserial_program_opens_sim_urls(tmp_path):
    import backend_sim.protocol_sim

    serial.protocol_handler_packages.append("backend_sim")
    try:
        port = serial.serial_for_url(f"sim://?speed=5&sd={tmp_path}", timeout=0.5)
        assert isinstance(port, backend_sim.protocol_sim.Serial) and port.sim.clock.speed == 5
        port.write(fr.encode(fr.Command(1, "PING")))
        assert port.readline().startswith(b"S ")
        port.close()
    finally:
        serial.protocol_handler_packages.remove("backend_sim")
    assert not port.sim.running


def test_sim_transport_answers_a_ping(tmp_path):
    port = open_transport(f"sim://?speed=50&sd={tmp_path}")
    try:
        port.write(fr.encode(fr.Command(1, "PING")))
        deframer, got = dfr.Deframer(), []
        while not any(isinstance(f, fr.Status) for f in got):
            got += deframer.feed(port.read(max(1, port.in_waiting)), 0.0)
    finally:
        port.close()
    assert not port.sim.running


def test_bad_port_is_an_exception_not_a_crash():
    with pytest.raises(serial.SerialException):
        open_transport("/dev/does-not-exist-cnc")


def test_split_commands():
    assert split_commands(["home", ",", "run", "a.ngc"]) == [["home"], ["run", "a.ngc"]]
    assert split_commands(["ping,", "status"]) == [["ping"], ["status"]]


def test_console_runs_a_sample_to_the_end(tmp_path, capsys):
    rc = main([f"sim://?speed=500&sd={tmp_path}", "-q", "check", "on", ",", "run", SAMPLE])
    out = capsys.readouterr().out
    assert rc == 0, out
    assert "job completed: 212 lines" in out and "\nstatus IDLE" in out


def test_console_sd_put_list_and_a_bad_file(tmp_path, capsys):
    url = f"sim://?speed=500&sd={tmp_path}"
    assert main([url, "-q", "sd", "put", SAMPLE, "star.nc", ",", "sd", "ls"]) == 0
    out = capsys.readouterr().out
    assert "stored star.nc: 212 lines" in out and "star.nc" in out.split("stored")[-1]
    assert main([url, "run", str(tmp_path / "missing.ngc")]) == 2


def test_console_exits_non_zero_with_the_reason(tmp_path, capsys):
    bad = tmp_path / "bad.ngc"
    bad.write_text("G21 G90\nG1 X10 Y10 F300\nG1 X10.5 Y10\nG1 X300 Y10\nG1 X20 Y10\n")
    rc = main([f"sim://?speed=500&sd={tmp_path}", "-q", "check", "on", ",", "run", str(bad)])
    captured = capsys.readouterr()
    assert rc in (1, 2), captured
    assert "error:" in captured.err


STOPS = "G21 G90\nM3 S3000\nG0 Z5\nG0 X10 Y10\nM0\nG1 X20 F600\nT2 M6\nG1 X30\nM5\nM2\n"


def test_console_answers_program_stops(tmp_path, capsys, monkeypatch):
    job = tmp_path / "stops.ngc"
    job.write_text(STOPS)
    url = f"sim://?speed=500&sd={tmp_path}"
    assert main([url, "-q", "--at-stops", "continue", "run", str(job)]) == 0
    out = capsys.readouterr().out
    assert "program stop at device line 3: M00" in out and "program stop at device line 5: M06 T2" in out
    assert "job completed: 9 lines" in out
    answers = iter(["", "stop"])
    monkeypatch.setattr("builtins.input", lambda prompt="": next(answers))
    assert main([url, "-q", "run", str(job)]) == 1
    captured = capsys.readouterr()
    assert "program stop at device line 5: M06 T2" in captured.out and "error: job failed" in captured.err


def test_console_runs_from_a_line(tmp_path, capsys):
    job = tmp_path / "stops.ngc"
    job.write_text(STOPS)
    url = f"sim://?speed=500&sd={tmp_path}"
    args = ["-q", "--at-stops", "continue", "--from", "8", "check", "on", ",", "run", str(job)]
    assert main([url, *args]) == 0
    out = capsys.readouterr().out
    restoring = "M03 S3000; G00 Z5.000; G00 X20.000 Y10.000 F600"
    assert f"starting at line 8 (device line 6); restoring: {restoring}" in out
    assert "job completed: 9 lines" in out


def test_console_reads_a_relative_first_move_from_where_the_machine_stands(tmp_path, capsys):
    job = tmp_path / "retract.ngc"
    job.write_text("G91 G00 Z-2\n")  # after homing the tool stands at work Z10: Z8, not Z-2
    assert main([f"sim://?speed=500&sd={tmp_path}", "-q", "set", "AFTERJOB", "0", ",", "run", str(job),
                 ",", "status"]) == 0
    out = capsys.readouterr().out
    assert "job completed: 1 lines" in out and "Z8.000" in out.split("status IDLE")[-1], out
