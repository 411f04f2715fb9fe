"""An expanded program streams like any other: its device lines are the expansion."""

from app.gcode import load_text
from tests.comm.simlink import SimLink, assert_oracle

PROGRAM = """O0001 (four holes by a macro)
#1 = 0
WHILE [#1 LT 4] DO 1
  G65 P10 X[20 + #1 * 10] Y30
  #1 = #1 + 1
END 1
M30
O0010
G0 X#24 Y#25 Z2
G1 Z-0.5 F200
G0 Z2
M99
"""


def test_an_expanded_program_runs_on_the_simulator_line_for_line(tmp_path):
    program = load_text(PROGRAM)
    assert not program.errors
    lines = program.device_lines
    assert len(lines) == 13 and lines[0].startswith("G00 X20 Y30")
    link = SimLink(seed=2, sd_dir=tmp_path)
    event = link.run_job(lines)
    assert event.completed
    assert_oracle(link.executed(), lines)
    assert set(program.line_map.tolist()) == {4, 7}  # every hole shows the G65 line, then M30
