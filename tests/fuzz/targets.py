"""Fuzz targets of issue 14 (point 10), shared by the suite and ``bench/bench_fuzz.py``.

Each target takes one generated input and checks that nothing but the documented
error type comes out: the G-code loader (text and bytes: never raises, diagnostics
name a line), the deframer and the codec (host and machine side: ``Frame``,
``Dropped`` or ``Legacy`` items; ``decode`` raises only ``FrameError`` and what it
returns encodes back to the same body), the machine's command parser (frames fed to a
running simulator: it answers and never raises), the CNC MCU's dialect parser (only
``DialectError``), and the profile and settings loaders (never raise; every value in
range). ``TARGETS`` maps a name to (strategy, function).
"""

from __future__ import annotations

import atexit
import contextlib
import math
import os
import shutil
import tempfile
from dataclasses import fields
from pathlib import Path

from hypothesis import strategies as st

from app.comm import frame as fr
from app.comm.deframer import Deframer, Dropped, Legacy
from app.gcode import load, load_text
from app.profile import MachineProfile, read_profile
from app.ui.settings.store import load_settings
from backend_sim.motion.dialect import DialectError, DialectParser

GCODE_ALPHABET = "GMXYZIJKFRPSTNgmxyz0123456789.-+ \t()%;*/#[]\r\n\ufeffé_eE"
GCODE_WORDS = ["G0", "G1", "G2", "G3", "G4", "G20", "G21", "G90", "G91", "G17", "G18", "G19", "M3", "M5",
               "M2", "X1", "Y-2.5", "Z.5", "I5", "J0", "F100", "F-1", "F0.0000001", "S-5", "P3", "R2",
               "X" + "9" * 30, "P1" + "0" * 40, " ", "\n", "\r", "\r\n", "(c)", ";x", "%", "1_0", "inf"]
gcode_text = st.one_of(
    st.text(alphabet=GCODE_ALPHABET, max_size=300),
    st.lists(st.sampled_from(GCODE_WORDS), max_size=40).map("".join),
    st.text(max_size=100),
)
FRAME_BYTES = b"DCRANFOESXIL0123456789 -*.\n\r!\x18ABCDEF"
frame_bytes = st.one_of(
    st.binary(max_size=300),
    st.lists(st.sampled_from([bytes([b]) for b in FRAME_BYTES]), max_size=150).map(b"".join),
    st.lists(st.sampled_from([b"D 0 G00 X1*", b"A 1 16*", b"\n", b"S 1 IDLE 0.000 0.000 0.000 -1 -1 16 0 -*",
                              b"C 1 PING*", b"R 1 HOLD*", b"6E51", b"904C", b"0000", b"!", b"\x18", b"\r"]),
             max_size=30).map(b"".join),
)
bodies = st.one_of(
    st.text(alphabet="DCANFOESXIL0123456789 -._+eEinfaGXYZ", max_size=60),
    st.builds(lambda k, rest: f"{k} {rest}", st.sampled_from(list("DCRANFOESXIL")),
              st.text(alphabet="0123456789 -.ABCDEFGHIJKLMNOPQRSTUVWXYZ_", max_size=50)),
)
VERBS = ["PING", "STATUS", "HOME", "JOB", "PAUSE", "RESUME", "STOP", "JOG", "SPINDLE", "SET", "GET", "ZERO",
         "SD", "RESET", "FOO"]
ARGS = ["FROM", "3", "-1", "1_0", "nan", "inf", "X", "Y", "Z", "10", "0.5", "300", "CHECK", "KP_X", "FERR",
        "LIST", "PUT", "RUN", "DEL", "a.nc", ".x", "ffffffff", "-", "1e3", "OFF", "NORMAL", "RECOVER", "0",
        "1"]
commands = st.builds(lambda cid, verb, args: f"C {cid} {' '.join([verb, *args])}",
                     st.integers(1, 50), st.sampled_from(VERBS), st.lists(st.sampled_from(ARGS), max_size=4))
data_lines = st.builds(lambda seq, line: f"D {seq} {line}", st.integers(0, 40),
                       st.lists(st.sampled_from(GCODE_WORDS[:22]), min_size=1, max_size=6).map(" ".join))
realtime_commands = st.builds(lambda cid, verb, why: f"R {cid} {verb} {why}".rstrip(), st.integers(1, 50),
                              st.sampled_from(["HOLD", "RESUME", "STOP", "RESET", "PAUSE"]),
                              st.sampled_from(["", "LINK", "PANEL", "NOPE"]))
machine_input = st.lists(st.one_of(commands, data_lines, realtime_commands,
                                   st.sampled_from(["!", "\x18", "garbage"])),
                         min_size=1, max_size=12)
dialect_lines = st.one_of(st.lists(st.sampled_from(GCODE_WORDS), max_size=8).map(" ".join),
                          st.text(alphabet="GMXYZIJFPS0123456789.-+ ", max_size=60))
json_scalars = st.one_of(st.none(), st.booleans(), st.integers(-10**6, 10**6), st.floats(allow_nan=True),
                         st.text(max_size=8))
