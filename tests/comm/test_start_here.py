"""Start from a line (issue 11): the stream is the restore preamble plus lines k.. of
the job; the machine's executed log shows exactly that, and the part ends where the
full run ends (within 0.01 mm)."""

from __future__ import annotations

from app.comm.modal import restart_preamble
from app.gcode import load_text
from tests.comm.simlink import FAST_HOMING, SimLink

SOURCE = """G21 G90
M3 S2500
G0 Z5
G0 X20 Y20
G1 Z-1 F300
G1 X60 F400
G2 X80 Y40 I0 J20
G1 Y70
G0 Z5
G0 X30 Y60
G1 Z-2 F200
G3 X50 Y80 I20 J0 F350
G1 X20
G0 Z5
M5
M2
"""


def _run(tmp_path, lines: list[str], start: int = 0) -> SimLink:
    link = SimLink(check=False, profile=FAST_HOMING, sd_dir=tmp_path)
    link.home()
    link.command_ok("SET", "AFTERJOB", 0)  # compare where the programs end
    assert link.session.start_job(lines, start)
    assert link.run_until(lambda: link.rec.of("on_job_finished"), 300.0)
    assert link.rec.last("on_job_finished").completed, link.rec.last("on_job_finished")
    assert link.run_until(lambda: link.sim.cnc.mc.state == "IDLE", 5.0)
    assert not link.sim.cnc.job.open  # the machine's job ended with the stream (JOB counted its lines)
    return link


def test_start_here_runs_the_preamble_then_lines_k_on_and_ends_where_the_full_run_ends(tmp_path):
    lines = load_text(SOURCE).device_lines
    full = _run(tmp_path / "full", lines)
    k = next(i for i, line in enumerate(lines) if line.startswith("G00 X30"))  # the second pass
    pre = restart_preamble(lines, k)
    assert pre[0].startswith("M03 S2500") and pre[1].startswith("G00 Z") and "F" in pre[2]
    part = _run(tmp_path / "part", lines, k)
    assert [line for _, line in part.executed()] == pre + lines[k:]
    assert [seq for seq, _ in part.executed()] == list(range(len(pre) + len(lines) - k))
    end_full, end_part = full.sim.cnc.mc.measured_mm, part.sim.cnc.mc.measured_mm
    assert max(abs(a - b) for a, b in zip(end_full, end_part, strict=True)) <= 0.01, (end_full, end_part)
    progress = part.rec.of("on_progress")[-1]
    assert progress.done == len(lines) - 1 and progress.total == len(lines)


def test_start_outside_the_program_is_refused(tmp_path):
    link = SimLink(check=True, sd_dir=tmp_path)
    assert not link.session.start_job(["G00 X1"], 5)
    assert link.rec.last("on_error").code == "BAD_START"
