"""Issue 14 point 3: an unfinished SD PUT is abandoned on host loss, STOP and reset;
its partial file is removed and the card's files are never touched by it."""

import pytest

from app.comm.frame import Data, Log, Ok
from backend_sim.sd_card import SdCard, crc32_of_lines
from tests.backend_sim.test_main_mcu import PROGRAM, put

OLD = ["G00 Z9", "G00 X1 Y1"]


def half_upload(sim, host) -> int:
    """``lock.ngc`` already on the card; a new upload of it cut off after two lines."""
    assert isinstance(put(host, "lock.ngc", OLD), Ok)
    cid = host.command(f"SD PUT lock.ngc {len(PROGRAM)} {crc32_of_lines(PROGRAM):08x}")
    for seq, line in enumerate(PROGRAM[:2]):
        host.send(Data(seq, line).body())
    sim.run_for(0.2)
    assert sim.main.upload is not None
    return cid


def card_is_clean(sim, tmp_path) -> None:
    folder = tmp_path / "sd"
    assert sorted(p.name for p in folder.iterdir()) == ["lock.ngc"], "a partial file was left"
    assert (folder / "lock.ngc").read_text() == "\n".join(OLD) + "\n"
    assert sim.main.upload is None


def the_card_works_again(host) -> None:
    assert isinstance(put(host, "other.ngc", PROGRAM), Ok)
    host.ok("SD LIST")


def abandon_by_stop(sim, host):
    host.ok("STOP")


def abandon_by_realtime_stop(sim, host):
    assert isinstance(host.answer(host.realtime("STOP")), Ok)
    sim.run_for(0.3)


def abandon_by_reset(sim, host):
    host.ok("RESET")
    sim.run_for(0.5)


def abandon_by_host_loss(sim, host):
    host.heartbeat = False
    sim.run_for(3.5)
    host.heartbeat = True


@pytest.mark.parametrize("abandon", [abandon_by_stop, abandon_by_realtime_stop, abandon_by_reset,
                                     abandon_by_host_loss])
def test_unfinished_upload_is_abandoned(sim, host, tmp_path, abandon):
    half_upload(sim, host)
    abandon(sim, host)
    card_is_clean(sim, tmp_path)
    host.pump()
    assert any(isinstance(f, Log) and "abandoned" in f.text for f in host.frames)
    the_card_works_again(host)


def test_partial_files_of_a_crash_are_removed_when_the_card_is_mounted(tmp_path):
    (tmp_path / ".x.ngc.part").write_bytes(b"G00 X1\n")
    (tmp_path / "keep.ngc").write_bytes(b"G00 X1\n")
    card = SdCard(tmp_path)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["keep.ngc"]
    assert card.names() == ["keep.ngc"]
