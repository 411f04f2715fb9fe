"""Issue 14 point 4: small protocol holes, each answered as docs/protocol.md says."""

import pytest

from app.comm.frame import Data, Error, FrameError, decimal
from app.comm.session import Session
from tests.backend_sim.test_main_mcu import PROGRAM


def test_d_frame_before_any_job_is_refused_bad_seq(sim, host):
    host.send(Data(0, "G00 X5").body())
    refusal = host.wait(lambda f: isinstance(f, Error) and f.id is None, timeout=1.0)
    assert refusal.code == "BAD_SEQ" and refusal.text.startswith("0 ")


def test_late_duplicate_of_a_finished_job_is_not_refused(sim, host):
    host.ok("SET CHECK 1")
    host.stream(PROGRAM)
    host.wait(lambda f: f.KIND == "L" and "job done" in f.text)
    host.send(Data(2, PROGRAM[2]).body())
    sim.run_for(0.5)
    host.pump()
    assert [f for f in host.frames if isinstance(f, Error)] == []


@pytest.mark.parametrize("value", ["nan", "inf", "-inf", "1_0", "0x1", "1e3", "2", ""])
def test_set_check_takes_only_0_or_1(sim, host, value):
    refusal = host.refused(f"SET CHECK {value}".strip())
    assert refusal.code in ("BAD_ARGS", "BAD_PARAM")


@pytest.mark.parametrize("text", ["JOG X 1_0 300", "JOG X inf 300", "JOG X nan 300", "JOG X 1 1_000",
                                  "JOG X 1e1 300", "SET KP_X nan", "SET FERR infinity", "SPINDLE 1_000"])
def test_numbers_follow_the_strict_grammar(sim, host, text):
    host.home()
    assert host.refused(text).code == "BAD_ARGS"


@pytest.mark.parametrize("crc", ["-1", "+1", "123456789", "0x12", "1_0", "zz"])
def test_sd_put_with_an_impossible_crc_is_refused(sim, host, crc):
    refusal = host.refused(f"SD PUT part.nc 1 {crc}")
    assert refusal.code == "BAD_ARGS"
    assert sim.main.upload is None


@pytest.mark.parametrize("text,value", [("0", 0.0), ("-1.5", -1.5), ("+2.", 2.0), (".5", 0.5), ("10", 10.0)])
def test_decimal_grammar_accepts(text, value):
    assert decimal(text, "x") == value


@pytest.mark.parametrize("text", ["1_0", "nan", "inf", "1e3", "", "-", ".", "١٢", "0x10", " 1", "1 "])
def test_decimal_grammar_refuses(text):
    with pytest.raises(FrameError, match="x"):
        decimal(text, "x")


def test_host_never_sends_a_non_finite_jog():
    session = Session()
    with pytest.raises(ValueError, match="distance"):
        session.jog("X", float("nan"), 300)


def test_homing_failed_is_documented():
    from pathlib import Path

    page = (Path(__file__).parents[2] / "docs" / "protocol.md").read_text(encoding="utf-8")
    assert "HOMING_FAILED" in page
