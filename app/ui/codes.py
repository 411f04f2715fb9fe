"""The machine's alarm (``X``) and refusal (``E``) codes of ``docs/protocol.md`` in the
operator's language. The machine's own text is firmware English; the window says what
the code means and keeps the machine's values (a soft limit names the axis, the
direction, the position and the limit); the console keeps the machine's words."""

from __future__ import annotations

import re

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication

from app.i18n import localize
from app.ui.language import current_language
from app.ui.numbers import decimal

CONTEXT = "MachineCodes"
MEANINGS = {
    # alarms
    "LIMIT": QT_TRANSLATE_NOOP("MachineCodes", "a limit switch was hit"),
    "FOLLOWING_ERROR": QT_TRANSLATE_NOOP("MachineCodes", "following error: an axis fell behind its path"),
    "HOST_LOST": QT_TRANSLATE_NOOP("MachineCodes", "the machine lost the computer link"),
    "UART_LOST": QT_TRANSLATE_NOOP("MachineCodes", "the link between the machine's two boards is lost"),
    "BOOT": QT_TRANSLATE_NOOP("MachineCodes", "the machine (re)started"),
    # refusals
    "NOT_HOMED": QT_TRANSLATE_NOOP("MachineCodes", "the machine is not homed"),
    "SOFT_LIMIT": QT_TRANSLATE_NOOP("MachineCodes", "the move would leave the travel (soft limit)"),
    "BAD_LINE": QT_TRANSLATE_NOOP("MachineCodes", "the machine cannot read this line"),
    "BAD_VALUE": QT_TRANSLATE_NOOP("MachineCodes", "a value is out of range"),
    "NO_FEED": QT_TRANSLATE_NOOP("MachineCodes", "no feed rate (F) given"),
    "BAD_ARC": QT_TRANSLATE_NOOP("MachineCodes", "the arc is not valid"),
    "BAD_SEQ": QT_TRANSLATE_NOOP("MachineCodes", "the line number is out of order"),
    "BUSY": QT_TRANSLATE_NOOP("MachineCodes", "the machine is busy"),
    "COVER_OPEN": QT_TRANSLATE_NOOP("MachineCodes", "the cover is open: no motion allowed"),
    "ALARM": QT_TRANSLATE_NOOP("MachineCodes", "the machine is in alarm: home it after a fault"),
    "QUEUE_FULL": QT_TRANSLATE_NOOP("MachineCodes", "the machine's queue is full"),
    "BAD_ARGS": QT_TRANSLATE_NOOP("MachineCodes", "wrong arguments for the command"),
    "BAD_PARAM": QT_TRANSLATE_NOOP("MachineCodes", "no such setting"),
    "UNKNOWN_VERB": QT_TRANSLATE_NOOP("MachineCodes", "the machine does not know this command"),
    "BAD_NAME": QT_TRANSLATE_NOOP("MachineCodes", "the file name is not allowed on the card"),
    "NO_FILE": QT_TRANSLATE_NOOP("MachineCodes", "no such file on the card"),
    "SD_FULL": QT_TRANSLATE_NOOP("MachineCodes", "the SD card is full"),
    "CRC_MISMATCH": QT_TRANSLATE_NOOP("MachineCodes", "the file on the card does not match (CRC)"),
}
SOFT_LIMIT_TEXT = re.compile(r"^\s*(?:\d+\s+)?([XYZ])([+-])\s+(-?[\d.]+)\s*([<>])\s*(-?[\d.]+)")


def meaning(code: str) -> str:
    """What ``code`` means, in the operator's language ("" for a code not listed)."""
    return QCoreApplication.translate(CONTEXT, MEANINGS[code]) if code in MEANINGS else ""


def soft_limit_text(text: str) -> str:
    """``X+ 151.200 > 150`` as a sentence naming the axis and direction ("" if not that shape)."""
    found = SOFT_LIMIT_TEXT.match(text or "")
    if not found:
        return ""
    axis, sign, value, _, limit = found.groups()
    sentence = QCoreApplication.translate("MachineCodes",
                                          "axis %1 in the %2 direction: %3 mm is past the limit %4 mm")
    for mark, part in (("%1", axis), ("%2", sign), ("%3", decimal(float(value), 3)),
                       ("%4", decimal(float(limit), 0 if float(limit).is_integer() else 3))):
        sentence = sentence.replace(mark, part)
    return sentence


def _explain(code: str, text: str) -> str:
    said, text = meaning(code), localize(text or "")
    if code == "SOFT_LIMIT" and soft_limit_text(text):
        return f"{said}: {soft_limit_text(text)}"
    if said:  # the machine's own words are firmware English: kept (and in the console) in English only
        detail = f": {text}" if text and current_language() == "en" else ""
        return f"{said} ({code}{detail})"
    return f"{code}: {text}".strip(": ")


def alarm_text(code: str, text: str) -> str:
    """An ``X`` alarm for the operator."""
    return _explain(code, text)


def refusal_text(code: str, info: str) -> str:
    """An ``E`` refusal (or a host-side code) for the operator."""
    return _explain(code, info)
