"""What an MDI line is, for the state table (no Qt): a machine command (``HOME``,
``SD RUN x``, ``GET KP_X``) or a G-code line, and which control of the table it is.

A G-code line that only switches the spindle (``M3 S3000``, ``M5``) is the Spindle
button's command (``SPINDLE 3000`` / ``SPINDLE OFF``), so it follows the same rule as
the button; any other G-code line runs as a one-line job (the table's ``mdi``).
A GRBL system command (``$$``, ``$H``, ``$X``, ``$J=..``, ``$10=3``) and GRBL's status
query ``?`` are commands too, each under the control of what it does.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

VERBS = frozenset({"PING", "STATUS", "HOME", "PAUSE", "RESUME", "STOP", "RESET", "JOG", "SPINDLE",
                   "SET", "GET", "ZERO", "SD"})
_SPINDLE = re.compile(r"^\s*(?:N\d+\s*)?(M0*([345]))\s*(?:S\s*(\d+(?:\.\d*)?))?\s*$", re.IGNORECASE)
_SPINDLE_REVERSED = re.compile(r"^\s*(?:N\d+\s*)?S\s*(\d+(?:\.\d*)?)\s*M0*([34])\s*$", re.IGNORECASE)
_SD = {"LIST": "sd_list", "DEL": "sd_delete", "RUN": "sd_run", "PUT": "sd_save"}
_GRBL_CONTROLS = {"$H": "home", "$X": "unlock", "$C": "check_mode", "$SLP": "machine_settings"}
_GRBL_SETTING = re.compile(r"^\$(\d+|N\d+|RST)=", re.IGNORECASE)
_VERB_CONTROLS = {"PING": "query", "STATUS": "query", "GET": "query", "SET": "query", "PAUSE": "pause",
                  "RESUME": "resume", "STOP": "stop", "RESET": "stop", "JOG": "jog", "ZERO": "zero"}


@dataclass(frozen=True)
class MdiLine:
    control: str  # the state table's control that decides whether it may be sent now
    command: str | None  # the machine command to send; None: run ``text`` as a one-line job
    text: str


def classify(text: str) -> MdiLine:
    """The control and the command of one MDI line (see the module docstring)."""
    words = text.split()
    verb = words[0].upper() if words else ""
    if verb in VERBS:
        return MdiLine(_verb_control(verb, words), text, text)
    if verb.startswith("$") or verb == "?":
        return MdiLine(_grbl_control(text.strip()), text.strip(), text)
    spindle = _spindle_command(text)
    if spindle is not None:
        return MdiLine("spindle_off" if spindle == "SPINDLE OFF" else "spindle_on", spindle, text)
    return MdiLine("mdi", None, text)


def _verb_control(verb: str, words: list[str]) -> str:
    if verb == "HOME":
        return "home_recover" if len(words) > 1 and words[1].upper() == "RECOVER" else "home"
    if verb == "SPINDLE":
        return "spindle_off" if len(words) > 1 and words[1].upper() == "OFF" else "spindle_on"
    if verb == "SD":
        return _SD.get(words[1].upper() if len(words) > 1 else "", "sd_list")
    if verb == "SET" and len(words) > 1 and words[1].upper() == "CHECK":
        return "check_mode"
    return _VERB_CONTROLS[verb]


def _grbl_control(text: str) -> str:
    """The control of a GRBL system command or ``?`` (reading ones are queries)."""
    upper = text.upper()
    if upper.startswith("$J="):
        return "jog"
    if _GRBL_SETTING.match(upper):
        return "machine_settings"
    return _GRBL_CONTROLS.get(upper, "query")


def _spindle_command(text: str) -> str | None:
    """``SPINDLE <rpm>`` / ``SPINDLE OFF`` for a line that only switches the spindle, else None
    (an M4, reverse, is not something the machine has: it stays a G-code line)."""
    match = _SPINDLE.match(text)
    if match:
        code, rpm = match.group(2), match.group(3)
        if code == "5":
            return "SPINDLE OFF"
        if code == "3" and rpm is not None:
            return f"SPINDLE {float(rpm):g}" if float(rpm) > 0 else "SPINDLE OFF"
        return None
    match = _SPINDLE_REVERSED.match(text)
    if match and match.group(2) == "3":
        return f"SPINDLE {float(match.group(1)):g}"
    return None
