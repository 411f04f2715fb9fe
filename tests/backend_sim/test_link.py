"""The links: UART byte timing, the fast lanes, honest frame faults and random rates, the host port."""

from __future__ import annotations

import pytest
import serial

from app.comm.frame import Status, seal
from backend_sim.clock import SimClock
from backend_sim.faults import ChannelFaults
from backend_sim.wire import USB_LATENCY, Wire, uart_byte_time

BYTE = 10 / 115200


def test_uart_bytes_take_ten_bit_times_back_to_back():
    wire = Wire("uart_down", uart_byte_time(115200))
    wire.write(b"AB\nC", 0.0)
    assert wire.take(BYTE * 0.99) == b""
    assert wire.take(BYTE * 1.01) == b"A"
    assert wire.next_time() == pytest.approx(3 * BYTE)
    assert wire.take(3 * BYTE) == b"B\n"
    wire.write(b"D", 3 * BYTE)
    assert wire.take(5 * BYTE) == b"CD"


def test_a_frame_of_96_bytes_takes_8_3_ms_on_the_uart():
    wire = Wire("uart_up", uart_byte_time(115200))
    wire.write(b"x" * 95 + b"\n", 0.0)
    assert wire.next_time() == pytest.approx(96 * BYTE)
    assert wire.take(96 * BYTE - 1e-7) == b"x" * 95


def test_urgent_frames_overtake_every_lane_but_never_cut_the_frame_on_the_wire():
    wire = Wire("uart_down", BYTE)
    wire.write(b"D 7 a\nD 8 b\n", 0.0)
    wire.write_priority(b"D 3 x\n", BYTE * 0.5)
    wire.write_urgent(b"R 1 HOLD\n", BYTE * 1.5)  # "D 7 a" is being shifted out: whole
    wire.write_urgent(b"R 2 STOP\n", BYTE * 2.5)  # behind the earlier urgent frame
    wire.write_priority(b"D 4 y\n", BYTE * 3.5)  # resends stay behind the urgent lane
    assert wire.take(1.0) == b"D 7 a\nR 1 HOLD\nR 2 STOP\nD 3 x\nD 4 y\nD 8 b\n"
    wire.write_urgent(b"R 3 RESUME\n", 2.0)  # an idle wire: sent at once
    assert wire.take(2.0 + 11.01 * BYTE) == b"R 3 RESUME\n"


def test_priority_frames_overtake_queued_frames_but_not_the_frame_on_the_wire():
    wire = Wire("uart_down", BYTE)
    wire.write(b"D 7 a\nD 8 b\nD 9 c\n", 0.0)
    wire.write_priority(b"D 3 x\n", BYTE * 2.5)  # "D 7 a" is being shifted out
    wire.write_priority(b"D 4 y\n", BYTE * 3.5)  # behind the earlier resend, in order
    assert wire.take(1.0) == b"D 7 a\nD 3 x\nD 4 y\nD 8 b\nD 9 c\n"
    wire.write_priority(b"D 5 z\n", 2.0)  # an idle wire: sent at once
    assert wire.take(2.0 + 6.01 * BYTE) == b"D 5 z\n"


def test_a_priority_lane_emptied_on_the_wire_starts_again_behind_the_current_frame():
    wire = Wire("uart_down", BYTE)
    wire.write_priority(b"D 1 a\n", 0.0)
    wire.write(b"D 8 b\nD 9 c\n", 0.0)
    assert wire.take(7.01 * BYTE) == b"D 1 a\nD"  # the resend has gone, "D 8 b" is on the wire
    wire.write_priority(b"D 2 x\n", 7.5 * BYTE)
    assert wire.take(1.0) == b" 8 b\nD 2 x\nD 9 c\n"


