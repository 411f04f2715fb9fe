"""The kit's own codec against the document's check values and hostile lines."""

import pytest

from app.comm.conformance.wire import GOLDEN, Reply, crc, seal, self_test


def test_golden_vectors():
    assert self_test() == []
    assert crc(b"123456789") == "29B1" and crc(b"D 0 G00 X10 Y10") == "904C" == GOLDEN[b"D 0 G00 X10 Y10"]


@pytest.mark.parametrize("body", ["S 1A2B IDLE 0.000 0.000 10.000 -1 -1 16 0 -", "A 12 8", "F -1", "N 3",
                                  "O 5 SD LIST 2", "E - BAD_SEQ 4 no job open", "E 9 BUSY machine is RUN",
                                  "X HOST_LOST no valid host frame for 3 s", "I 5 a.ngc 12 3", "L job done",
                                  "O 7 RESET"])
def test_valid_frames_read(body):
    reply = Reply.parse(seal(body), 0.0)
    assert reply.problem is None, reply.problem
    assert reply.kind == body[0]


@pytest.mark.parametrize("line,why", [
    (b"S 1A2B IDLE 0 0 0 -1 -1 16 0 -*0000\n", "CRC"),
    (b"A 1 2\n", "no '*'"),
    (seal("S 1A2B DANCING 0.000 0.000 0.000 -1 -1 16 0 -"), "grammar"),
    (seal("S 1A2B IDLE 0.000 0.000 0.000 -1 -1 16 0 Q"), "grammar"),
    (seal("A x 2"), "grammar"),
    (seal("Q 1"), "unknown kind"),
    (seal("L " + "x" * 95), "over"),
])
def test_bad_lines_say_why(line, why):
    reply = Reply.parse(line, 0.0)
    assert reply.problem is not None and why in reply.problem


def test_fields():
    reply = Reply.parse(seal("E 12 SOFT_LIMIT X+ 151.200 > 150"), 0.0)
    assert reply.id == 12 and reply.fields[1] == "SOFT_LIMIT" and reply.text == "X+ 151.200 > 150"
    assert Reply.parse(seal("E - BAD_SEQ 4 no job open"), 0.0).id is None
