"""The fault suite of issue 4 on the link, in check mode, through the simulator's two hops.

Oracle for every recoverable case: the CNC MCU executed 0..N-1, each once, in order,
each line byte-identical to the program; the session reports the job completed.
Unrecoverable cases end in a named error within a time bound. All on simulated time.
"""

import pytest

from app.comm.listener import SessionState
from tests.comm.simlink import SimLink, assert_oracle, dialect_program
from tests.comm.tamper import Tamper, drop_byte, flip, flip_into, frame_of, swap_adjacent_digits

LINES = dialect_program(30)
TARGET = 10
DOWN = ("usb_down", "uart_down")
UP = ("usb_up", "uart_up")
ALL = DOWN + UP


@pytest.fixture
def link(tmp_path):
    return SimLink(seed=3, sd_dir=tmp_path)


def target_frame(wire: str, seq: int = TARGET):
    """The frame a fault hits: ``D seq`` going down, ``A seq`` coming up."""
    return frame_of("D" if wire.endswith("down") else "A", seq)


def wire_bytes(link, wire: str, seq: int = TARGET) -> bytes:
    from app.comm import frame as fr

    return fr.Data(seq, LINES[seq]).encode() if wire.endswith("down") else fr.Ack(seq, 16).encode()


def completes(link, lines=LINES, timeout=60.0):
    mark = len(link.executed())
    job = link.run_job(lines, timeout)
    assert job.completed, job
    assert_oracle(link.executed()[mark:], lines)
    return job


# ---------------------------------------------------------------------- byte-level damage


@pytest.mark.parametrize("wire", ALL)
def test_bit_flip_at_every_byte_position(tmp_path, wire):
    link = SimLink(seed=3, sd_dir=tmp_path)
    size = len(wire_bytes(link, wire))
    for position in range(size):
        tamper = Tamper(link.sim, wire, target_frame(wire), flip(position, position % 8))
        try:
            completes(link)
        except AssertionError as exc:
            raise AssertionError(f"{wire}: bit flip at byte {position}: {exc}") from exc
        assert tamper.hits == 1, f"{wire}: byte {position}: the fault never fired"
        tamper.remove()


@pytest.mark.parametrize("wire", ALL)
@pytest.mark.parametrize(("value", "index"), [(0x21, 0), (0x21, 1), (0x18, 0), (0x0A, 0), (0x0A, -1)],
                         ids=["space->!", "space2->!", "8->0x18", "first->newline", "last->newline"])
def test_a_flip_that_makes_a_special_byte_costs_one_resend(link, wire, value, index):
    """Issue 18: a flip makes whatever it makes; ``!``, 0x18 or a newline inside a frame
    is caught by the CRC like any byte: never a hold or stop, the job completes exactly."""
    target = target_frame(wire, 18)  # "D 18 ..." has an 8 to turn into 0x18
    tamper = Tamper(link.sim, wire, target, flip_into(value, index))
    completes(link)
    assert tamper.hits == 1
    assert not [s for s in link.rec.of("on_status") if s.state == "HOLD"]


@pytest.mark.parametrize("wire", ALL)
def test_two_adjacent_digits_swapped(link, wire):
    seq = 12 if wire.endswith("down") else 13  # "D 12 ..." / "A 13 16"
    tamper = Tamper(link.sim, wire, target_frame(wire, seq), swap_adjacent_digits)
    completes(link)
    assert tamper.hits == 1


