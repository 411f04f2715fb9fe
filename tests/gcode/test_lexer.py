"""The general lexer: words, numbers, comments, and errors with line and column."""

import pytest

from app.gcode.lexer import lex_line


def words(text):
    lexed = lex_line(text, 1)
    assert lexed.error is None, lexed.error
    return [(w.letter, w.value) for w in lexed.words]


@pytest.mark.parametrize(
    "text, expected",
    [
        ("G1X10Y-2.5", [("G", 1), ("X", 10), ("Y", -2.5)]),
        ("g1 x.5 y-0. z+3", [("G", 1), ("X", 0.5), ("Y", 0.0), ("Z", 3)]),
        ("G01 Z-0.125000 F100.0(Penetrate)", [("G", 1), ("Z", -0.125), ("F", 100)]),
        ("(a comment) G0 (another) X1 ; the rest ( is ignored", [("G", 0), ("X", 1)]),
        ("N120 G0 X1*57", [("N", 120), ("G", 0), ("X", 1)]),
        ("X1 0.5", [("X", 10.5)]),
        ("G 1 X 2", [("G", 1), ("X", 2)]),
        ("", []),
        ("   \t\r", []),
        ("(only a comment)", []),
        ("G90.1", [("G", 90.1)]),
    ],
)
def test_words(text, expected):
    assert words(text) == expected


def test_columns_are_one_based():
    lexed = lex_line("  G1 X5", 3)
    assert [(w.letter, w.column) for w in lexed.words] == [("G", 3), ("X", 6)]


@pytest.mark.parametrize("text, skip", [("%", "%"), ("  % (start)", "%"), ("/G1 X5", "block delete")])
def test_skipped_lines(text, skip):
    assert lex_line(text, 1).skip == skip


@pytest.mark.parametrize(
    "text, column, fragment",
    [
        ("G1 X#1", 5, "'#' parameters"),
        ("o100 sub", 1, "o-words"),
        ("G1 X[1+2]", 5, "expressions"),
        ("G1 (open comment", 4, "not closed"),
        ("G1 (a) X1 (open", 11, "not closed"),
        ("G1 (a (b) c) X1", 7, "nested comment"),
        ("(a (b)) G1", 4, "nested comment"),
        ("G1 (a (b", 7, "nested comment"),
        ("G1 X", 4, "word X has no number"),
        ("G1 X-", 4, "word X has no number"),
        ("G1 X1.2.3", 8, "unexpected character '.'"),
        ("G1 X1 $", 7, "unexpected character '$'"),
        ("G1 X1 é", 7, "unexpected character"),
        ("% G1", 1, "after '%'"),
    ],
)
def test_errors_name_line_and_column(text, column, fragment):
    lexed = lex_line(text, 7)
    assert lexed.error is not None
    assert (lexed.error.line, lexed.error.column) == (7, column)
    assert fragment in lexed.error.message
    assert str(lexed.error).startswith(f"line 7, column {column}: ")


@pytest.mark.parametrize("text", ["G1 X1(c)0", "G1 X1 (c) 0", "G1 X1\x010"])
def test_fast_path_agrees_that_a_comment_ends_a_number(text):
    from app.gcode import load_text

    assert load_text(text).errors


@pytest.mark.parametrize("text", ["(header (plain); scale 1)\nG1 X1 F100\nM2\n", "G1 X1 F1 (a (b) c)\nM2\n"])
def test_a_nested_comment_is_refused_on_the_plain_path(text):
    """rs274 refuses the line ("Nested comment found"); the rest of the program stays plain."""
    from app.gcode import load_text, sniff

    assert not sniff.needs_expander(text.encode())
    program = load_text(text)
    assert [(d.line, "nested comment" in d.message) for d in program.errors] == [(1, True)]
