"""The CNC MCU's side of docs/protocol.md, in process through ``sim.host_port``."""

from __future__ import annotations

from app.comm.frame import Ack, Alarm, Data, Error, Finished, Log, Nak, Ok, Status, seal
from tests.backend_sim.helpers import Host

LINES = ["G00 Z5", "G00 X10 Y10", "G01 Z4 F600", "G01 X14 Y10", "G01 X14 Y14", "G00 Z5"]


def last_status(host: Host) -> Status:
    return host.of(Status)[-1]


def finished_all(host: Host, n: int, timeout: float = 120.0) -> None:
    host.wait(lambda f: isinstance(f, Finished) and f.seq == n - 1, timeout)


def test_ping_answers_a_status_and_every_frame_has_a_good_crc(host):
    host.ok("GET KP_X")
    status = last_status(host)
    assert status.state == "IDLE" and status.acc == -1 and status.done == -1
    assert not status.has("H")
    assert host.dropped == []


def test_a_job_is_acked_and_finished_cumulatively_and_logged(sim, host):
    host.home()
    host.stream(LINES)
    finished_all(host, len(LINES))
    acks = [f.seq for f in host.of(Ack)]
    assert acks == sorted(acks) and acks[-1] == len(LINES) - 1
    fins = [f.seq for f in host.of(Finished)]
    assert fins == sorted(fins) and fins[-1] == len(LINES) - 1
    assert sim.exec_log.entries == list(enumerate(LINES))
    host.wait(lambda f: isinstance(f, Log) and "job done" in f.text)
    assert host.dropped == []


def test_status_at_least_every_50_ms_while_moving(sim, host):
    host.home()
    start = len(host.frames)
    host.stream(["G01 X30 F600"])
    finished_all(host, 1)
    times = [t for f, t in zip(host.frames[start:], host.times[start:], strict=True)
             if isinstance(f, Status) and f.state == "RUN"]
    assert len(times) > 20
    assert max(b - a for a, b in zip(times, times[1:], strict=False)) <= 0.052


def test_duplicate_is_reacked_and_a_gap_is_naked_once(sim, host):
    host.home()
    host.ok("JOB 5")
    host.send("D 0 G00 Z5")
    host.send("D 0 G00 Z5")
    host.send("D 2 G00 Z6")
    host.send("D 3 G00 Z7")
    sim.run_for(0.2)
    assert [f.seq for f in host.of(Ack)] == [0, 0]
    assert [f.seq for f in host.of(Nak)] == [1]
    host.send("D 1 G00 Z4")
    host.wait(lambda f: isinstance(f, Ack) and f.seq == 1)


def test_every_seq_seen_missing_is_naked_at_once(sim, host):
    host.home()
    host.ok("JOB 12")
    host.send("D 0 G00 Z5")
    host.send("D 2 G00 Z6")  # 1 missing: N 1 (the gap)
    host.send("D 3 G00 Z7")  # nothing new missing
    host.send("D 6 G00 Z8")  # 4 and 5 missing above the gap: named now, not after 1 is filled
    sim.run_for(0.2)
    assert [f.seq for f in host.of(Nak)] == [1, 4, 5]
    for seq, z in ((1, 4), (4, 3), (5, 2)):
        host.send(f"D {seq} G00 Z{z}")
    host.wait(lambda f: isinstance(f, Ack) and f.seq == 6)


def test_a_probe_while_frames_are_kept_is_answered_with_what_is_missing(sim, host):
    host.home()
    host.ok("JOB 8")
    host.send("D 0 G00 Z5")
    host.send("D 1 G00 Z6")
    host.send("D 3 G00 Z7")  # 2 missing, 3 kept
    sim.run_for(0.2)
    naks = len(host.of(Nak))
    host.send("D 1 G00 Z6")  # the host's probe (its A 1 was lost): A 1 and N 2
    host.send("D 1 G00 Z6")  # same burst: A again only
    sim.run_for(0.2)
    assert [f.seq for f in host.of(Ack)][-2:] == [1, 1]
    assert [f.seq for f in host.of(Nak)][naks:] == [2]


def test_bad_crc_is_naked_with_the_expected_seq(sim, host):
    host.home()
    host.ok("JOB 3")
    host.send("D 0 G00 Z5")
    frame = bytearray(seal("D 1 G00 Z6"))
    frame[5] ^= 0x01
    host.port.write(bytes(frame))
    nak = host.wait(lambda f: isinstance(f, Nak))
    assert nak.seq == 1


