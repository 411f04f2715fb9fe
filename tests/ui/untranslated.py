"""Which visible texts are still English when the window is in Vietnamese, and which
carry unfilled placeholders in either language.

A text is English when it is one of the English sources of ``resources/i18n/cnc_vi.ts``
or of the core's catalogue, or when it holds a word that appears only in English
sources (never in a Vietnamese translation), after taking out file names, URLs,
protocol words, proper names, units and G-code words."""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from functools import cache
from pathlib import Path

from babel.messages.pofile import read_po

from tests.ui.visible import plain

I18N = Path(__file__).resolve().parents[2] / "resources" / "i18n"
WORD = re.compile(r"[A-Za-z]{3,}")
NOT_WORDS = re.compile(r"\S*[._/:\\#@=]\S*|\b[A-Z][A-Z_0-9]*[_0-9][A-Z_0-9]*\b"
                       r"|\b(?:Ctrl|Alt|Shift|Meta)\+\S+")  # file names, protocol words, keys
PLACEHOLDER = re.compile(r"%\d|%n\b|\{[a-z_]+(?:[:!][^}]*)?\}|[A-Za-z]\((?:s|es)\)")
# Proper names, units, G-code and protocol words, which stay as they are in every language.
ALLOWED = {
    "cnc", "usb", "uart", "oled", "led", "pid", "mdi", "crc", "gcodetools", "inkscape", "linuxcnc",
    "pyside", "pyqtgraph", "mit", "stm", "ctrl", "shift", "alt", "pgup", "pgdn", "esc", "rpm",
    "home", "jog", "spindle", "set", "get", "zero", "status", "ping", "pause", "resume", "stop",
    "reset", "list", "put", "del", "run", "mreset", "exit", "down", "ascii", "baud", "sim",
    "ngc", "gcode", "png", "txt", "tap", "kp_x", "ferr", "check", "off", "recover", "normal",
}


# Whole texts that stay: the names printed on the machine's own buttons (its panel mirror).
MACHINE_BUTTONS = {"UP", "DOWN", "OK", "EXIT", "MRESET", "RESET"}


def _ts_pairs(path: Path) -> list[tuple[str, list[str]]]:
    pairs = []
    for message in ET.parse(path).getroot().iter("message"):
        source = message.findtext("source") or ""
        node = message.find("translation")
        forms = [f.text or "" for f in node.findall("numerusform")] or [node.text or ""]
        pairs.append((source, forms))
    return pairs


def _po_pairs(path: Path) -> list[tuple[str, list[str]]]:
    with path.open("rb") as file:
        return [(m.id, [m.string]) for m in read_po(file) if m.id]


@cache
def catalogue() -> tuple[frozenset, frozenset]:
    """(English sources that the Vietnamese catalogue changes, words found only in English)."""
    pairs = _ts_pairs(I18N / "cnc_vi.ts") + _po_pairs(I18N / "vi" / "LC_MESSAGES" / "cnc.po")
    sources, english, vietnamese = set(), set(), set()
    for source, forms in pairs:
        if any(plain(f) != plain(source) for f in forms):
            sources.add(plain(source))
        english |= _words(source)
        for form in forms:
            vietnamese |= _words(form)
    return frozenset(sources), frozenset(english - vietnamese - ALLOWED)


def _words(text: str) -> set[str]:
    text = re.sub(r"%\d|%n|\{[^}]*\}", " ", plain(text))
    return {w.lower() for w in WORD.findall(NOT_WORDS.sub(" ", text))}


def english_in_vietnamese(texts) -> list[str]:
    """The (where, text) pairs of a Vietnamese window that are still English, described."""
    sources, words = catalogue()
    found = []
    for where, text in texts:
        if text in MACHINE_BUTTONS:
            continue
        if text in sources:
            found.append(f"{where}: {text!r} (an English source)")
        elif _words(text) & words:
            found.append(f"{where}: {text!r} (English: {sorted(_words(text) & words)})")
    return sorted(set(found))


def placeholders(texts) -> list[str]:
    """(where, text) pairs that show an unfilled ``%1``, ``%n``, ``{name}`` or ``line(s)``."""
    return sorted({f"{where}: {text!r}" for where, text in texts if PLACEHOLDER.search(text)})
