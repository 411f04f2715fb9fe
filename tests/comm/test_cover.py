"""The cover interlock, end to end: Session <-> simulator (issue 11).

No motion and no spindle while the cover is open: a job holds and its spindle stops
(0 rpm within 1 s); every command that would move or spin is answered ``COVER_OPEN``
within 100 ms, homing included (also when the cover opens during homing); closing
restarts nothing; RESUME brings the spindle back to speed before the job moves on;
the link never looks lost meanwhile. The spindle reading decays to 0 after OFF.
"""

from __future__ import annotations

from tests.comm.simlink import FAST_HOMING, SimLink, assert_oracle

PROGRAM = ["M03 S3000", "G00 Z5", "G00 X10 Y10", "G01 Z-1 F300", "G01 X120 F200", "G01 Y60",
           "G00 Z5", "M05", "M02"]
REFUSED = [("HOME",), ("HOME", "RECOVER"), ("JOG", "X", "1", "300"), ("SPINDLE", "1000"),
           ("JOB", "3"), ("RESUME",)]


def _link(tmp_path) -> SimLink:
    link = SimLink(check=False, profile=FAST_HOMING, sd_dir=tmp_path)
    link.home()
    return link


def _rpm(link: SimLink) -> int:
    return link.session.status.rpm


def _answered_within(link: SimLink, verb: str, *args, limit: float = 0.1):
    start = link.now
    result = link.command(verb, *args, timeout=1.0)
    return result, link.now - start


def _no_link_alert(link: SimLink) -> bool:
    return all(event.state == "CONNECTED" for event in link.rec.of("on_link_changed")[1:])


def test_cover_holds_the_job_stops_the_spindle_and_resume_spins_up_first(tmp_path):
    link = _link(tmp_path)
    assert link.session.start_job(PROGRAM)
    assert link.run_until(lambda: link.session.status.done >= 3 and _rpm(link) > 2500, 60.0)
    link.sim.faults.open_cover()
    opened = link.now
    assert link.run_until(lambda: _rpm(link) == 0 and link.session.status.state == "HOLD", 1.0)
    assert link.now - opened <= 1.0
    for verb, *args in REFUSED:  # every verb that moves or spins
        result, took = _answered_within(link, verb, *args)
        assert not result.ok and result.code == "COVER_OPEN" and took <= 0.1, (verb, result, took)
    for verb in ("PING", "STATUS"):
        result, took = _answered_within(link, verb)
        assert result.ok and took <= 0.1
    link.sim.faults.close_cover()
    link.run_for(2.0)  # closing restarts nothing
    assert link.session.status.state == "HOLD" and _rpm(link) == 0
    done = link.session.status.done
    assert link.session.resume()
    assert link.run_until(lambda: link.session.status.state == "RUN", 10.0)
    assert _rpm(link) > 2800  # at speed before it moves
    assert link.session.status.done == done
    assert link.run_until(lambda: link.rec.of("on_job_finished"), 120.0)
    assert link.rec.last("on_job_finished").completed
    assert_oracle(link.executed(), PROGRAM)
    assert _no_link_alert(link)


def test_cover_during_homing_stops_it_with_an_error_and_jog_works_after_closing(tmp_path):
    link = SimLink(check=False, profile=FAST_HOMING, sd_dir=tmp_path)
    cid = link.session.submit("HOME", "NORMAL")
    link.run_for(0.3)
    link.sim.faults.open_cover()
    opened = link.now
    found = lambda: [r for r in link.rec.of("on_command_done") if r.id == cid]  # noqa: E731
    assert link.run_until(lambda: bool(found()), 1.0)
    assert found()[0].code == "COVER_OPEN" and link.now - opened <= 0.1
    assert not link.session.status.homed
    assert link.run_until(lambda: link.session.status.state == "IDLE", 1.0)  # stopped on the path
    link.sim.faults.close_cover()
    assert link.command("JOG", "X", "1", "300").ok  # not BUSY
    spin = link.command("SPINDLE", "2000")  # the cover was opened with a spindle command too
    assert spin.ok
    link.home()
    assert link.run_until(lambda: link.session.status.homed, 1.0) and _no_link_alert(link)


def test_spindle_reading_decays_to_zero_within_2_s_of_off(tmp_path):
    link = _link(tmp_path)
    link.command_ok("SPINDLE", "3000")
    link.run_for(1.0)
    assert _rpm(link) > 2800
    link.command_ok("SPINDLE", "OFF")
    off = link.now
    assert link.run_until(lambda: _rpm(link) == 0, 2.0), _rpm(link)
    assert link.now - off <= 2.0
    link.run_for(2.0)
    assert _rpm(link) == 0 and link.sim.cnc.status().rpm == 0