def test_a_cut_wire_forgets_its_priority_lane():
    wire = Wire("uart_down", BYTE)
    wire.write(b"D 7 a\n", 0.0)
    wire.write_priority(b"D 3 x\n", 0.5 * BYTE)
    wire.set_cut(True)
    wire.set_cut(False)
    wire.write(b"D 8 b\nD 9 c\n", 1.0)
    wire.write_priority(b"D 4 y\n", 1.0 + 2.5 * BYTE)  # behind "D 8 b" on the wire, never inside it
    assert wire.take(2.0) == b"D 8 b\nD 4 y\nD 9 c\n"


def test_usb_is_fast_but_not_instant():
    wire = Wire("usb_down", 1e-6, USB_LATENCY)
    wire.write(b"C 1 PING*0000\n", 0.0)
    assert wire.take(USB_LATENCY * 0.9) == b""
    assert wire.take(USB_LATENCY + 20e-6) == b"C 1 PING*0000\n"


def test_cut_wire_loses_bytes():
    wire = Wire("uart_up", BYTE)
    wire.write(b"abc\n", 0.0)
    wire.set_cut(True)
    wire.write(b"def\n", 0.0)
    assert wire.take(1.0) == b""


FRAME = b"D 5 G01 X10*1234\n"


@pytest.mark.parametrize(
    ("kind", "params", "expect"),
    [
        ("drop", {}, []),
        ("duplicate", {}, [FRAME, FRAME]),
        ("truncate", {"keep": 5}, [FRAME[:5]]),
    ],
)
def test_frame_faults(kind, params, expect):
    faults = ChannelFaults("usb_down", seed=1)
    faults.arm(kind, **params)
    assert [p for _, p in faults.process(FRAME)] == expect
    assert faults.process(FRAME) == [(0.0, FRAME)]


def test_corrupt_flips_one_bit_of_any_byte_newline_included():
    positions, bits = set(), set()
    for seed in range(400):
        faults = ChannelFaults("usb_down", seed=seed)
        faults.arm("corrupt")
        (_, out), = faults.process(FRAME)
        diff = [(i, a ^ b) for i, (a, b) in enumerate(zip(out, FRAME, strict=True)) if a != b]
        assert len(diff) == 1 and bin(diff[0][1]).count("1") == 1
        positions.add(diff[0][0])
        bits.add(diff[0][1])
    assert len(FRAME) - 1 in positions  # the newline too
    assert bits == {1 << b for b in range(8)}  # the 8th bit too


def test_delay_reorder_and_noise():
    faults = ChannelFaults("uart_up", seed=1)
    faults.arm("delay", seconds=0.3)
    assert faults.process(FRAME) == [(0.3, FRAME)]
    faults.arm("reorder")
    assert faults.process(b"first\n") == []
    assert [p for _, p in faults.process(b"second\n")] == [b"second\n", b"first\n"]
    faults.arm("noise", nbytes=4)
    (_, out), = faults.process(FRAME)
    assert out.endswith(b"\n" + FRAME) and len(out) == len(FRAME) + 5


def test_real_time_frames_are_frame_faulted_like_any_line():
    faults = ChannelFaults("usb_down", seed=1)
    faults.arm("drop")
    assert faults.process(b"R 1 HOLD*6E51\n") == []


def test_random_rates_are_deterministic_for_a_seed():
    data = FRAME * 2000

    def run(seed):
        faults = ChannelFaults("usb_up")
        faults.set_rates(seed=seed, corrupt=1e-3, drop=1e-3)
        return b"".join(p for _, p in faults.process(data)), dict(faults.counts)

    out1, counts1 = run(7)
    assert run(7) == (out1, counts1)
    assert run(8)[0] != out1
    assert 10 < counts1["rate_corrupt"] < 70 and 10 < counts1["rate_drop"] < 70


