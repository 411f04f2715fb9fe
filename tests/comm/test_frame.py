"""Golden byte vectors and error cases for the frame codec (docs/protocol.md)."""

from dataclasses import replace

import pytest
from hypothesis import given
from hypothesis import strategies as st

from app.comm import frame as fr

GOLDEN = [
    (fr.Data(0, "G00 X10 Y10"), b"D 0 G00 X10 Y10*904C\n"),
    (fr.Command(3, "PING"), b"C 3 PING*6852\n"),
    (fr.Command(4, "JOG", ("X", "1.5", "300")), b"C 4 JOG X 1.5 300*E180\n"),
    (fr.Ack(5, 7), b"A 5 7*F37C\n"),
    (fr.Finished(-1), b"F -1*1DCB\n"),
    (fr.Nak(3), b"N 3*CAE6\n"),
    (fr.Ok(4, "HOME"), b"O 4 HOME*E871\n"),
    (fr.Error(None, "SOFT_LIMIT", "X+ 151.000 > 150"), b"E - SOFT_LIMIT X+ 151.000 > 150*C043\n"),
    (fr.Error(3, "BUSY", "job running"), b"E 3 BUSY job running*28B9\n"),
    (
        fr.Status("A1B2C3D4", "IDLE", 0, 0, 30, -1, -1, 16, 0, "H"),
        b"S A1B2C3D4 IDLE 0.000 0.000 30.000 -1 -1 16 0 H -*F248\n",
    ),
    (
        fr.Status("1", "RUN", 1.5, -2, 3, 4, 3, 10, 4500, ""),
        b"S 1 RUN 1.500 -2.000 3.000 4 3 10 4500 - -*04B0\n",
    ),
    (
        fr.Status("1", "HOLD", 1.5, -2, 3, 4, 3, 10, 4500, "HW", "PROG"),
        b"S 1 HOLD 1.500 -2.000 3.000 4 3 10 4500 HW PROG*067D\n",
    ),
    (fr.RealtimeCommand(7, "HOLD"), b"R 7 HOLD*6E51\n"),
    (fr.RealtimeCommand(8, "STOP"), b"R 8 STOP*1A9E\n"),
    (fr.RealtimeCommand(1000000001, "HOLD", "LINK"), b"R 1000000001 HOLD LINK*8AFE\n"),
    (fr.Alarm("LIMIT", "X min"), b"X LIMIT X min*9441\n"),
    (fr.Info(7, "a.nc 120 10"), b"I 7 a.nc 120 10*F127\n"),
    (fr.Log("hello world"), b"L hello world*296F\n"),
]


def test_check_values_of_the_protocol():
    assert fr.crc16(b"123456789") == 0x29B1
    assert fr.seal("D 0 G00 X10 Y10") == b"D 0 G00 X10 Y10*904C\n"


@pytest.mark.parametrize(("frame", "wire"), GOLDEN, ids=lambda v: getattr(v, "KIND", None))
def test_golden_vectors(frame, wire):
    assert fr.encode(frame) == wire
    assert fr.decode(wire) == frame


@pytest.mark.parametrize(
    ("wire", "reason"),
    [
        (b"D 0 G00 X10 Y10*904D\n", "bad CRC"),
        (b"D 0 G00 X10 Y10\n", "no '*'"),
        (b"D 0 G00 X01 Y10*904C\n", "bad CRC"),  # two adjacent digits swapped
        (b"D 0 G00 X10 Y10*904c\n", "4 upper-case hex"),
        (b"Q 1*" + b"%04X" % fr.crc16(b"Q 1") + b"\n", "unknown frame kind"),
        (fr.seal("A x 3"), "bad seq"),
        (fr.seal("S 1 FLY 0 0 0 -1 -1 1 0 -"), "bad state"),
        (fr.seal("S 1 IDLE 0 0 0 -1 -1 1 0 Q"), "bad flags"),
        (fr.seal("C 1  PING"), "single-spaced"),
        (b"D 1 " + b"X" * 90 + b"*0000\n", "over-length"),
        (fr.seal("R 7 PAUSE"), "bad real-time verb"),
        (fr.seal("R 7 HOLD NOW"), "bad why"),
        (fr.seal("R 7 HOLD LINK X"), "at most a why"),
        (fr.seal("R x HOLD"), "bad command id"),
        (fr.seal("R 7"), "needs an id, a verb"),
        (fr.seal("R 12345678901 STOP"), "bad command id"),
        (fr.seal("S 1 IDLE 0 0 0 -1 -1 1 0 - WHY"), "bad why"),
    ],
)
def test_bad_frames_are_refused_with_a_reason(wire, reason):
    with pytest.raises(fr.FrameError, match=reason):
        fr.decode(wire)


def test_seal_refuses_a_body_that_would_be_too_long():
    with pytest.raises(fr.FrameError, match="over 96"):
        fr.seal("D 1 " + "X" * 87)


def test_a_status_of_ten_fields_is_read_with_why_unknown():
    """A machine from before the ``why`` field still reads (docs/protocol.md)."""
    status = fr.decode(fr.seal("S 1 HOLD 1.500 -2.000 3.000 4 3 10 4500 H"))
    assert status.state == "HOLD" and status.flags == "H" and status.why == ""
    assert fr.decode(fr.seal("S 1 HOLD 1 -2 3 4 3 10 4500 H")).why == ""  # the slow path too


def test_every_single_bit_flip_is_detected():
    wire = fr.encode(fr.Data(12, "G01 X12.5 Y-3 F300"))
    for i in range(len(wire) - 1):
        for bit in range(8):
            bad = bytearray(wire)
            bad[i] ^= 1 << bit
            with pytest.raises(fr.FrameError):
                fr.decode(bytes(bad))


_coord = st.decimals(min_value="-99999.999", max_value="99999.999", places=3).map(float)
_seq = st.integers(-1, 9_999_999)
_ovr = st.tuples(st.integers(10, 200), st.integers(50, 150), st.sampled_from((25, 50, 100)))


@given(
    st.builds(
        fr.Status,
        boot=st.text("0123456789ABCDEF", min_size=1, max_size=8),
        state=st.sampled_from(fr.STATES),
        x=_coord, y=_coord, z=_coord,
        acc=_seq, done=_seq,
        free=st.integers(0, 999), rpm=st.integers(0, 99_999),
        flags=st.text(fr.FLAG_LETTERS, max_size=7),
        why=st.sampled_from(("",) + fr.WHY_CODES),
        overrides=st.none() | _ovr,
    )
)
def test_any_status_within_the_documented_bounds_round_trips(status):
    """docs/protocol.md: within these bounds the eleven fields always fit in 96 bytes;
    `ovr` goes along when it fits too."""
    back = fr.decode(fr.encode(status))
    assert back == status or (back == replace(status, overrides=None) and len(status.body()) < 96)


def test_the_longest_status_goes_without_ovr():
    longest = fr.Status("ABCDEF01", "HOMING", -99999.999, -99999.999, -99999.999, 9_999_999, 9_999_999,
                        999, 99_999, "HCLUPSW", "LIMIT", (200, 150, 100))
    wire = fr.encode(longest)
    assert len(wire) == 96 and fr.decode(wire) == replace(longest, overrides=None)
    short = replace(longest, x=1.0, y=2.0, z=3.0, acc=10, done=9)
    assert fr.decode(fr.encode(short)) == short
