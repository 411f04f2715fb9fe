"""Issue 14 point 1, machine side: a repeated command id is answered, never run twice."""

from app.comm.frame import Ok, Status
from tests.comm.tamper import Tamper


def lose_answer(sim, cid: int) -> Tamper:
    """Drop the CNC MCU's ``O``/``E`` of command ``cid`` on the UART up-hop."""
    heads = (f"O {cid} ".encode(), f"E {cid} ".encode())
    return Tamper(sim, "uart_up", lambda line: line.startswith(heads), lambda line: b"")


def jogged_x(sim, host, extra: str = "") -> float:
    """Jog X by 5 mm with its answer lost, retry the same id (after ``extra``); X moved."""
    host.home()
    x0 = sim.cnc.status().x
    cid = host.next_id
    tamper = lose_answer(sim, cid)
    host.command("JOG X 5 600")
    sim.run_for(3.0)
    assert tamper.hits == 1
    if extra:
        host.command(extra)
        host.wait(lambda f: isinstance(f, Status))
    host.send(f"C {cid} JOG X 5 600")
    answer = host.answer(cid, timeout=3.0)
    assert isinstance(answer, Ok), answer
    sim.run_for(3.0)
    return sim.cnc.status().x - x0


def test_cnc_mcu_answers_a_repeated_id_with_its_cached_answer(sim, host):
    assert abs(jogged_x(sim, host) - 5.0) < 0.05


def test_ping_does_not_replace_the_remembered_id(sim, host):
    assert abs(jogged_x(sim, host, "PING") - 5.0) < 0.05


def test_main_mcu_forwards_a_retry_whose_first_copy_was_lost(sim, host):
    sim.faults.drop("uart", "down")  # the first copy never reaches the CNC MCU
    cid = host.command("SET CHECK 1")
    sim.run_for(0.3)
    host.send(f"C {cid} SET CHECK 1")
    answer = host.answer(cid, timeout=3.0)
    assert isinstance(answer, Ok) and answer.info == "CHECK 1"
