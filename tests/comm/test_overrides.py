"""Overrides on the host: the frame grammar and the sans-IO session (docs/protocol.md,
"Overrides")."""

from __future__ import annotations

import pytest

from app.comm import frame as fr
from tests.comm.scripted import BOOT, Harness

# ---------------------------------------------------------------------- grammar


@pytest.mark.parametrize("body, percent", [("R 5 FEED 10", 10), ("R 5 FEED 200", 200),
                                           ("R 6 SPINDLE 50", 50), ("R 7 RAPID 25", 25)])
def test_override_frames_round_trip(body, percent):
    frame = fr.decode(fr.seal(body))
    assert isinstance(frame, fr.RealtimeCommand) and frame.percent == percent
    assert frame.body() == body


@pytest.mark.parametrize("body", ["R 5 FEED 9", "R 5 FEED 201", "R 5 FEED 010", "R 5 FEED +50",
                                  "R 5 FEED 50.0", "R 5 FEED", "R 5 FEED 50 HOST", "R 5 SPINDLE 151",
                                  "R 5 SPINDLE 49", "R 5 RAPID 75", "R 5 RAPID 0", "R 5 HOLD 50",
                                  "R 5 FEED HOST"])
def test_a_bad_override_is_a_bad_frame(body):
    with pytest.raises(fr.FrameError):
        fr.decode(fr.seal(body))


def test_status_with_overrides_and_the_older_statuses():
    body = "S 1A2B RUN 1.000 2.000 -1.000 41 39 12 9000 HP - 120/100/50"
    status = fr.decode(fr.seal(body))
    assert status.overrides == (120, 100, 50) and status.body() == body
    eleven = fr.decode(fr.seal("S 1A2B RUN 1.000 2.000 -1.000 41 39 12 9000 HP -"))
    ten = fr.decode(fr.seal("S 1A2B RUN 1.000 2.000 -1.000 41 39 12 9000 HP"))
    assert eleven.overrides is None and ten.overrides is None and ten.why == ""
    slow = fr.decode(fr.seal("S 1A2B RUN 01.000 2.000 -1.000 41 39 12 9000 HP - 120/100/50"))
    assert slow.overrides == (120, 100, 50)  # the field-by-field path reads it too
    for bad in ("120/100/75", "120/100", "300/100/100", "120/100/50/1", "x/100/100"):
        with pytest.raises(fr.FrameError):
            fr.decode(fr.seal(f"S 1A2B RUN 1.000 2.000 -1.000 41 39 12 9000 HP - {bad}"))


# ---------------------------------------------------------------------- session


def _overrides(out, verb):
    return [f for f in out if isinstance(f, fr.RealtimeCommand) and f.verb == verb]


def running():
    h = Harness(status=Harness.status(free=16))
    h.open_job([f"G01 X{i} F300" for i in range(40)])
    h.take()
    return h


def test_an_override_is_sent_in_the_fast_lane_until_answered():
    h = running()
    assert h.session.set_override("FEED", 120)
    first = _overrides(h.take(), "FEED")
    assert len(first) == 2 and first[0] == first[1] and first[0].percent == 120
    h.advance(0.03)
    repeats = _overrides(h.take(), "FEED")
    assert repeats and all(f == first[0] for f in repeats)  # same id: idempotent
    h.reply(fr.Ok(first[0].id, "FEED", "RUN"))
    h.advance(0.1)
    assert not _overrides(h.take(), "FEED")
    assert h.rec.last("on_command_done").verb == "FEED"


def test_a_new_value_replaces_a_waiting_one_under_a_new_id():
    h = running()
    h.session.set_override("FEED", 110)
    old = _overrides(h.take(), "FEED")[0]
    h.session.set_override("FEED", 120)
    h.advance(0.02)
    sent = _overrides(h.take(), "FEED")
    assert sent and {f.percent for f in sent} == {120} and sent[0].id != old.id
    h.reply(fr.Ok(old.id, "FEED", "RUN"))  # the old value's answer ends nothing
    h.advance(0.02)
    assert _overrides(h.take(), "FEED")
    h.session.set_override("SPINDLE", 80)  # one of each verb may wait at once
    h.advance(0.02)
    out = h.take()
    assert _overrides(out, "FEED") and _overrides(out, "SPINDLE")[0].percent == 80


@pytest.mark.parametrize("verb, percent", [("FEED", 5), ("FEED", 201), ("SPINDLE", 160), ("RAPID", 30),
                                           ("JOG", 50)])
def test_an_out_of_range_override_is_refused_and_nothing_sent(verb, percent):
    h = running()
    assert not h.session.set_override(verb, percent)
    assert not [f for f in h.take() if isinstance(f, fr.RealtimeCommand)]
    assert h.rec.last("on_error").code == "BAD_ARGS"


def test_the_status_event_carries_the_overrides_or_none_for_an_older_machine():
    older = running()
    older.reply(fr.Status(BOOT, "RUN", 0.0, 0.0, 1.0, 3, 1, 12, 0, "H"))
    assert older.rec.last("on_status").overrides is None
    h = running()
    h.reply(fr.Status(BOOT, "RUN", 0.0, 0.0, 1.0, 3, 1, 12, 0, "H", "", (150, 90, 50)))
    assert h.rec.last("on_status").overrides == (150, 90, 50)


def test_a_status_too_long_for_ovr_keeps_the_overrides_last_read():
    """docs/protocol.md: a status over 96 bytes with `ovr` goes without it."""
    h = running()
    h.reply(fr.Status(BOOT, "RUN", 0.0, 0.0, 1.0, 3, 1, 12, 0, "H", "", (150, 90, 50)))
    long = fr.Status(BOOT, "HOMING", -99999.999, -99999.999, -99999.999, 9_999_999, 9_999_999, 999,
                     99_999, "HCLUPSW", "LIMIT", (150, 90, 50))
    assert fr.decode(fr.encode(long)).overrides is None
    h.reply(long)
    assert h.rec.last("on_status").overrides == (150, 90, 50)


def test_an_unanswered_override_is_given_up_on_and_said():
    h = running()
    h.session.set_override("RAPID", 50)
    h.advance(5.2, step=0.05)
    assert h.rec.last("on_error").code == "REALTIME_UNCONFIRMED"
