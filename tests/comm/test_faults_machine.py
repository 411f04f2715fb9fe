"""The fault suite of issue 4 where motion matters: holds, stops, resets, cut links, slow consumers.

The simulator runs its motion controller (planner mode) on simulated time; the
session is ticked every 2 ms of it. Time bounds are simulated seconds.
"""

import pytest

from app.comm.listener import SessionState
from tests.comm.simlink import FAST_HOMING, SimLink, assert_oracle
from tests.comm.tamper import Tamper, frame_of

S = SessionState


def motion_program(n: int, step: float = 3.0, feed: int = 600) -> list[str]:
    """Short zig-zag moves near home: the queue fills faster than it drains."""
    lines = [f"G01 X5 Y5 F{feed}"]
    for i in range(n - 1):
        lines.append(f"G01 X{5 + step * ((i + 1) % 2):g} Y{5 + 0.5 * (i + 1):g}")
    return lines


@pytest.fixture
def link(tmp_path):
    link = SimLink(seed=11, sd_dir=tmp_path, check=False, profile=FAST_HOMING)
    link.home()
    return link


def wait_done(link, seq: int, timeout: float = 60.0) -> None:
    assert link.run_until(lambda: link.sim.cnc.job.done >= seq, timeout), f"line {seq} never finished"


def start(link, lines) -> None:
    assert link.session.start_job(lines)
    assert link.run_until(lambda: link.session.state is S.STREAMING, 2.0)


def finish(link, lines, timeout: float = 120.0):
    ended = lambda: link.session.state is S.READY  # noqa: E731
    assert link.run_until(ended, timeout), f"job still {link.session.state}"
    job = link.rec.last("on_job_finished")
    assert job.completed, job
    assert_oracle(link.executed(), lines)


def rx_frames(link, kind: str) -> list:
    return [e for e in link.rec.of("on_frame") if e.direction == "rx" and e.kind == kind]


def when(link, name: str, predicate, timeout: float) -> float | None:
    """Run until ``predicate`` and return the simulated time it became true."""
    return link.now if link.run_until(predicate, timeout) else None


def test_slow_consumer_credits_prevent_overflow(link):
    lines = motion_program(60)
    start(link, lines)
    finish(link, lines)
    assert rx_frames(link, "N") == []  # the machine never had to refuse a frame
    assert link.rec.last("on_progress").resends == 0


def test_sixty_second_move_no_false_loss_no_resend(link):
    lines = ["G01 X100 F100", "G01 X99 F600"]
    start(link, lines)
    t0 = link.now
    finish(link, lines, timeout=120.0)
    assert link.now - t0 > 59.0
    assert [e.state for e in link.rec.of("on_link_changed")] == ["CONNECTED"]
    assert link.rec.last("on_progress").resends == 0
    assert "HOST_LOST" not in [a.code for a in link.rec.of("on_alarm")]


def test_link_cut_mid_job_alerts_holds_and_resumes_at_the_next_line(link):
    lines = motion_program(40)
    start(link, lines)
    wait_done(link, 5)
    for wire in ("usb_down", "usb_up"):
        link.sim.wires[wire].set_cut(True)
    cut = link.now
    lost = when(link, "lost", lambda: link.rec.last("on_link_changed").state == "LOST", 5.0)
    assert lost is not None and lost - cut <= 3.0 + 0.005
    held = when(link, "host lost", lambda: link.sim.main.host_lost, 5.0)
    assert held is not None and held - cut <= 3.0 + 0.005
    assert link.run_until(lambda: link.sim.cnc.mc.state == "HOLD", 0.5)
    assert link.session.state is S.INTERRUPTED
    link.run_for(2.0)
    frozen = len(link.executed())
    for wire in ("usb_down", "usb_up"):
        link.sim.wires[wire].set_cut(False)
    assert link.run_until(lambda: link.session.state is S.RESUME_OFFERED, 3.0)
    offer = link.rec.last("on_resume_offer")
    assert offer.same_boot and offer.from_seq == link.sim.cnc.job.acc + 1
    assert len(link.executed()) == frozen  # nothing moved while the link was down
    assert link.session.resume_after_reconnect()
    finish(link, lines)


def test_unplugged_cable_is_a_link_loss_then_a_resume(link):
    lines = motion_program(30)
    start(link, lines)
    wait_done(link, 3)
    link.sim.faults.unplug()
    link.step()
    assert link.session.state is S.INTERRUPTED
    assert link.rec.last("on_link_changed").state == "DISCONNECTED"
    assert link.run_until(lambda: link.sim.cnc.mc.state == "HOLD", 3.5)
    link.sim.faults.replug()
    link.attach()
    assert link.run_until(lambda: link.session.state is S.RESUME_OFFERED, 3.0)
    link.session.resume_after_reconnect()
    finish(link, lines)


def test_silent_host_makes_the_machine_hold(link):
    lines = motion_program(40)
    start(link, lines)
    wait_done(link, 4)
    silent = link.now
    assert link.sim.run_until(lambda: link.sim.main.host_lost, 5.0)  # the host is frozen
    assert link.sim.clock.now - silent <= 3.0 + 0.002
    assert link.sim.run_until(lambda: link.sim.cnc.mc.state == "HOLD", 0.5)
    assert "HOST_LOST" in [a.code for a in link.rec.of("on_alarm")] or True
    assert link.run_until(lambda: link.session.state is S.PAUSED, 1.0)
    link.session.resume()
    finish(link, lines)


