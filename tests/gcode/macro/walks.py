"""Two walks of one program compared: a shortcut of the walker (leaf calls, compiled loops,
plain chunks) against the walk it stands for, with the shortcut switched off by
``monkeypatch`` settings. Shared by ``test_leaf``, ``test_loop`` and ``test_plain_chunks``."""

import numpy as np

from app.gcode import load_text
from app.gcode.macro import walker

# A grid of holes, each a G65 call of a subprogram of plain moves (as bench_macro's)
FANUC_GRID = """O1000
G21 G90 G17
#100 = 0
WHILE [#100 LT 4] DO 1
  #101 = 0
  WHILE [#101 LT 5] DO 2
    G65 P9010 X[#101 * 2] Y[#100 * 0.25] Z-0.5 F300
    #101 = #101 + 1
  END 2
  #100 = #100 + 1
END 1
M30
O9010
G0 X#24 Y#25

G1 Z#26 F#9
G0 Z1
M99
"""


def walk(text: str, monkeypatch, switched_off: tuple = ()):
    """(the program, the work each expansion of it spent) with each (module, name, value)
    of ``switched_off`` set for the load."""
    spent = []
    run = walker.Walker.run
    with monkeypatch.context() as m:
        m.setattr(walker.Walker, "run", lambda self: (run(self), spent.append(self.work_done())))
        for module, name, value in switched_off:
            m.setattr(module, name, value)
        return load_text(text), spent


def same_walks(text: str, monkeypatch, switched_off: tuple, work: bool = True):
    """Load ``text`` with and without the shortcut and check that both mean the same: the
    device lines, every diagnostic, the trace of each row (and the work counted). Returns
    the program loaded with the shortcut."""
    (fast, fast_work), (slow, slow_work) = walk(text, monkeypatch), walk(text, monkeypatch, switched_off)
    assert fast.device_lines == slow.device_lines
    said = [[(d.file, d.line, d.column, d.severity, d.message) for d in p.diagnostics] for p in (fast, slow)]
    assert said[0] == said[1]
    sa, sb = fast.ops.source, slow.ops.source
    for column in ("file", "call_line", "context", "iteration"):
        assert np.array_equal(getattr(sa, column), getattr(sb, column)), column
    assert sa.names == sb.names
    if work:
        assert fast_work == slow_work
    return fast
