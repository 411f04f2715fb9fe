"""The first-move probe (``start.py``) of an expanded program reads only the rows it asks
for: the walk interprets its moves in batches no larger (issue 24), so the probe costs
next to nothing beside the expansion itself."""

import pytest

from app.gcode import load_text
from app.gcode.macro import walker

FANUC = """O1
G21 G90 G0 Z5
#1 = 0
WHILE [#1 LT 20000] DO 1
  G65 P9 X[#1 MOD 100] Y[FIX[#1 / 100]]
  #1 = #1 + 1
END 1
M30
O9
G0 X#24 Y#25
G1 Z-1 F300
G0 Z1
M99
"""
LINUXCNC = """o<hole> sub
  G0 X#1 Y#2
  G1 Z-1 F300
  G0 Z1
o<hole> endsub
G21 G90 G0 Z5
#1 = 0
o1 while [#1 LT 20000]
  o<hole> call [#1 MOD 100] [FIX[#1 / 100]]
  #1 = [#1 + 1]
o1 endwhile
M2
"""


@pytest.mark.parametrize("text", [FANUC, LINUXCNC])
def test_the_probe_reads_a_few_rows_of_an_expanded_program(text, monkeypatch):
    rows = []
    run = walker.Walker.run

    def counted(self):
        try:
            run(self)
        finally:
            rows.append(len(self.trace.file) + len(self.batch))

    monkeypatch.setattr(walker.Walker, "run", counted)
    program = load_text(text)
    assert not program.errors and len(program.moves) == 60_001
    whole, *probes = rows
    assert whole > 60_000 and probes  # the program's own reading, then the shifted one
    assert sum(probes) < 1_000
    assert program.start.known_line[2] == text.splitlines().index("G21 G90 G0 Z5") + 1  # Z set first