json_values = st.recursive(
    json_scalars,
    lambda children: (st.lists(children, max_size=4)
                      | st.dictionaries(st.text(max_size=8), children, max_size=4)),
    max_leaves=10,
)
SECTIONS = [f.name for f in fields(MachineProfile)]
# Sections of scalars mostly (what a profile holds: the loaders' range and type rules), with
# nested values now and then; sizes bounded so that generating one costs about a loader call.
profile_like = st.dictionaries(
    st.sampled_from([*SECTIONS, "wheels"]),
    st.one_of(st.dictionaries(
        st.sampled_from(["kp", "ki", "lost_s", "heartbeat_s", "x_max", "encoder_ppr", "lead_mm", "nope"]),
        json_scalars, max_size=6), json_values),
    max_size=5,
)
settings_text = st.one_of(
    st.text(max_size=200),
    st.builds(lambda p: __import__("json").dumps({"version": 1, "profile": p}), profile_like),
    st.builds(lambda p: __import__("json").dumps(p), profile_like),
    st.integers(1, 3000).map(lambda n: "[" * n + "]" * n),
)


def gcode_text_loads(text: str) -> None:
    program = load_text(text)
    assert all(d.line >= 0 and d.message for d in program.diagnostics)
    assert len(program.line_map) == len(program.device_lines)


_SHM = Path("/dev/shm")  # a memory file system where there is one: the loaders still read real files
_TMP = Path(tempfile.mkdtemp(prefix="fuzz-", dir=_SHM if os.access(_SHM, os.W_OK) else None))
atexit.register(shutil.rmtree, _TMP, True)


def gcode_bytes_load(data: bytes) -> None:
    path = _TMP / "x.ngc"
    path.write_bytes(data)
    program = load(path)
    assert all(d.line >= 0 and d.message for d in program.diagnostics)


def deframer_both_sides(data: bytes) -> None:
    for legacy in (False, True):
        deframer = Deframer(legacy=legacy)
        items = deframer.feed(data[: len(data) // 2], 0.0) + deframer.feed(data[len(data) // 2:], 0.1)
        items += deframer.poll(10.0)
        for item in items:
            assert isinstance(item, fr.Frame | Dropped | Legacy)
            if isinstance(item, Legacy):
                assert legacy and item.byte in (b"!", b"\x18")


def codec_round_trip(body: str) -> None:
    try:
        line = fr.seal(body)
    except fr.FrameError:
        return
    try:
        frame = fr.decode(line)
    except fr.FrameError:
        return
    assert fr.decode(fr.encode(frame)) == frame


class _Machine:
    """One simulator fed by every example (its state carries over, as a fuzzer's would)."""

    sim = None

    @classmethod
    def get(cls):
        if cls.sim is None:
            from backend_sim import Simulator

            cls.sim = Simulator(sd_dir=tempfile.mkdtemp(prefix="fuzz-sd-"), seed=3)
            cls.sim.host_port.timeout = 0
        return cls.sim


def machine_takes_anything(items: list[str]) -> None:
    sim = _Machine.get()
    for item in items:
        raw = item.encode() if len(item) == 1 and item in "!\x18" else fr.seal(item) if item != "garbage" \
            else b"garbage\n"
        sim.host_port.write(raw)
        sim.run_for(0.02)
    sim.host_port.read(sim.host_port.in_waiting)


def dialect_parser(line: str) -> None:
    parser = DialectParser((0.0, 0.0, 20.0), (0.0, 0.0, 30.0))
    with contextlib.suppress(DialectError):
        parser.parse(0, line)


def _check_profile(profile: MachineProfile) -> None:
    for section in fields(profile):
        part = getattr(profile, section.name)
        for spec in fields(part):
            value = getattr(part, spec.name)
            lo, hi = spec.metadata["range"]
            assert not isinstance(value, bool) and math.isfinite(value) and lo <= value <= hi
    link = profile.link
    assert link.heartbeat_s < link.degraded_s < link.lost_s


def settings_loader(text: str) -> None:
    path = _TMP / "settings.json"
    path.write_text(text, encoding="utf-8", errors="surrogatepass")
    _check_profile(load_settings(path).profile)


def profile_loader(text: str) -> None:
    for name in ("m.json", "m.toml"):
        path = _TMP / name
        path.write_text(text, encoding="utf-8", errors="surrogatepass")
        _check_profile(read_profile(path).profile)


TARGETS = {
    "gcode text": (gcode_text, gcode_text_loads),
    "gcode bytes": (st.one_of(st.binary(max_size=300),
                              gcode_text.map(lambda t: t.encode("utf-8", "replace"))), gcode_bytes_load),
    "deframer": (frame_bytes, deframer_both_sides),
    "codec": (bodies, codec_round_trip),
    "machine commands": (machine_input, machine_takes_anything),
    "dialect parser": (dialect_lines, dialect_parser),
    "settings loader": (settings_text, settings_loader),
    "profile loader": (settings_text, profile_loader),
}
