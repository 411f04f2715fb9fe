"""The incremental deframer: splits, noise, real-time bytes, timeouts, over-length lines."""

from hypothesis import given
from hypothesis import strategies as st

from app.comm import deframer as dfr
from app.comm import frame as fr
from tests.comm.test_frame import GOLDEN


def _wire(frames):
    return b"".join(fr.encode(f) for f, _ in frames)


@given(st.lists(st.integers(min_value=1, max_value=40), max_size=30))
def test_deframer_reassembles_any_split(cuts):
    stream = _wire(GOLDEN)
    deframer = dfr.Deframer()
    out, pos = [], 0
    for cut in cuts:
        out += deframer.feed(stream[pos : pos + cut], now=0.0)
        pos += cut
    out += deframer.feed(stream[pos:], now=0.0)
    assert out == [f for f, _ in GOLDEN]


def test_noise_between_frames_costs_only_the_next_frame():
    deframer = dfr.Deframer()
    out = deframer.feed(b"\x00\xff~~" + fr.encode(fr.Ack(1, 3)) + fr.encode(fr.Ack(2, 3)), 0.0)
    assert isinstance(out[0], dfr.Dropped)
    assert out[1:] == [fr.Ack(2, 3)]
    assert deframer.stats.bad == 1


def test_machine_side_takes_realtime_bytes_out_of_the_stream():
    deframer = dfr.Deframer(realtime=True)
    wire = fr.encode(fr.Data(0, "G00 X1"))
    out = deframer.feed(wire[:5] + b"!" + wire[5:] + b"\x18", 0.0)
    assert out == [dfr.Realtime(b"!"), fr.Data(0, "G00 X1"), dfr.Realtime(b"\x18")]


def test_partial_frame_is_dropped_after_500_ms():
    deframer = dfr.Deframer()
    assert deframer.feed(b"A 1 ", 0.0) == []
    assert deframer.poll(0.4) == []
    dropped = deframer.poll(0.6)
    assert dropped == [dfr.Dropped("partial frame timed out", b"A 1 ")]
    assert deframer.feed(fr.encode(fr.Ack(1, 2)), 0.7) == [fr.Ack(1, 2)]


def test_overlength_line_is_dropped_once_and_the_next_frame_survives():
    deframer = dfr.Deframer()
    out = deframer.feed(b"L " + b"x" * 300 + b"\n" + fr.encode(fr.Finished(4)), 0.0)
    assert [type(o) for o in out] == [dfr.Dropped, fr.Finished]
    assert deframer.stats.overlength == 1


def test_carriage_returns_and_blank_lines_are_ignored():
    deframer = dfr.Deframer()
    assert deframer.feed(b"\r\n\nF 2*" + b"%04X" % fr.crc16(b"F 2") + b"\r\n", 0.0) == [fr.Finished(2)]
