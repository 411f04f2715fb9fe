"""Fanuc's system variables (fanuc_system.py): the modal state and the position a macro
reads, read-only, and the #3000 alarm that stops the program with the line's message."""

import pytest

from app.gcode import load_text

SETUP = "O0001\nG21 G91 G1 X5 F250 S1000 M3\nT3\n"


def _rapids(program) -> list[list[float]]:
    return [m["end"] for m in program.moves if m["kind"] == "rapid"]


@pytest.mark.parametrize(("variable", "value"), [
    ("#4001", 1), ("#4002", 17), ("#4003", 91), ("#4006", 21), ("#4007", 40), ("#4009", 80),
    ("#4014", 54), ("#4109", 250), ("#4119", 1000), ("#4120", 3), ("#5041", 5), ("#5001", 5),
])
def test_a_macro_reads_the_modal_state_and_position(variable, value):
    program = load_text(SETUP + f"#1 = {variable}\nG90 G0 X0 Y[#1]\nM30\n")
    assert not program.errors
    assert _rapids(program)[-1][1] == pytest.approx(value)


def test_g90_g91_saved_and_restored_through_4003():
    text = "O0001\nG90 G0 X1\n#10 = #4003\nG91 G0 X1\nG#10\nG0 X7\nM30\n"
    program = load_text(text)
    assert not program.errors
    assert _rapids(program)[-1][0] == 7.0  # back in G90: X7, not X9


def test_system_variables_are_read_only():
    program = load_text("O0001\n#4003 = 90\nM30\n")
    assert [(e.line, e.message) for e in program.errors] == [
        (2, "#4003 is a system variable of the control: it can be read, not set")]


def test_alarm_3000_stops_the_program_with_the_lines_message():
    text = "O0001\nG0 X1\nIF [#24 EQ #0] THEN #3000 = 1 (X NOT GIVEN)\nG0 X2\nM30\n"
    program = load_text(text)
    assert [(e.line, e.message) for e in program.errors] == [(3, "macro alarm 3001: X NOT GIVEN")]
    assert [end[0] for end in _rapids(program)] == [1.0]


def test_linuxcnc_parameters_4000_and_up_stay_ordinary():
    program = load_text("#4003 = 12\n#3000 = 1\nG0 X#4003 Y#3000\nM2\n")
    assert not program.errors
    assert _rapids(program)[-1][:2] == [12.0, 1.0]
