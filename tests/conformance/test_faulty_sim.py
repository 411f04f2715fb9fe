"""A deliberately faulty machine breaks one rule of docs/protocol.md at a time; the kit
names that rule (and the honest machine passes the same sections)."""

import pytest

from app.comm.frame import Nak
from backend_sim import cnc_commands
from tests.conformance.helpers import failures


def wrong_crc_in_statuses(sim):
    """Every status the machine sends carries a CRC off by one."""
    deliver = sim.host_port.deliver

    def corrupt(data: bytes) -> None:
        out = bytearray()
        for line in data.split(b"\n"):
            if line.startswith(b"S ") and line[-5:-4] == b"*":
                line = line[:-1] + (b"0" if line[-1:] != b"0" else b"1")
            out += line + b"\n"
        deliver(bytes(out[:-1]))

    sim.host_port.deliver = corrupt


def no_n_for_a_gap(sim):
    """The CNC MCU keeps frames above a gap but never asks for the missing one."""
    send = sim.cnc.send
    sim.cnc.send = lambda frame: None if isinstance(frame, Nak) else send(frame)


def late_host_lost(sim):
    sim.main.lost_s = 5.0


def early_host_lost(sim):
    sim.main.lost_s = 2.0


def no_selective_repeat(sim):
    """Frames above a gap are thrown away (the machine is go-back-N only)."""
    sim.cnc.job.keep = lambda seq, line, free: []


def lenient_set_choices(monkeypatch):
    def patch(sim):
        monkeypatch.setattr(cnc_commands.value_ranges, "set_value", lambda name, text: None)
    return patch


def duplicate_run_twice(sim):
    """A duplicate D frame below expected is queued again instead of re-acked (the main
    MCU passes every copy down rather than answering it from what it knows)."""
    sim.main.relay.answer_for = lambda seq, now: []
    offer = sim.cnc.job.offer

    def offer_again(seq):
        verdict = offer(seq)
        return type(verdict).QUEUE if verdict.name == "REACK" else verdict

    sim.cnc.job.offer = offer_again


def forgets_realtime_ids(sim):
    """Both MCUs forget every R id at once: a repeated R STOP is carried out again."""
    for recent in (sim.main.urgent.recent, sim.cnc.recent):
        recent.remembers = lambda rid: False
        recent.answers = lambda rid: []


def no_dead_man(sim):
    """A continuous jog runs on without keep-alives (to the end of its travel)."""
    tick = sim.cnc.jogging.tick

    def tick_without_dead_man():
        running = sim.cnc.jogging.running
        if running is not None:
            running.deadline_ms = sim.cnc.clock.now_ms + 10**9
        tick()

    sim.cnc.jogging.tick = tick_without_dead_man


def work_positions_ignore_the_system(monkeypatch):
    """`SET WCS` is stored but the work positions keep the old system's offset."""
    from backend_sim import flash, work_systems

    def store(mcu):
        mcu.flash.save_systems(mcu.systems, mcu.wcs)
        mcu.reset_parser()

    def patch(sim):
        assert flash.SYSTEMS  # the module the patch stands in for is the one the machine uses
        monkeypatch.setattr(work_systems, "store", store)
    return patch


CASES = [
    (wrong_crc_in_statuses, ["frames"], "frames.machine-frames-valid"),
    (no_n_for_a_gap, ["stream"], "stream.gap-answered-n"),
    (late_host_lost, ["link"], "link.host-lost-after-3s"),
    (early_host_lost, ["link"], "link.host-lost-after-3s"),
    (no_selective_repeat, ["stream"], "stream.selective-repeat"),
    (duplicate_run_twice, ["stream"], "stream.duplicate-reacked"),
    (forgets_realtime_ids, ["realtime"], "realtime.repeat-not-executed"),
    (forgets_realtime_ids, ["overrides"], "overrides.repeat-not-taken"),
    (no_dead_man, ["jog"], "jog.dead-man"),
]


@pytest.mark.parametrize("patch,sections,rule", CASES, ids=[c[0].__name__ for c in CASES])
def test_the_kit_names_the_broken_rule(tmp_path, patch, sections, rule):
    failed = failures(tmp_path, sections, patch)
    assert rule in failed, f"the kit missed {rule}; it failed {sorted(failed)}"
    result = failed[rule]
    assert result.rule and result.section and (result.got or result.note)


def test_a_repeated_override_is_judged_once_the_first_id_s_copies_are_answered(tmp_path, monkeypatch):
    """Copies of the first id still on their way when its answer came (a slow host or
    wire) kept the main MCU forwarding that id, so it dropped the repeat: the kit passed a
    machine that takes repeats (1 run in 3 of the suite under load). Now it waits for them;
    the honest machine still passes."""
    from app.comm.conformance.link import Link

    realtime = Link.realtime

    def with_late_copies(self, verb, timeout=5.0, cid=None):
        sent = realtime(self, verb, timeout, cid)
        if verb == "FEED 120":
            for _ in range(3):
                self.send(f"R {sent[0]} FEED 120")
        return sent

    monkeypatch.setattr(Link, "realtime", with_late_copies)
    assert "overrides.repeat-not-taken" in failures(tmp_path / "broken", ["overrides"], forgets_realtime_ids)
    assert failures(tmp_path / "honest", ["overrides"]) == {}


def test_the_kit_names_a_lenient_set_grammar(tmp_path, monkeypatch):
    failed = failures(tmp_path, ["errors"], lenient_set_choices(monkeypatch))
    assert {"errors.set-choice-minus-zero", "errors.set-choice-point",
            "errors.set-choice-leading-zero"} <= set(failed), sorted(failed)


def test_the_kit_names_work_positions_that_ignore_the_system(tmp_path, monkeypatch):
    failed = failures(tmp_path, ["systems"], work_positions_ignore_the_system(monkeypatch))
    assert "systems.work-position-follows" in failed, sorted(failed)


@pytest.mark.parametrize("sections", [["frames"], ["stream"], ["link"], ["errors"], ["realtime"],
                                      ["overrides", "systems", "jog"]])
def test_the_honest_machine_passes_the_same_sections(tmp_path, sections):
    assert failures(tmp_path, sections) == {}