def test_motion_before_homing_is_refused_but_jog_is_allowed(sim, host):
    assert host.refused("JOB 2").code == "NOT_HOMED"
    host.ok("JOG X 1 300")
    assert sim.cnc.mc.state == "IDLE"


def test_soft_limit_names_axis_and_direction_before_moving(sim, host):
    host.home()
    host.ok("JOB 2")
    host.send("D 0 G00 X200")
    err = host.wait(lambda f: isinstance(f, Error))
    assert err.id is None and err.code == "SOFT_LIMIT" and err.text.startswith("0 X+ 200.000 > 150")
    assert not sim.cnc.job.open and sim.exec_log.entries == []


def test_bad_line_and_unknown_verb_and_busy(sim, host):
    assert host.refused("FROB").code == "UNKNOWN_VERB"
    host.home()
    host.ok("JOB 3")
    host.send("D 0 G01 X10 F600")
    host.wait(lambda f: isinstance(f, Ack))
    assert host.refused("HOME").code == "BUSY"
    host.send("D 1 G07 X1")
    err = host.wait(lambda f: isinstance(f, Error) and f.id is None)
    assert err.code == "BAD_LINE" and err.text.startswith("1 ")
    assert not sim.cnc.job.open


def test_cover_open_refuses_motion_and_holds_a_running_job(sim, host):
    sim.panel.set_cover(True)
    assert host.refused("HOME").code == "COVER_OPEN"
    sim.panel.set_cover(False)
    host.home()
    host.stream(["G01 X40 F600", "G01 X0"])
    host.wait(lambda f: isinstance(f, Status) and f.state == "RUN")
    sim.faults.open_cover()
    host.wait(lambda f: isinstance(f, Alarm) and f.code == "COVER_OPEN")
    host.wait(lambda f: isinstance(f, Status) and f.state == "HOLD" and f.has("C"))
    assert host.refused("RESUME").code == "COVER_OPEN"
    sim.faults.close_cover()
    host.ok("RESUME")
    finished_all(host, 2)


def test_repeated_command_id_resends_the_first_answer(sim, host):
    host.send("C 50 SET KP_X 5")
    first = host.answer(50)
    host.send("C 50 SET KP_X 9")
    sim.run_for(0.1)
    answers = [f for f in host.of(Ok) if f.id == 50]
    assert answers == [first, first]
    assert sim.cnc.mc.get_param("KP_X") == 5


def test_check_mode_finishes_lines_without_moving(sim, host):
    host.ok("SET CHECK 1")
    before = sim.cnc.mc.measured_mm
    host.stream(LINES)
    finished_all(host, len(LINES), timeout=5)
    assert sim.cnc.mc.measured_mm == before
    assert host.ok("GET CHECK").info == "CHECK 1"


def test_pause_answers_when_held_then_resume_finishes(sim, host):
    host.home()
    host.stream(["G01 X40 F600"])
    host.wait(lambda f: isinstance(f, Status) and f.state == "RUN" and f.x > 5)
    ok = host.ok("PAUSE")
    assert ok.verb == "PAUSE" and sim.cnc.mc.state == "HOLD"
    x = sim.cnc.mc.measured_mm[0]
    sim.run_for(1.0)
    assert abs(sim.cnc.mc.measured_mm[0] - x) < 0.01
    host.ok("RESUME")
    finished_all(host, 1)


def test_realtime_commands_hold_and_stop_once_per_id(sim, host):
    host.home()
    host.stream(["G01 X40 F600", "G01 X0"])
    host.wait(lambda f: isinstance(f, Status) and f.state == "RUN" and f.x > 5)
    hold = host.realtime("HOLD")
    assert host.answer(hold) == Ok(hold, "HOLD", "HOLD")
    status = host.wait(lambda f: isinstance(f, Status) and f.state == "HOLD")
    assert status.why == "HOST"
    resume = host.realtime("RESUME")
    assert isinstance(host.answer(resume), Ok)
    host.wait(lambda f: isinstance(f, Status) and f.state == "RUN" and not f.why)
    start = len(host.frames)
    host.send(f"R {hold} HOLD")  # a late copy of the first hold: answered again, not carried out
    host.wait(lambda f: isinstance(f, Ok) and f.id == hold, start=start)
    sim.run_for(0.2)
    assert sim.cnc.mc.state == "RUN"
    stop = host.realtime("STOP")
    assert isinstance(host.answer(stop), Ok)
    status = host.wait(lambda f: isinstance(f, Status) and f.state == "IDLE")
    assert not sim.cnc.job.open and status.why == "HOST"


