"""The incremental deframer: splits, noise, legacy bytes, bit errors, timeouts, over-length lines."""

import pytest
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


def test_noise_in_front_of_a_frame_costs_nothing_but_its_bytes():
    deframer = dfr.Deframer()
    out = deframer.feed(b"\x00\xff~~A " + fr.encode(fr.Ack(1, 3)) + fr.encode(fr.Ack(2, 3)), 0.0)
    assert out == [fr.Ack(1, 3), fr.Ack(2, 3)]
    assert deframer.stats.resynced == 1 and deframer.stats.bad == 0
    noise = bytes(range(256)).replace(b"\n", b"")  # over-length: the tail is searched
    out = deframer.feed(noise + fr.encode(fr.Finished(4)) + b"junk*12\n", 0.0)
    assert out[0] == fr.Finished(4) and isinstance(out[1], dfr.Dropped)
    assert deframer.stats.resynced == 2 and deframer.stats.bad == 1


def test_machine_side_takes_legacy_bytes_off_the_start_of_a_line_only():
    """``!``/0x18 are no commands (docs/protocol.md): taken off a line's start and counted;
    inside a line they are bytes of it, and the CRC judges the frame."""
    deframer = dfr.Deframer(legacy=True)
    wire = fr.encode(fr.Data(0, "G00 X1"))
    out = deframer.feed(b"!\x18" + wire + wire[:5] + b"!" + wire[5:] + b"\x18", 0.0)
    assert out[:3] == [dfr.Legacy(b"!"), dfr.Legacy(b"\x18"), fr.Data(0, "G00 X1")]
    assert isinstance(out[3], dfr.Dropped) and out[4:] == [dfr.Legacy(b"\x18")]  # a new line's start
    assert deframer.stats.legacy == 3 and deframer.pending() == 0


def test_host_side_keeps_legacy_bytes_in_the_line():
    deframer = dfr.Deframer()
    out = deframer.feed(b"!" + fr.encode(fr.Ack(1, 3)), 0.0)
    assert out == [fr.Ack(1, 3)] and deframer.stats.legacy == 0 and deframer.stats.resynced == 1


def _bit_errors(wire: bytes, count: int):
    bits = range(len(wire) * 8)
    if count == 1:
        yield from ((b,) for b in bits)
    else:
        yield from ((a, b) for a in bits for b in bits if a < b)


def _flipped(wire: bytes, positions) -> bytes:
    bad = bytearray(wire)
    for bit in positions:
        bad[bit // 8] ^= 1 << (bit % 8)
    return bytes(bad)


@pytest.mark.parametrize("count", [1, 2])
def test_no_one_or_two_bit_error_makes_a_frame_that_was_not_sent(count):
    """Issue 18: every 1- and 2-bit error of an R frame, a D frame and a status behind it
    (newlines and CRCs included: a flip may make a newline, ``!`` or 0x18) gives nothing
    but the frames sent, intact, or drops: never a different frame, never a command."""
    sent = [fr.RealtimeCommand(41, "RESUME"), fr.Data(7, "G01 X12.5 Y-3"), fr.Command(42, "PING")]
    wire = b"".join(fr.encode(f) for f in sent)
    for positions in _bit_errors(wire, count):
        deframer = dfr.Deframer(legacy=True)
        out = deframer.feed(_flipped(wire, positions), 0.0) + deframer.poll(1.0)
        frames = [o for o in out if isinstance(o, fr.Frame)]
        assert all(f in sent for f in frames), (positions, frames)


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
