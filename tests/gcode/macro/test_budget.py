"""Hostile programs (issue 19): every program ends within a budget of work counted, never
timed, or is refused with a message naming the line and the limit."""

import pytest

from app.gcode import limits, load, load_text
from app.gcode.macro import structure, walker


def _only_error(program):
    (error,) = program.errors
    return error


@pytest.mark.parametrize("body", [
    "#2 = 0\no2 while [#2 LT 1000]\n#2 = [#2 + 1]\no2 endwhile\n",  # a nested loop of no moves
    "#2 = #<_x>\n", "#2 = #5420\n",  # reads of the machine's state
    "G1 X[#1 MOD 3]\n#2 = #<_x>\n",  # a read after each move: the interpreter asked each time
    "G1 X1\nG91\nG90\n",  # blocks the general interpreter reads one at a time
])
def test_a_loop_past_the_work_budget_is_refused_naming_its_line(monkeypatch, body):
    monkeypatch.setattr(walker, "WORK_LIMIT", 200_000)
    text = f"G21 F100\n#1 = 0\no1 while [#1 LT 900000]\n{body}#1 = [#1 + 1]\no1 endwhile\nM2\n"
    error = _only_error(load_text(text))
    assert "more work than the limit of 200,000" in error.message
    assert 3 <= error.line <= 3 + body.count("\n") + 2  # a line of the loop


@pytest.mark.parametrize("dialect", ["FANUC", "LINUXCNC"])
def test_the_work_budget_leaves_room_for_the_benchmarks_expansion(monkeypatch, dialect):
    """``bench_macro``'s million moves, measured on a hundredth of its grid: the work
    counted grows with the holes, and the whole grid spends under half the budget."""
    from bench import bench_macro

    spent = []
    run = walker.Walker.run
    monkeypatch.setattr(walker.Walker, "run", lambda self: (run(self), spent.append(self.work_done())))
    text = getattr(bench_macro, dialect)
    for old, new in ((str(bench_macro.ROWS), "58"), (str(bench_macro.COLUMNS), "57")):
        text = text.replace(old, new)
    program = load_text(text)
    assert not program.errors and len(program.moves) == 3 * 58 * 57
    holes = bench_macro.ROWS * bench_macro.COLUMNS
    assert spent[0] * holes / (58 * 57) < walker.WORK_LIMIT / 2
    assert 3 * holes < walker.MOVE_LIMIT


def test_reading_the_position_after_every_move_gives_rs274s_values():
    """The interpreter is not asked again while nothing changed (the sync's cache)."""
    text = ("G21 F100\n#1 = 0\no1 while [#1 LT 50]\nG1 X[#1 MOD 7]\n#<a> = #<_x>\n#<b> = #<_x>\n"
            "G1 Y[#<a> + #<b>]\n#1 = [#1 + 1]\no1 endwhile\nM2\n")
    program = load_text(text)
    assert not program.errors
    ys = [m["end"][1] for m in program.moves if m["line"] == 7]
    assert ys == [2.0 * (k % 7) for k in range(50)]


@pytest.mark.parametrize("line, found", [
    ("G91 G81 X0.001 Y0 Z-1 R1 L100000000",
     "G81 at line 3 would make 500,000,000 moves (100,000,000 repeats); the limit is 500,000"),
    ("G83 X1 Y1 Z-90 R1 Q0.00001", "G83 at line 3 would make 27,300,002 moves (9,099,999 pecks); "
                                   "the limit is 500,000"),
    ("G73 X1 Y1 Z-90 R1 Q0.0001", "G73 at line 3 would make 1,820,003 moves (909,999 pecks)"),
    ("G82 X1 Y1 Z-1 R1 P100000", "dwell P100000 is longer than 3600 s"),
])
def test_a_cycle_is_counted_before_it_is_expanded(line, found):
    program = load_text(f"G21 G90 F100\nG0 Z5\n{line}\nG80\nM2\n")
    error = _only_error(program)
    assert error.line == 3 and found in error.message
    assert not [m for m in program.moves if m["line"] == 3]


def test_cycles_and_splines_of_a_program_share_one_budget(monkeypatch):
    monkeypatch.setattr(limits, "MAX_MOVES", 30)
    program = load_text("G21 G90 F100\nG0 Z5\n" + "G81 X1 Y1 Z-1 R1 L4\n" * 3 + "G80\nM2\n")
    assert [d.line for d in program.errors] == [4, 5]  # 20 each: the second passes 30
    assert "the limit for a program is 30" in program.errors[0].message
    spline = load_text("G21 G90 F100\nG5 I0 J10000 P0 Q10000 X1 Y0\nM2\n")
    assert "G5 at line 2 would bring the moves that cycles and splines make to" in _only_error(spline).message
    monkeypatch.setattr(limits, "MAX_MOVES", 1000)
    assert not load_text("G21 G90 F100\nG5 I0 J10000 P0 Q10000 X1 Y0\nM2\n").errors
    monkeypatch.setattr(limits, "MAX_LINE_MOVES", 10)
    spline = load_text("G21 G90 F100\nG5 I0 J10000 P0 Q10000 X1 Y0\nM2\n")
    assert "G5 at line 2 would make" in _only_error(spline).message


@pytest.mark.parametrize("code, per_peck", [(83, 3), (73, 2)])
def test_the_count_of_pecks_is_the_pecks_made(monkeypatch, code, per_peck):
    """The count before expanding is the expansion's own (at most 5 moves a hole besides)."""
    program = load_text(f"G21 G90 F100\nG0 Z5\nG{code} X1 Y1 Z-10.5 R1 Q1 L3\nG80\nM2\n")
    made = len([m for m in program.moves if m["line"] == 3])
    monkeypatch.setattr(limits, "MAX_LINE_MOVES", made - 1)
    error = _only_error(load_text(f"G21 G90 F100\nG0 Z5\nG{code} X1 Y1 Z-10.5 R1 Q1 L3\nG80\nM2\n"))
    assert f"({3 * 11} pecks)" in error.message
    assert 3 * 11 * per_peck < made <= 3 * (11 * per_peck + 5)


def test_a_program_with_too_many_lines_to_compile_is_refused_at_the_first_past_the_limit(
        monkeypatch, tmp_path):
    monkeypatch.setattr(structure, "MAX_LINES", 40)
    program = load_text("#1 = 1\n" + "G1 X#1 F100\n" * 45)
    ((line, message),) = [(d.line, d.message) for d in program.errors]
    assert line == 41 and "at most 40 lines" in message and "past the limit" in message
    (tmp_path / "sub.ngc").write_text("o<sub> sub\n" + "G1 X1\n" * 30 + "o<sub> endsub\n")
    (tmp_path / "main.ngc").write_text("G21 F100\n" + "G1 X2\n" * 10 + "o<sub> call\nM2\n")
    ((where, line, message),) = [(d.file, d.line, d.message) for d in load(tmp_path / "main.ngc").errors]
    assert where.endswith("sub.ngc") and line == 40 - 13 + 1 and "at most 40 lines" in message


def test_plain_lines_do_not_count_toward_the_lines_compiled(monkeypatch):
    monkeypatch.setattr(structure, "MAX_LINES", 40)
    program = load_text("#1 = 1\nG21 F100\n" + "G1 X1 Y2 (a comment)\nG1 X2 Y1 ; another\n" * 5000 + "M2\n")
    assert not program.errors and len(program.moves) == 10_000