@pytest.mark.parametrize("wire", ALL)
@pytest.mark.parametrize("where", ["first", "middle", "crc", "newline"])
def test_one_byte_dropped(link, wire, where):
    size = len(wire_bytes(link, wire))
    position = {"first": 0, "middle": size // 2, "crc": size - 3, "newline": size - 1}[where]
    tamper = Tamper(link.sim, wire, target_frame(wire), drop_byte(position))
    completes(link)
    assert tamper.hits == 1


@pytest.mark.parametrize("wire", ALL)
def test_frame_cut_short_then_silence(link, wire):
    last = len(LINES) - 1
    tamper = Tamper(link.sim, wire, target_frame(wire, last), lambda line: line[: len(line) // 2])
    completes(link)
    assert tamper.hits == 1


@pytest.mark.parametrize("wire", ALL)
def test_noise_bursts_between_frames(link, wire):
    bursts = [b"~~~\n", b"!?~ x\x00\xff\n", b"\x18!\r\n", b"\x7f\x80~garbage*12AB\n"]
    queue = list(bursts)
    tamper = Tamper(link.sim, wire, lambda line: line.startswith((b"D", b"A")),
                    lambda line: (queue.pop(0) if queue else b"") + line, times=len(bursts))
    completes(link)
    assert tamper.hits == len(bursts)


@pytest.mark.parametrize("wire", DOWN)
def test_old_real_time_bytes_in_noise_never_hold_or_stop(link, wire):
    """Issue 18: ``!`` and 0x18 are no commands: before a frame they are counted and
    logged, inside one the CRC drops it; the job completes exactly, never held."""
    Tamper(link.sim, wire, frame_of("D", TARGET), lambda line: b"\x18!" + line)
    Tamper(link.sim, wire, frame_of("D", TARGET + 2), lambda line: line[:4] + b"\x18" + line[4:])
    completes(link)
    assert not [s for s in link.rec.of("on_status") if s.state in ("HOLD", "ALARM") and s.boot != "0"]
    logs = [e.text for e in link.rec.of("on_log") if e.source == "machine"]
    assert any(text.startswith("ignored 2 real-time byte(s)") for text in logs)


# ---------------------------------------------------------------------- whole frames


@pytest.mark.parametrize("wire", ALL)
def test_frame_delivered_twice(link, wire):
    link.sim.faults.duplicate(wire.split("_")[0], wire.split("_")[1], frames=5)
    completes(link)


@pytest.mark.parametrize("wire", UP)
@pytest.mark.parametrize("kind", ["A", "F"])
def test_lost_ack_and_lost_finished(link, wire, kind):
    seq = TARGET if kind == "A" else 15  # check mode sends F for every 8th line (protocol.md)
    tamper = Tamper(link.sim, wire, frame_of(kind, seq), lambda line: b"")
    completes(link)
    assert tamper.hits == 1


@pytest.mark.parametrize("wire", ALL)
def test_frames_reordered(link, wire):
    hop, direction = wire.split("_")
    for _ in range(3):
        link.sim.faults.reorder(hop, direction)
    completes(link)


@pytest.mark.parametrize("wire", ALL)
def test_whole_window_lost(link, wire):
    kind = "D" if wire.endswith("down") else "A"
    window = [frame_of(kind, seq) for seq in range(TARGET, TARGET + 8)]
    tamper = Tamper(link.sim, wire, lambda line: any(m(line) for m in window), lambda line: b"", times=8)
    completes(link)
    assert tamper.hits == 8


def test_garbled_replies_are_never_counted_as_acks(link):
    link.sim.faults.set_rates("usb", "up", corrupt=0.003, seed=5)
    link.sim.faults.set_rates("uart", "up", corrupt=0.003, seed=6)
    lines = dialect_program(300)
    assert link.session.start_job(lines)
    end = link.now + 60.0
    while link.session.state is not SessionState.READY and link.now < end:
        link.step()
        stream = link.session.stream
        if stream is not None:
            assert stream.window.acked <= link.sim.cnc.job.acc
    assert link.rec.last("on_job_finished").completed
    assert_oracle(link.executed(), lines)


# ---------------------------------------------------------------------- resend rates


def test_a_third_of_frames_lost_completes_with_a_warning(link):
    count = {"n": 0}

    def every_third(line: bytes) -> bool:
        count["n"] += 1
        return count["n"] % 3 == 0

    Tamper(link.sim, "usb_down", lambda line: line.startswith(b"D") and every_third(line),
           lambda line: b"", times=10**9)
    job = completes(link, dialect_program(150), timeout=300.0)
    assert job.completed
    progress = link.rec.last("on_progress")
    assert progress.resend_rate > 0.10
    assert any(e.quality_warning for e in link.rec.of("on_link_changed"))


def test_every_frame_lost_aborts_after_ten_retries(link):
    Tamper(link.sim, "uart_down", lambda line: line.startswith(b"D"), lambda line: b"", times=10**9)
    start = link.now
    job = link.run_job(LINES, timeout=60.0)
    assert not job.completed and "resent 10 times" in job.reason
    assert link.now - start < 25.0  # 0.5 + 1 + 2 * 8 s of doubling timeouts, plus slack
    assert link.executed() == []
    assert link.rec.last("on_link_changed").state == "CONNECTED"  # the link itself is alive


# ---------------------------------------------------------------------- commands and lines


def test_job_while_frames_in_flight_is_refused(link):
    assert link.session.start_job(LINES)
    link.run_until(lambda: link.session.state is SessionState.STREAMING, 2.0)
    assert not link.session.start_job(LINES)
    assert link.rec.last("on_error").code == "BUSY"
    result = link.command("JOB", 5)  # the machine refuses too
    assert not result.ok and result.code == "BUSY"
    link.run_until(lambda: link.session.state is SessionState.READY, 30.0)
    assert link.rec.last("on_job_finished").completed


def test_refused_line_flushes_the_queue_and_is_not_resent(link):
    k = 12
    lines = list(LINES)
    lines[k] = "G01 X500 Y10"  # past the travel: SOFT_LIMIT when it is queued
    sent = []
    Tamper(link.sim, "usb_down", lambda line: sent.append(line) and False, lambda line: line)
    job = link.run_job(lines, timeout=30.0)
    link.run_for(3.0)
    assert not job.completed and "SOFT_LIMIT" in job.reason and f"line {k}" in job.reason
    assert [s for s, _ in link.executed()] == list(range(k))
    assert sum(1 for line in sent if line.startswith(f"D {k} ".encode())) == 1
    assert link.session.state is SessionState.READY