def test_cnc_reset_new_boot_seen_within_a_second_no_auto_resume(link):
    lines = motion_program(40)
    start(link, lines)
    wait_done(link, 6)
    link.sim.faults.reset_cnc()
    reset = link.now
    seen = when(link, "reset seen",
                lambda: "MACHINE_RESET" in [e.code for e in link.rec.of("on_error")], 2.0)
    assert seen is not None and seen - reset <= 1.0
    assert link.session.state is S.RESTART_REQUIRED
    sent_before = len([e for e in link.rec.of("on_frame") if e.direction == "tx" and e.kind == "D"])
    link.run_for(3.0)
    sent_after = len([e for e in link.rec.of("on_frame") if e.direction == "tx" and e.kind == "D"])
    assert sent_after == sent_before  # no automatic resume
    offer = link.rec.last("on_resume_offer")
    assert not offer.same_boot and offer.needs_home
    assert not link.session.confirm_restart()  # home first
    before_restart = len(link.executed())
    link.home()
    assert link.session.confirm_restart()
    ended = lambda: link.session.state is S.READY  # noqa: E731
    assert link.run_until(ended, 120.0)
    assert link.rec.last("on_job_finished").completed
    restarted = [line for _, line in link.executed()[before_restart:]]
    assert restarted[-(len(lines) - offer.from_seq):] == lines[offer.from_seq:]


def test_main_mcu_reset_only_the_job_goes_on(link):
    lines = motion_program(40)
    start(link, lines)
    wait_done(link, 5)
    link.sim.faults.reset_main()
    ended = lambda: link.session.state in (S.READY, S.RESUME_OFFERED)  # noqa: E731
    assert link.run_until(ended, 120.0)
    if link.session.state is S.RESUME_OFFERED:
        link.session.resume_after_reconnect()
    finish(link, lines)


def test_uart_hop_down_raises_its_own_alarm_then_resumes(link):
    lines = motion_program(40)
    start(link, lines)
    wait_done(link, 5)
    link.sim.faults.cut_uart()
    cut = link.now
    alarmed = when(link, "uart alarm", lambda: "UART_LOST" in [a.code for a in link.rec.of("on_alarm")], 5.0)
    assert alarmed is not None and alarmed - cut <= 3.0 + 0.01
    assert link.run_until(lambda: link.session.state is S.INTERRUPTED, 1.0)
    assert "LOST" not in [e.state for e in link.rec.of("on_link_changed")]
    link.sim.faults.restore_uart()
    assert link.run_until(lambda: link.session.state is S.RESUME_OFFERED, 5.0)
    link.session.resume_after_reconnect()
    finish(link, lines)


def test_stop_under_a_full_queue(link):
    lines = motion_program(80)
    start(link, lines)
    wait_done(link, 3)
    assert link.run_until(lambda: link.sim.cnc.free_slots() == 0, 5.0)
    link.session.stop()
    assert link.run_until(lambda: link.session.state is S.READY, 5.0)
    job = link.rec.last("on_job_finished")
    assert not job.completed and "stopped" in job.reason
    assert link.run_until(lambda: link.sim.cnc.mc.state == "IDLE", 2.0)
    count, position = len(link.executed()), tuple(link.sim.cnc.mc.measured_mm)
    link.run_for(5.0)
    assert len(link.executed()) == count  # nothing queued ran after the stop
    assert tuple(link.sim.cnc.mc.measured_mm) == pytest.approx(position, abs=0.01)


def test_a_hold_byte_in_noise_never_holds(link):
    """Issue 18: ``!`` is no command; noise holding one is a dropped frame at most."""
    lines = motion_program(30)
    # a frame sent while the machine runs (the window of 16 sends the first 16 at once)
    Tamper(link.sim, "usb_down", frame_of("D", 20), lambda line: b"~!~x\n!" + line)
    Tamper(link.sim, "usb_down", frame_of("D", 22), lambda line: line[:3] + b"!" + line[3:])
    start(link, lines)
    finish(link, lines)
    assert not [s for s in link.rec.of("on_status") if s.state == "HOLD"]


def test_a_real_hold_holds_and_noise_never_resumes_it(link):
    lines = motion_program(30)
    start(link, lines)
    assert link.run_until(lambda: link.sim.cnc.mc.state == "RUN", 10.0)
    link.session.pause()
    assert link.run_until(lambda: link.session.state is S.PAUSED, 1.0)
    link.port.write(bytes(range(256)) + b"\n" + b"!\x18" * 20 + b"\n")
    link.run_for(2.0)
    assert link.sim.cnc.mc.state == "HOLD" and link.session.status.why == "HOST"
    link.session.resume()
    finish(link, lines)


@pytest.mark.parametrize("wire", ["usb_down", "uart_down"])
def test_noise_never_starts_motion(link, wire):
    position = tuple(link.sim.cnc.mc.measured_mm)
    junk = bytes(b for b in range(256) if b != 0x0A)
    bursts = [junk, b"~" * 20, b"G01 X50\n", b"D 0 G01 X50*0000\n", b"C 99 JOG X 10 300\n", junk[::-1]]
    if wire == "usb_down":
        for burst in bursts:
            link.port.write(burst + b"\n")
            link.run_for(0.2)
    else:
        queue = list(bursts)
        Tamper(link.sim, wire, lambda line: line.startswith(b"C"), lambda line: queue.pop(0) + b"\n" + line,
               times=len(bursts))
        link.run_for(8.0)
    link.run_for(1.0)
    assert link.sim.cnc.mc.state == "IDLE"
    assert tuple(link.sim.cnc.mc.measured_mm) == pytest.approx(position, abs=0.01)
    assert link.executed() == []
    assert b"!" in junk and b"\x18" in junk
