"""Issue 14 point 1: a retried command id is always answered; PING keeps the link alive.

A ``C`` frame lost on the UART hop after the main MCU forwarded it used to leave the
retries unanswered (swallowed as duplicates) until the host called the link lost.
"""

from tests.comm.simlink import FAST_HOMING, SimLink, assert_oracle, dialect_program


def test_home_lost_on_the_uart_down_hop_still_completes(tmp_path):
    link = SimLink(seed=5, sd_dir=tmp_path, check=False, profile=FAST_HOMING)
    link.sim.faults.drop("uart", "down")
    result = link.command("HOME", timeout=120.0)
    assert result.ok, result
    assert link.rec.of("on_error") == []
    assert link.session.link.state.value == "CONNECTED"


def test_job_command_lost_on_the_uart_down_hop_still_completes(tmp_path):
    link = SimLink(seed=5, sd_dir=tmp_path)
    lines = dialect_program(20)
    link.sim.faults.drop("uart", "down")
    job = link.run_job(lines, timeout=60.0)
    assert job.completed, job
    assert_oracle(link.executed(), lines)
    assert [e for e in link.rec.of("on_error") if e.code == "LINK_LOST"] == []


def test_ping_goes_out_every_second_while_a_command_is_outstanding(tmp_path):
    link = SimLink(seed=5, sd_dir=tmp_path, check=False, profile=FAST_HOMING)
    link.session.submit("HOME")
    times, seen = [], 0
    end = link.now + 5.0
    while link.now < end:
        link.step(0.01)
        pings = [e for e in link.rec.of("on_frame") if e.direction == "tx" and e.text.endswith(" PING")]
        times += [link.now] * (len(pings) - seen)
        seen = len(pings)
    assert link.session.commands.outstanding is not None, "HOME should still be running"
    assert len(times) >= 4, times
    assert all(b - a <= 1.05 for a, b in zip(times, times[1:], strict=False)), times
