"""A program's G54-G59 select the work systems the machine holds (issue 21):
``load_text(..., systems=(active, rows))`` starts in the machine's active system and
places each other system by its difference from the active one."""

from __future__ import annotations

import numpy as np

from app.gcode import load_text

ROWS = {1: (0.0, 0.0, 20.0), 2: (50.0, 10.0, 15.0), 3: (0.0, 0.0, 20.0), 4: (0.0, 0.0, 20.0),
        5: (0.0, 0.0, 20.0), 6: (-5.0, 0.0, 20.0)}


def _ends(text: str, systems) -> np.ndarray:
    program = load_text(text, systems=systems)
    assert not program.errors, program.errors
    return program.ops.end


def test_g55_moves_where_the_machine_has_g55():
    ends = _ends("G0 X1 Y2 Z3\nG55 G0 X1 Y2 Z3\nG59 X0\nG54 X0\n", (1, ROWS))
    assert np.allclose(ends[-4:], [[1, 2, 3], [51, 12, -2], [-5, 12, -2], [0, 12, -2]])


def test_the_program_starts_in_the_machine_s_active_system():
    ends = _ends("G0 X1 Y2 Z3\nG54 X0\n", (2, ROWS))  # the machine runs in G55
    assert np.allclose(ends[-2:], [[1, 2, 3], [-50, 2, 3]])  # omitted axes stay where they are


def test_without_the_machine_s_systems_g54_is_the_frame_as_before():
    plain = load_text("G55 G0 X1\n").ops.end
    assert np.allclose(plain[-1][0], 1.0)
