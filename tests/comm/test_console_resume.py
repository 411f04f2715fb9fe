"""Issue 14 point 5: the console's ``resume`` works as the window's; ``RESUME FROM 3``
is no Python error; a machine that stops answering ends with the link-lost status (3).

The console runs on the simulator's clock: its pauses advance the simulation (no
threads, no sleeps), so every run is deterministic.
"""

import pytest

from app.comm.console import Console, ConsoleError, load_lines
from app.comm.transport import open_transport
from backend_sim import Simulator
from tests.comm.simlink import assert_oracle, dialect_program

LINES = dialect_program(60)


class Rig:
    """A simulator (not started) and consoles pumping it through their pauses."""

    def __init__(self, tmp_path) -> None:
        self.sim = Simulator(sd_dir=tmp_path / "sd", seed=4)
        self.path = tmp_path / "job.ngc"
        self.path.write_text("\n".join(LINES) + "\n")
        self.hooks = []

    def console(self) -> Console:
        transport = open_transport("sim://", do_not_open=True)  # the pyserial sim:// handler
        transport.simulator = self.sim  # this (unstarted) machine, driven by pause()
        transport.open()
        console = Console(transport, quiet=True, timeout=120.0, sleep=self.pause,
                          wall=lambda: self.sim.clock.now)
        console.connect()
        return console

    def pause(self, seconds: float) -> None:
        self.sim.run_for(seconds)
        for hook in list(self.hooks):
            hook()

    def cut_after(self, lines: int, seconds: float = 4.0) -> None:
        """Silence the USB hop both ways for ``seconds`` once ``lines`` have executed."""
        state = {}

        def hook():
            now = self.sim.clock.now
            if "until" not in state and len(self.sim.exec_log) >= lines:
                state["until"] = now + seconds
                self.sim.faults.set_rates("usb", drop=1.0)
            elif "until" in state and now >= state["until"]:
                self.sim.faults.clear()
                self.sim.faults.set_rates("usb", drop=0.0)
                self.hooks.remove(hook)

        self.hooks.append(hook)


@pytest.fixture
def rig(tmp_path):
    return Rig(tmp_path)


def test_machine_that_stops_answering_ends_with_link_lost(rig):
    console = rig.console()
    rig.sim.faults.set_rates("usb", "up", drop=1.0)
    with pytest.raises(ConsoleError, match="link lost") as info:
        console.do(["home"])
    assert info.value.code == 3


def test_resume_in_the_same_console_finishes_the_job(rig):
    console = rig.console()
    console.do(["check", "on"])
    rig.cut_after(10)
    with pytest.raises(ConsoleError) as info:
        console.do(["run", str(rig.path)])
    assert info.value.code == 3
    console.do(["resume"])
    assert console.printer.jobs[-1].completed
    assert_oracle(list(rig.sim.exec_log), load_lines(str(rig.path)))


def test_resume_file_in_a_new_console_finishes_the_job(rig):
    first = rig.console()
    first.do(["check", "on"])
    rig.cut_after(10, seconds=3.5)
    with pytest.raises(ConsoleError):
        first.do(["run", str(rig.path)])
    rig.pause(1.0)
    second = rig.console()
    second.do(["resume", str(rig.path)])
    assert second.printer.jobs[-1].completed
    assert_oracle(list(rig.sim.exec_log), load_lines(str(rig.path)))


@pytest.mark.parametrize("words", [["RESUME", "FROM", "3"], ["resume", "from", "x"], ["resume", "from"]])
def test_resume_from_is_a_clear_refusal_not_a_python_error(rig, words):
    console = rig.console()
    with pytest.raises(ConsoleError) as info:
        console.do(words)
    assert "RESUME" in str(info.value) or "resume" in str(info.value)
    assert "positional" not in str(info.value)