def test_random_faults_reach_the_whole_byte_space():
    """Issue 18: flips make whatever byte they make (newline, ``!``, 0x18 ...), noise
    bursts draw from all 256 values, duplicates and drops hit newlines too."""
    data = FRAME * 20000

    def faulted(**rates):
        faults = ChannelFaults("uart_down")
        faults.set_rates(seed=3, **rates)
        return b"".join(p for _, p in faults.process(data))

    flipped = faulted(corrupt=1e-2)
    assert len(flipped) == len(data)
    made = {b for a, b in zip(data, flipped, strict=True) if a != b}
    assert {ord("\n"), ord("!"), 0x18} <= made and max(made) >= 0x80
    assert flipped.count(b"\n") != data.count(b"\n")  # newlines made and unmade
    noisy = faulted(noise=1e-2)
    assert set(noisy) == set(range(256))
    assert faulted(drop=1e-2).count(b"\n") < data.count(b"\n") < faulted(duplicate=1e-2).count(b"\n")


def test_host_port_read_timeout_runs_the_simulated_clock(sim):
    port = sim.host_port
    port.timeout = 0
    assert port.read(10) == b""
    assert sim.clock.now_ms == 0
    sim.run_for(0.1)
    port.timeout = 0.5
    port.write(seal("C 1 PING"))
    line = port.readline()
    assert line.startswith(b"S ") and sim.clock.now < 0.11
    assert port.read(1) == b""
    assert 0.6 <= sim.clock.now < 0.62


def test_host_port_unplug_close_and_reopen(sim):
    port = sim.host_port
    port.write(seal("C 1 PING"))
    sim.faults.unplug()
    with pytest.raises(serial.SerialException):
        port.read(1)
    with pytest.raises(serial.SerialException):
        port.write(b"x")
    sim.faults.replug()
    port.timeout = 0.1
    port.write(seal("C 2 PING"))
    assert port.readline().startswith(b"S ")
    port.close()
    with pytest.raises(serial.PortNotOpenError):
        port.read(1)
    port.open()
    port.reset_input_buffer()
    assert port.in_waiting == 0


def test_unplugged_host_is_lost_after_3_s(sim, host):
    sim.faults.unplug()
    assert sim.run_until(lambda: sim.main.host_lost, 3.2)
    assert sim.main.flags() == "L"


def test_frame_faults_through_the_simulator_are_answered(sim, host):
    sim.faults.corrupt("usb", "down")
    host.command("PING")
    sim.run_for(0.1)
    host.pump()
    naks = [f for f in host.frames if f.KIND == "N"]
    assert naks and sim.faults.counts()["usb_down"] == {"corrupt": 1}
    sim.faults.drop("uart", "up")
    sim.faults.set_rates("uart", "up", seed=3, corrupt=0.0)
    host.command("STATUS")
    assert host.wait(lambda f: isinstance(f, Status))


def test_threaded_run_at_a_speed_factor(tmp_path):
    from backend_sim.simulator import Simulator

    sim = Simulator(sd_dir=tmp_path, seed=1, clock=SimClock())
    sim.start(speed=200.0)
    try:
        port = sim.host_port
        port.timeout = 2.0
        port.write(seal("C 1 PING"))
        assert port.readline().startswith(b"S ")
        t0 = sim.clock.now
        assert port.read(1) in (b"", b"S")
        sim.run_for(1.0)
        assert sim.clock.now >= t0 + 1.0
    finally:
        sim.stop()
    assert not sim.running


def test_a_forwarded_command_takes_its_uart_time_both_ways(sim, host):
    sim.run_for(0.13)  # between the main MCU's pings (every 0.1 s of UART silence)
    start = sim.clock.now
    cid = host.command("GET KP_X")
    answer = host.answer(cid)
    arrived = host.times[host.frames.index(answer)]
    down = len(seal(f"C {cid} GET KP_X")) * BYTE
    up = len(answer.encode()) * BYTE
    assert down + up + 2 * USB_LATENCY <= arrived - start <= down + up + 2 * USB_LATENCY + 0.003


def test_readline_timeout_covers_the_whole_line(sim):
    port = sim.host_port
    port.timeout = 0.3
    port.write(b"C 1 PI")
    assert port.readline() == b""
    assert 0.3 <= sim.clock.now < 0.32
