"""The kit passes against the simulator: ``cnc-sim --pty`` at speed 1 and 10 (its own
process, a real pty) and ``sim://``; the command line's exit status and reports."""

import json

import pytest

from app.comm.conformance.__main__ import main
from app.comm.conformance.result import FAIL, SKIP
from tests.backend_sim.serial_host import start_sim, stop_sim
from tests.conformance.helpers import sim_port


def run_cli(capsys, *argv):
    code = main(list(argv))
    out = capsys.readouterr().out
    return code, out


# At speed 10 every section; at speed 1 those whose rules run on the wall clock as much
# as on the machine's (the partial-frame timeout, host lost after 3 s, real-time answers).
REAL_TIME = ["--section", "frames", "--section", "link", "--section", "realtime"]


@pytest.mark.slow
@pytest.mark.parametrize("speed,quick", [("1", True), ("10", False)])
def test_passes_against_cnc_sim_on_a_pty(tmp_path, capsys, speed, quick):
    proc, first = start_sim(tmp_path, "--speed", speed)
    try:
        assert first.startswith("PTY "), first
        report = tmp_path / "report.json"
        options = ["--quick", *REAL_TIME] if quick else []
        code, out = run_cli(capsys, first.split()[1], *options, "--report", str(report))
    finally:
        stop_sim(proc)
    assert code == 0, out
    data = json.loads(report.read_text())
    outcomes = {r["id"]: r["outcome"] for r in data["results"]}
    assert FAIL not in outcomes.values()
    if quick:
        assert {r.split(".")[0] for r in outcomes} == {"frames", "link", "realtime"}
    else:
        assert outcomes["cover.interlock"] == SKIP  # no wire command opens the cover of a pty machine
        assert "motion.home" in outcomes and "jog.dead-man" in outcomes


def test_passes_against_sim_url_and_writes_markdown(tmp_path, capsys):
    """At speed 1 (the pty runs above cover the other sections), where a host can hold a
    continuous jog with its keep-alives."""
    report = tmp_path / "report.md"
    url = f"sim://?speed=1&sd={tmp_path / 'sd'}"
    code, out = run_cli(capsys, url, "--section", "cover", "--section", "jog", "--report", str(report))
    assert code == 0, out
    text = report.read_text()
    assert text.startswith("# Conformance of sim://") and "| pass | `frames.crc-check-values` |" in text
    assert "| pass | `cover.open-alarm-and-flag` |" in text  # sim:// opens its cover through the panel
    assert "| pass | `jog.keep-alive` |" in text and "| pass | `jog.change-of-direction` |" in text
    assert " 0 failed" in out


def test_a_failure_exits_non_zero_and_shows_what_was_sent(tmp_path, capsys, monkeypatch):
    from backend_sim import cnc_commands

    monkeypatch.setitem(cnc_commands.HANDLERS, "PAUSE", cnc_commands.HANDLERS["RESUME"])
    code, out = run_cli(capsys, f"sim://?speed=10&sd={tmp_path / 'sd'}", "--section", "commands")
    assert code == 1
    assert "FAIL  commands.pause-at-rest" in out and "sent:     C <id> PAUSE" in out and "doc says:" in out


def test_an_unopenable_port_exits_2(capsys):
    assert main(["/dev/nonexistent-port-xyz"]) == 2
    assert "cannot open" in capsys.readouterr().err


def test_sim_port_helper_runs_a_machine(tmp_path):
    with sim_port(tmp_path) as (sim, port):
        assert sim.running and port.is_open
