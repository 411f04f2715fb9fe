"""The main MCU repairs the UART hop itself (issue 18): relayed D frames kept until the
CNC MCU acknowledges them, resent on its N and after 20 ms of silence without asking
the host; a host's copy of a frame already taken is answered at once; an unanswered
forwarded command goes down again for half a second."""

from __future__ import annotations

from app.comm.frame import Ack, Command, Data, Nak, Ok, seal
from backend_sim.relay import PROBE_S, REFORWARD_FOR_S, REFORWARD_S, DataRelay, Reforward
from tests.backend_sim.helpers import Host
from tests.comm.tamper import Tamper, frame_of


def test_data_relay_resends_probes_and_answers_copies():
    relay = DataRelay()
    relay.relayed(0, b"D0", 0.0)
    relay.relayed(1, b"D1", 0.0)
    assert relay.resend(1, 0.005) == b"D1"
    assert relay.resend(1, 0.01) is None  # at most every 20 ms
    assert relay.resend(1, 0.03) == b"D1"
    assert relay.probe(0.01) is None and relay.probe(0.021) == b"D0"  # the first kept frame
    relay.on_ack(Ack(0, 9), 0.03)
    assert relay.answer_for(0, 0.03) == [Ack(0, 9)] and relay.answer_for(1, 0.03) == []
    relay.relayed(3, b"D3", 0.03)
    relay.on_ack(Ack(1, 8), 0.04)  # 2 never came from the host, 3 is kept above the gap
    assert relay.answer_for(1, 0.05) == [Ack(1, 8), Nak(2)]
    assert relay.answer_for(1, 0.05) == [Ack(1, 8)]  # the gap is named once per burst
    assert relay.next_due() == 0.04 + PROBE_S


def test_reforward_goes_again_until_answered_for_half_a_second():
    forward = Reforward()
    cmd = Command(7, "GET", ("KP_X",))
    forward.start(cmd, 0.0)
    answered = {"yes": False}
    sent = [t / 1000 for t in range(0, 800, 5) if forward.take(t / 1000, lambda c: answered["yes"])]
    assert sent[0] == REFORWARD_S and len(sent) == int(REFORWARD_FOR_S / REFORWARD_S)
    forward.start(cmd, 1.0)
    answered["yes"] = True
    assert forward.take(1.05, lambda c: answered["yes"]) is None and forward.next_due(lambda c: True) is None


def test_a_d_frame_lost_on_the_uart_is_resent_by_the_main_mcu_alone(sim, host: Host):
    host.ok("SET CHECK 1")
    Tamper(sim, "uart_down", frame_of("D", 1), lambda line: b"")  # lost on the UART, once
    host.ok("JOB 3")
    before = sim.wires["usb_down"].sent
    for seq, line in enumerate(["G00 Z5", "G00 X1", "G00 X2"]):
        host.send(f"D {seq} {line}")
    sent = sim.wires["usb_down"].sent - before
    host.wait(lambda f: isinstance(f, Ack) and f.seq == 2)
    assert not host.of(Nak), "the host was asked to resend"
    assert sim.wires["usb_down"].sent - before == sent  # nothing more from the host
    assert [s for s, _ in sim.exec_log] == [0, 1, 2]


def test_a_host_copy_of_a_taken_frame_is_answered_without_the_uart(sim, host: Host):
    host.ok("SET CHECK 1")
    host.ok("JOB 5")
    host.send("D 0 G00 Z5")
    host.wait(lambda f: isinstance(f, Ack) and f.seq == 0)
    uart = sim.wires["uart_down"].sent
    host.port.write(seal(Data(0, "G00 Z5").body()))
    host.wait(lambda f: isinstance(f, Ack) and f.seq == 0, start=len(host.frames))
    assert sim.wires["uart_down"].sent == uart


def test_a_forwarded_command_lost_on_the_uart_is_sent_again_by_the_main_mcu(sim, host: Host):
    Tamper(sim, "uart_down", lambda line: line.startswith(b"C ") and b"GET" in line, lambda line: b"")
    host.heartbeat = False
    cid = host.command("GET KP_X")
    answer = host.answer(cid, timeout=0.2)  # long before a host would retry
    assert isinstance(answer, Ok)
