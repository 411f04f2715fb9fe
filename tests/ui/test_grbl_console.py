"""The window's console on a GRBL machine (issue 23): its noise filter knows GRBL's kinds
of lines (the polled reports, the job's lines and their ``ok``), and what the operator
types in the MDI line as GRBL writes it (``?``, ``$$``, ``$H``) goes to the machine
and shows its answer."""

from __future__ import annotations

import pytest

from app.comm.grbl.protocol import STREAM_KINDS
from app.ui.console import is_noise
from app.ui.mdi import classify
from tests.ui.test_grbl_features import WAIT, connect_grbl


@pytest.mark.parametrize("kind", sorted(STREAM_KINDS))
def test_grbls_stream_and_poll_lines_are_noise(kind):
    assert is_noise(kind, "ok")


@pytest.mark.parametrize("kind", ["rx", "command", "report", "^"])
def test_grbls_commands_their_answers_and_an_asked_report_are_not(kind):
    assert not is_noise(kind, "ok")


@pytest.mark.parametrize("text, control", [
    ("?", "query"), ("$$", "query"), ("$#", "query"), ("$G", "query"), ("$H", "home"), ("$X", "unlock"),
    ("$J=G91 X1 F100", "jog"), ("$10=3", "machine_settings"), ("$C", "check_mode"),
])
def test_grbl_system_commands_typed_are_commands_under_their_control(text, control):
    line = classify(text)
    assert (line.control, line.command) == (control, text)


def test_the_operators_question_mark_and_dollar_commands_show_their_answers(qtbot, make_window):
    window, _machine = connect_grbl(qtbot, make_window)
    console = window.console
    assert not console.show_stream.isChecked()
    text = lambda: console.log.toPlainText()  # noqa: E731
    qtbot.waitUntil(lambda: window.binder.status.state == "ALARM", timeout=WAIT)  # locked until homed
    console.flush()
    assert "← <" not in text()  # the polls' reports stay hidden
    window.operator.mdi("?")
    qtbot.waitUntil(lambda: "← <Alarm|" in text(), timeout=WAIT)
    assert "→ ?" in text() and text().count("← <") == 1
    window.operator.mdi("$#")
    qtbot.waitUntil(lambda: "← [G54:" in text(), timeout=WAIT)
    assert "→ $#" in text() and "unexpected character" not in text()
    window.operator.mdi("$X")
    qtbot.waitUntil(lambda: window.binder.status.state == "IDLE", timeout=WAIT)
