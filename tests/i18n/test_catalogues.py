"""The translation files are complete and compiled from what is committed:
every string of ``app/ui`` is in ``cnc_vi.ts`` and translated (``cnc_en.ts``: every plural), every
core message is in the ``.po`` and translated, and each committed ``.qm``/``.mo`` is what
``pyside6-lrelease``/Babel make of its source today (and not older than it)."""

from __future__ import annotations

import io
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from babel.messages.extract import extract_from_dir, extract_python
from babel.messages.mofile import write_mo
from babel.messages.pofile import read_po

ROOT = Path(__file__).resolve().parents[2]
I18N = ROOT / "resources" / "i18n"
BIN = Path(sys.executable).parent
TS = sorted(I18N.glob("cnc_*.ts"))
PO = I18N / "vi" / "LC_MESSAGES" / "cnc.po"
UI_SOURCES = sorted(str(p.relative_to(ROOT)) for p in (ROOT / "app" / "ui").rglob("*.py"))


def _messages(ts: Path) -> dict[tuple[str, str], ET.Element]:
    root = ET.parse(ts).getroot()
    return {(ctx.findtext("name"), m.findtext("source")): m for ctx in root for m in ctx.iter("message")}


def _lupdate(tmp_path: Path) -> Path:
    """What ``make i18n`` would collect from the sources now, into a fresh .ts."""
    out = tmp_path / "fresh.ts"
    command = [str(BIN / "pyside6-lupdate"), "-silent", "-locations", "none", *UI_SOURCES, "-ts", str(out)]
    subprocess.run(command, cwd=ROOT, check=True, capture_output=True)
    return out


def test_every_window_string_is_in_the_ts_files_and_translated(tmp_path):
    fresh = _messages(_lupdate(tmp_path))
    assert len(fresh) > 250
    plurals = {key for key, m in fresh.items() if m.get("numerus") == "yes"}
    wanted = {"cnc_vi.ts": set(fresh), "cnc_en.ts": plurals}  # English, the source, needs only plurals
    assert set(wanted) == {ts.name for ts in TS}
    for ts in TS:
        missing = sorted(wanted[ts.name] - set(_messages(ts)))
        assert missing == [], f"{ts.name} lacks {missing[:10]}: run `make i18n` and translate"
    for ts in TS:
        unfinished = [key for key, m in _messages(ts).items()
                      if m.find("translation").get("type") in ("unfinished", "obsolete", "vanished")]
        assert unfinished == [], f"{ts.name}: untranslated {unfinished[:10]}"


@pytest.mark.parametrize("ts", TS, ids=lambda p: p.name)
def test_committed_qm_is_what_lrelease_makes_of_the_ts(ts, tmp_path):
    qm = ts.with_suffix(".qm")
    assert qm.exists(), f"{qm.name} missing: run `make translations`"
    assert qm.stat().st_mtime >= ts.stat().st_mtime, f"{qm.name} is older than {ts.name}: `make translations`"
    fresh = tmp_path / qm.name
    command = [str(BIN / "pyside6-lrelease"), "-silent", str(shutil.copy(ts, tmp_path)), "-qm", str(fresh)]
    subprocess.run(command, check=True, capture_output=True)
    assert fresh.read_bytes() == qm.read_bytes(), f"{qm.name} differs from its .ts: `make translations`"


def test_every_core_message_is_in_the_po_and_translated():
    found = set()
    for folder in ("app/gcode", "app/comm", "app"):
        files = "*.py" if folder == "app" else "**.py"  # app/ itself: profile.py, i18n.py
        for _, _, message, *_ in extract_from_dir(ROOT / folder, method_map=[(files, "python")],
                                                  keywords={"msg": None, "N_": None}):
            found.add(message)
    store = ROOT / "app" / "ui" / "settings" / "store.py"  # Qt-free, beside the dialog
    with store.open("rb") as file:
        found |= {m[2] for m in extract_python(file, ["msg", "N_"], [], {})}
    assert len(found) > 60
    with PO.open("rb") as file:
        catalogue = read_po(file)
    missing = sorted(m for m in found if m not in catalogue)
    assert missing == [], f"cnc.po lacks {missing[:5]}: run `make i18n` and translate"
    untranslated = sorted(m.id for m in catalogue if m.id and (not m.string or m.fuzzy))
    assert untranslated == [], f"cnc.po: untranslated {untranslated[:5]}"


def test_committed_mo_is_what_babel_makes_of_the_po():
    mo = PO.with_suffix(".mo")
    assert mo.stat().st_mtime >= PO.stat().st_mtime, "cnc.mo is older than cnc.po: `make translations`"
    with PO.open("rb") as file:
        catalogue = read_po(file)
    fresh = io.BytesIO()
    write_mo(fresh, catalogue, use_fuzzy=True)
    assert fresh.getvalue() == mo.read_bytes(), "cnc.mo differs from cnc.po: `make translations`"
