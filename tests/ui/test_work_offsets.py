"""The host's picture of the machine's six work systems (app/ui/work_offsets.py)."""

from __future__ import annotations

import pytest

from app.ui.work_offsets import WorkSystems


def _answers(systems: WorkSystems, answers: dict[str, float]) -> None:
    for name, value in answers.items():
        systems.take("GET", (name,), f"{name} {value:g}", True)


def test_queries_read_every_row():
    queries = WorkSystems.row_queries()
    assert len(queries) == 18 and "GET G59_Z" in queries and "GET G54_X" in queries


def test_rows_the_active_system_and_the_machine_position():
    systems = WorkSystems()
    _answers(systems, {"WCS": 56, "G56_X": 10, "G56_Y": 20, "G56_Z": 5, "G54_X": 1})
    assert systems.supported and systems.active == 56
    assert systems.offset() == [10.0, 20.0, 5.0]
    assert systems.machine((1.0, -2.0, 3.5)) == [11.0, 18.0, 8.5]
    assert systems.take("ZERO", ("X",), "X33.000 Y20.000 Z5.000", True)
    assert systems.rows[56] == [33.0, 20.0, 5.0] and systems.rows[54][0] == 1.0
    assert systems.take("SET", ("G55_Y",), "G55_Y -4.5", True)
    assert systems.rows[55][1] == -4.5
    assert not systems.take("SET", ("G55_Y",), "", False)  # refused: nothing changes
    assert systems.rows[55][1] == -4.5


def test_an_older_machine_shows_its_one_offset_as_g54():
    systems = WorkSystems()
    assert systems.take("GET", ("WCS",), "", False)
    assert systems.supported is False
    _answers(systems, {"OFFSET_X": 7, "OFFSET_Y": 8, "OFFSET_Z": 9})
    assert systems.offset() == [7.0, 8.0, 9.0]
    assert systems.machine((0.0, 0.0, 0.0)) == [7.0, 8.0, 9.0]


def test_unknown_offsets_give_no_machine_position_and_no_move():
    systems = WorkSystems()
    assert systems.machine((1.0, 2.0, 3.0)) == [None, None, None]
    with pytest.raises(ValueError):
        systems.move_to({"X": 0.0}, 30.0)


def test_a_move_rapids_at_the_top_of_z_first():
    systems = WorkSystems()
    _answers(systems, {"WCS": 54, "G54_X": 0, "G54_Y": 0, "G54_Z": 20})
    assert systems.move_to({"X": 0.0, "Y": 0.0, "Z": 0.0}, 30.0).splitlines() == [
        "G00 Z10", "G00 X0 Y0", "G00 Z0"]
    assert systems.move_to({"Y": 12.25}, 30.0).splitlines() == ["G00 Z10", "G00 Y12.25"]
    assert systems.set_row(57, "Z", -1.5) == "SET G57_Z -1.5" and systems.select(59) == "SET WCS 59"
