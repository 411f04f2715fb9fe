"""Issue 18 point 2: a hold the host did not ask for is never silent.

The machine says in its status why it holds (``why``), the session reports it once
(``on_hold``, logged), and the console prints it and waits for the operator, or ends
the job with its own exit status under ``--at-stops stop``. All on simulated time.
"""

import pytest

from app.comm.console import Console, ConsoleError
from app.comm.console_jobs import HELD_EXIT
from app.comm.listener import SessionState
from app.comm.transport import open_transport
from backend_sim import Simulator
from tests.comm.simlink import FAST_HOMING, SimLink

S = SessionState
MOVES = ["G00 Z5", "G00 X10 Y10"] + [f"G01 X{10 + 20 * (i % 2)} Y{10 + i} F900" for i in range(40)]


@pytest.fixture
def link(tmp_path):
    link = SimLink(seed=5, sd_dir=tmp_path, check=False, profile=FAST_HOMING)
    link.home()
    return link


def running(link, lines=MOVES) -> None:
    assert link.session.start_job(lines)
    assert link.run_until(lambda: link.sim.cnc.mc.state == "RUN" and len(link.executed()) > 2, 20.0)


def holds(link, why: str, state: str = "HOLD", timeout: float = 5.0):
    found = lambda: [h for h in link.rec.of("on_hold") if h.why == why and h.state == state]  # noqa: E731
    assert link.run_until(lambda: bool(found()), timeout), link.rec.of("on_hold")
    return found()[0]


def press(link, *buttons: str) -> None:
    for button in buttons:
        link.sim.panel.press(button)


def test_a_panel_pause_says_panel_and_is_logged(link):
    running(link)
    press(link, "OK", "DOWN", "OK")  # menu > Pause
    hold = holds(link, "PANEL")
    assert hold.source == "panel" and not hold.asked and "panel" in hold.text
    assert link.session.status.why == "PANEL" and link.session.state is S.PAUSED
    assert any("the machine holds (the machine's panel)" in e.text for e in link.rec.of("on_log"))
    link.session.resume()
    assert link.run_until(lambda: link.rec.last("on_hold").why == "", 2.0)
    assert link.session.state is S.STREAMING


def test_the_cover_says_cover(link):
    running(link)
    link.sim.faults.open_cover()
    hold = holds(link, "COVER")
    assert hold.source == "cover" and "cover" in hold.text


def test_a_lost_host_holds_with_link_by_an_r_frame(link):
    running(link)
    link.session.detach("cable pulled")
    assert link.sim.run_until(lambda: link.sim.cnc.mc.state == "HOLD", 5.0)
    assert link.sim.cnc.why == "LINK"  # the main MCU's own R HOLD LINK
    assert link.sim.cnc.status().why == "LINK"


def test_a_program_stop_says_prog_and_the_host_sees_it_once(link):
    running(link, MOVES[:6] + ["M00"] + MOVES[6:10])
    hold = holds(link, "PROG", timeout=20.0)
    assert hold.source == "program"
    link.run_for(1.0)
    assert len([h for h in link.rec.of("on_hold") if h.why == "PROG"]) == 1


def test_a_line_past_the_soft_limits_says_soft(link):
    job = link.run_job(MOVES[:4] + ["G01 X400 F900"], timeout=30.0)
    assert not job.completed
    hold = holds(link, "SOFT", state="IDLE")
    assert "soft limits" in hold.text and not hold.asked


def test_the_host_s_own_hold_says_host_and_is_asked(link):
    running(link)
    link.session.pause()
    hold = holds(link, "HOST")
    assert hold.asked and not [e for e in link.rec.of("on_log") if "the machine holds" in e.text]
    link.session.stop()
    assert link.run_until(lambda: link.session.state is S.READY, 5.0)
    assert link.rec.last("on_job_finished").reason == "stopped by the operator"


# ---------------------------------------------------------------------- the console


class Rig:
    """A simulator (not started) and a console pumping it through its pauses."""

    def __init__(self, tmp_path, at_stops: str) -> None:
        self.sim = Simulator(profile=FAST_HOMING, sd_dir=tmp_path / "sd", seed=4)
        self.path = tmp_path / "job.ngc"
        self.path.write_text("G21 G90\n" + "\n".join(MOVES) + "\n")
        self.hooks = []
        transport = open_transport("sim://", do_not_open=True)
        transport.simulator = self.sim
        transport.open()
        self.console = Console(transport, quiet=True, timeout=300.0, at_stops=at_stops, sleep=self.pause,
                               wall=lambda: self.sim.clock.now)
        self.console.out = self.console.printer.out = self.lines = _Lines()
        self.console.connect()

    def pause(self, seconds: float) -> None:
        self.sim.run_for(seconds)
        for hook in list(self.hooks):
            hook()

    def when(self, predicate, action) -> None:
        def hook():
            if predicate():
                self.hooks.remove(hook)
                action()

        self.hooks.append(hook)


class _Lines(list):
    def write(self, text: str) -> None:
        self.extend(line for line in text.splitlines() if line)

    def flush(self) -> None:
        pass


def test_console_prints_the_hold_and_exits_4_under_at_stops_stop(tmp_path):
    rig = Rig(tmp_path, "stop")
    rig.when(lambda: len(rig.sim.exec_log) > 5, rig.sim.faults.open_cover)
    with pytest.raises(ConsoleError) as raised:
        rig.console.cmd_run(str(rig.path))
    assert raised.value.code == HELD_EXIT and "COVER" in str(raised.value)
    said = [line for line in rig.lines if line.startswith("machine HOLDS")]
    assert said and "[COVER, cover]: the cover is open" in said[0]


def test_console_waits_for_the_operator_under_continue(tmp_path):
    rig = Rig(tmp_path, "continue")
    panel = rig.sim.panel

    def operator_resumes():
        rig.when(lambda: True, lambda: [panel.press(b) for b in ("OK", "DOWN", "DOWN", "OK")])  # Resume

    rig.when(lambda: len(rig.sim.exec_log) > 5, lambda: ([panel.press(b) for b in ("OK", "DOWN", "OK")],
                                                          rig.when(lambda: rig.sim.cnc.why == "PANEL",
                                                                   operator_resumes)))
    rig.console.cmd_run(str(rig.path))
    text = "\n".join(rig.lines)
    assert "machine HOLDS [PANEL, panel]" in text and "waiting for the operator at the machine" in text
    assert "machine: running again" in text and "job completed" in text