def test_legacy_bytes_are_counted_and_logged_never_acted_on(sim, host):
    host.home()
    host.stream(["G01 X40 F600", "G01 X0"])
    host.wait(lambda f: isinstance(f, Status) and f.state == "RUN" and f.x > 5)
    host.port.write(b"!\x18!")
    log = host.wait(lambda f: isinstance(f, Log) and f.text.startswith("ignored"))
    assert log.text == "ignored 3 real-time byte(s) (use R frames)"
    assert sim.cnc.mc.state == "RUN" and sim.cnc.job.open and sim.main.legacy.total == 3
    sim.main.uart_tx.write(b"\x18!", sim.clock.now)  # straight onto the UART: the CNC MCU ignores them too
    host.wait(lambda f: isinstance(f, Log) and f.text == "ignored 2 real-time byte(s) (use R frames)")
    assert sim.cnc.mc.state == "RUN" and sim.cnc.legacy.total == 2


def test_reset_gives_a_new_boot_and_forgets_homing(sim, host):
    host.home()
    boot = last_status(host).boot
    host.ok("RESET")
    status = host.wait(lambda f: isinstance(f, Status) and f.boot != boot)
    assert not status.has("H")


def test_resume_from_after_a_lost_host(sim, host):
    lines = [f"G01 X{10 + i} F300" for i in range(12)]
    host.home()
    host.stream(lines, count=6)
    host.heartbeat = False
    host.wait(lambda f: isinstance(f, Alarm) and f.code == "HOST_LOST", timeout=5)
    host.wait(lambda f: isinstance(f, Status) and f.state == "HOLD" and f.has("L"))
    host.heartbeat = True
    acc = sim.cnc.job.acc
    host.ok(f"RESUME FROM {acc + 1}")
    assert host.refused("RESUME FROM 0").code == "BAD_SEQ"
    for seq in range(acc + 1, len(lines)):
        host.send(Data(seq, lines[seq]).body())
    finished_all(host, len(lines))
    assert [s for s, _ in sim.exec_log] == list(range(len(lines)))


def test_spindle_and_zero(sim, host):
    host.home()
    host.ok("SPINDLE 3000")
    host.wait(lambda f: isinstance(f, Status) and f.has("P") and f.rpm > 2500, timeout=10)
    host.ok("SPINDLE OFF")
    assert sim.cnc.mc.state == "IDLE"
    ok = host.ok("ZERO XY")
    assert ok.info.startswith("X0.000 Y0.000")
    assert host.refused("ZERO Q").code == "BAD_ARGS"


def test_exec_log_file(tmp_path):
    from backend_sim.simulator import Simulator
    from tests.backend_sim.conftest import FAST_HOMING

    path = tmp_path / "exec.log"
    sim = Simulator(FAST_HOMING, sd_dir=tmp_path / "sd", seed=3, exec_log=path)
    host = Host(sim)
    host.home()
    host.stream(LINES[:3])
    finished_all(host, 3)
    assert path.read_text().splitlines() == [f"{i}\t{line}" for i, line in enumerate(LINES[:3])]


def test_simple_mode_runs_the_same_protocol(tmp_path):
    from backend_sim.simulator import Simulator
    from tests.backend_sim.conftest import FAST_HOMING

    sim = Simulator(FAST_HOMING, sd_dir=tmp_path / "sd", seed=4, mode="simple")
    host = Host(sim)
    host.home()
    host.stream(LINES)
    finished_all(host, len(LINES))
    assert [s for s, _ in sim.exec_log] == list(range(len(LINES)))


def test_work_offset_survives_reset_and_restart(tmp_path):
    from backend_sim.simulator import Simulator
    from tests.backend_sim.conftest import FAST_HOMING

    sim = Simulator(FAST_HOMING, sd_dir=tmp_path / "sd", seed=5)
    host = Host(sim)
    host.home()
    host.ok("JOG X 12 600")
    assert host.ok("ZERO X").info.startswith("X12.000 Y0.000 Z20.000")
    host.ok("RESET")
    sim.run_for(0.1)
    assert sim.cnc.offset[0] == 12.0
    again = Simulator(FAST_HOMING, sd_dir=tmp_path / "sd", seed=6)
    assert again.cnc.offset == sim.cnc.offset
    assert again.sd.names() == []
    (tmp_path / "sd" / ".flash.json").write_text("{broken")
    assert Simulator(FAST_HOMING, sd_dir=tmp_path / "sd").cnc.offset == (0.0, 0.0, 20.0)
