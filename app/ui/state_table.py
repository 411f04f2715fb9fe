"""Which control is allowed in which state: one table, no Qt.

Inputs (``Inputs``): the link (none / connecting / up / degraded / lost), the machine's
state (``Machine``), homed or not, a dialog waiting for the operator, whether the open
program can run, and the machine's ``Capabilities``. ``decide(control, inputs)`` gives
a ``Verdict`` (allowed, and the reason when not, in English: the window translates it
in the "StateTable" context). ``app/ui/enabler.py`` applies the verdicts to every
button, menu action, shortcut and panel control, and ``OperatorActions`` asks the same
table before it sends anything, so a stale click is refused with the reason and never
queued. ``machine_of`` turns what the session and the status say into a ``Machine``.

The table reads row by row: a row per machine state, a column per control; ``Y`` the
control may be used, ``h`` once the machine is homed, ``.`` not in this state. The link,
a waiting dialog, the program and the capabilities then narrow it (``decide``).

At a program stop (``program_stop``: ``M00``/``M01``/``M06``, flag ``W``) the operator
touches off, as every sender allows at a tool change: the jog (buttons, keys, hold to
jog) and the work zero are allowed beside Resume and Stop (docs/protocol.md, "Program
stops and tool changes"; for GRBL the host holds the stream with the machine idle).
While such a jog runs (status ``JOG`` with ``W``, or a jog sent and not yet answered)
the machine is in the ``jog`` row: no Resume until the jog has ended.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass

from app.capabilities import FRAME_PROTOCOL, Capabilities


def QT_TRANSLATE_NOOP(context: str, text: str) -> str:  # noqa: N802 (lupdate's marker, no Qt here)
    return text


class Link(enum.Enum):
    NONE = "none"
    CONNECTING = "connecting"
    UP = "up"
    DEGRADED = "degraded"
    LOST = "lost"


class Machine(enum.Enum):
    IDLE = "idle"
    CHECK_MODE = "check_mode"  # idle, check mode on: jobs are dry runs
    HOMING = "homing"
    JOG = "jog"  # a jog, or the after-job lift
    SPINDLE = "spindle"  # a spindle command under way (spinning up or down)
    RUN_HOST = "run_host"  # a job streamed from this computer
    RUN_SD = "run_sd"  # a job the machine runs from its card
    UPLOAD = "upload"  # a program being saved to the card
    HOLD = "hold"  # a job held (pause)
    PROGRAM_STOP = "program_stop"  # a job waiting at M00/M01/M06
    ALARM = "alarm"
    COVER_OPEN = "cover_open"


# The columns: each abbreviation and the control it stands for.
COLUMNS = {
    "home": "home",
    "recov": "home_recover",
    "start": "start",
    "here": "start_here",
    "pause": "pause",
    "resum": "resume",
    "stop": "stop",
    "jog": "jog",
    "spon": "spindle_on",
    "spoff": "spindle_off",
    "zero": "zero",
    "check": "check_mode",
    "trav": "override_travel",
    "sdsav": "sd_save",
    "sdls": "sd_list",
    "sddel": "sd_delete",
    "sdrun": "sd_run",
    "mdi": "mdi",
    "wcs": "work_offsets",
    "goto": "go_to",
    "cust": "custom_commands",
    "hold": "jog_hold",
    "outl": "outline",
    "ovfd": "feed_override",
    "ovsp": "spindle_override",
    "ovrp": "rapid_override",
    "sets": "machine_settings",
    "unlk": "unlock",
}

TABLE = """
state        home recov start here pause resum stop jog spon spoff zero check trav sdsav sdls sddel sdrun mdi wcs goto cust hold outl
idle         Y    Y     h     h    .     .     Y    Y   Y    Y     h    Y     .    Y     Y    Y     h     h   Y   h    h    Y    h
check_mode   Y    Y     Y     Y    .     .     Y    Y   Y    Y     h    Y     Y    Y     Y    Y     .     Y   Y   Y    Y    Y    Y
homing       .    .     .     .    Y     .     Y    .   .    .     .    .     .    .     .    .     .     .   .   .    .    .    .
jog          .    .     .     .    Y     .     Y    .   .    .     .    .     .    .     .    .     .     .   .   .    .    Y    .
spindle      .    .     .     .    .     .     Y    .   .    Y     .    .     .    .     .    .     .     .   .   .    .    .    .
run_host     .    .     .     .    Y     .     Y    .   .    .     .    .     .    .     .    .     .     .   .   .    .    .    .
run_sd       .    .     .     .    Y     .     Y    .   .    .     .    .     .    .     .    .     .     .   .   .    .    .    .
upload       .    .     .     .    .     .     Y    .   .    .     .    .     .    .     .    .     .     .   .   .    .    .    .
hold         .    .     .     .    .     Y     Y    .   .    .     .    .     .    .     .    .     .     .   .   .    .    .    .
program_stop .    .     .     .    .     Y     Y    Y   .    .     h    .     .    .     .    .     .     .   .   .    .    Y    .
alarm        Y    Y     .     .    .     .     Y    .   .    Y     .    .     .    .     Y    .     .     .   Y   .    .    .    .
cover_open   .    .     .     .    Y     .     Y    .   .    Y     .    .     .    .     .    .     .     .   Y   .    .    .    .
"""

# The overrides' columns (issue 21), kept in a table of their own (the one above is as wide
# as a line may be): the machine takes them in any state; not while a homing, a jog or an
# upload has it (the spindle one also while the spindle changes speed).
OVERRIDE_TABLE = """
state        ovfd ovsp ovrp
idle         Y    Y    Y
check_mode   Y    Y    Y
homing       .    .    .
jog          .    .    .
spindle      .    Y    .
run_host     Y    Y    Y
run_sd       Y    Y    Y
upload       .    .    .
hold         Y    Y    Y
program_stop Y    Y    Y
alarm        Y    Y    Y
cover_open   Y    Y    Y
"""

# A machine's own settings table and its alarm lock (issue 23, GRBL's ``$$`` and ``$X``):
# GRBL takes a setting write only idle or in alarm, and ``$X`` lifts an alarm's lock.
MACHINE_TABLE = """
state        sets unlk
idle         Y    .
check_mode   .    .
homing       .    .
jog          .    .
spindle      .    .
run_host     .    .
run_sd       .    .
upload       .    .
hold         .    .
program_stop .    .
alarm        Y    Y
cover_open   .    .
"""

# Controls the link alone decides (enabled whenever the link is up, as the machine
# answers them in every state): queries, and the connect/disconnect button always.
LINK_ONLY = ("query",)
ALWAYS = ("connect",)
# What stays usable while the link is degraded or a dialog waits: what makes the machine safer.
SAFE = frozenset({"pause", "stop", "spindle_off"})
NEEDS_PROGRAM = frozenset({"start", "start_here", "sd_save"})
NEEDS_PROGRAM |= {"outline"}  # issue 21: the outline of the open program
NEEDS_CAPABILITY = {"sd_save": "sd_card", "sd_list": "sd_card", "sd_delete": "sd_card", "sd_run": "sd_card",
                    "panel": "oled_panel", "cover_switch": "cover"}
# The overrides (issue 21): the control of each ``R`` override verb; set in any state the
# machine takes them in, except while a homing, a jog or an upload has the machine.
OVERRIDE_CONTROLS = {"FEED": "feed_override", "SPINDLE": "spindle_override", "RAPID": "rapid_override"}
NEEDS_CAPABILITY.update(dict.fromkeys(OVERRIDE_CONTROLS.values(), "overrides"))
NEEDS_CAPABILITY.update({"machine_settings": "settings_table", "unlock": "unlock"})


def _parse(table: str) -> tuple[tuple[str, ...], dict[Machine, dict[str, str]]]:
    header, *rows = [line.split() for line in table.strip().splitlines()]
    controls = tuple(COLUMNS[name] for name in header[1:])
    cells = {}
    for row in rows:
        if len(row) != len(header) or any(c not in "Yh." for c in row[1:]):
            raise ValueError(f"state table row {row[0]!r}: one of Y h . per control")
        cells[Machine(row[0])] = dict(zip(controls, row[1:], strict=True))
    if set(cells) != set(Machine):
        raise ValueError("state table: one row per machine state")
    return controls, cells


TABLE_CONTROLS, CELLS = _parse(TABLE)
for _table in (OVERRIDE_TABLE, MACHINE_TABLE):
    _more, _more_cells = _parse(_table)
    TABLE_CONTROLS += _more
    for _machine, _row in _more_cells.items():
        CELLS[_machine].update(_row)
CONTROLS = (*TABLE_CONTROLS, *LINK_ONLY, *ALWAYS, "panel", "cover_switch")

# Why a control is not allowed, in the operator's words ("StateTable" context).
LINK_REASONS = {
    Link.NONE: QT_TRANSLATE_NOOP("StateTable", "not connected"),
    Link.CONNECTING: QT_TRANSLATE_NOOP("StateTable", "still connecting"),
    Link.DEGRADED: QT_TRANSLATE_NOOP("StateTable", "the link is unsteady: only Pause, Stop and Spindle off"),
    Link.LOST: QT_TRANSLATE_NOOP("StateTable", "the link is lost: reconnect first"),
}
STATE_REASONS = {
    Machine.HOMING: QT_TRANSLATE_NOOP("StateTable", "the machine is homing"),
    Machine.JOG: QT_TRANSLATE_NOOP("StateTable", "the machine is moving (jog)"),
    Machine.SPINDLE: QT_TRANSLATE_NOOP("StateTable", "the spindle is changing speed"),
    Machine.RUN_HOST: QT_TRANSLATE_NOOP("StateTable", "a job is running"),
    Machine.RUN_SD: QT_TRANSLATE_NOOP("StateTable", "a job is running from the SD card"),
    Machine.UPLOAD: QT_TRANSLATE_NOOP("StateTable", "a program is being saved to the SD card"),
    Machine.HOLD: QT_TRANSLATE_NOOP("StateTable", "the job is held: resume or stop it first"),
    Machine.PROGRAM_STOP: QT_TRANSLATE_NOOP("StateTable", "the job waits at a program stop"),
    Machine.ALARM: QT_TRANSLATE_NOOP("StateTable", "the machine is in alarm: home it first"),
    Machine.COVER_OPEN: QT_TRANSLATE_NOOP("StateTable", "the cover is open"),
}
IDLE_REASONS = {
    "pause": QT_TRANSLATE_NOOP("StateTable", "nothing is moving"),
    "resume": QT_TRANSLATE_NOOP("StateTable", "nothing is held"),
    "override_travel": QT_TRANSLATE_NOOP("StateTable", "only in check mode"),
    "sd_run": QT_TRANSLATE_NOOP("StateTable", "check mode is on"),
    "machine_settings": QT_TRANSLATE_NOOP("StateTable", "check mode is on"),
    "unlock": QT_TRANSLATE_NOOP("StateTable", "the machine is not in alarm"),
}
NOT_HOMED = QT_TRANSLATE_NOOP("StateTable", "home the machine first")
DIALOG = QT_TRANSLATE_NOOP("StateTable", "answer the open dialog first")
NO_PROGRAM = QT_TRANSLATE_NOOP("StateTable", "open a program that can run first")
CAPABILITY_REASONS = {
    "sd_card": QT_TRANSLATE_NOOP("StateTable", "this machine has no SD card"),
    "oled_panel": QT_TRANSLATE_NOOP("StateTable", "this machine has no panel of its own"),
    "cover": QT_TRANSLATE_NOOP("StateTable", "this machine has no cover switch"),
    "overrides": QT_TRANSLATE_NOOP("StateTable", "this machine takes no overrides"),
    "settings_table": QT_TRANSLATE_NOOP("StateTable", "this machine has no settings table of its own: "
                                                      "its settings are in File > Settings"),
    "unlock": QT_TRANSLATE_NOOP("StateTable", "this machine has no alarm lock to lift: home it"),
}


@dataclass(frozen=True)
class Inputs:
    link: Link = Link.NONE
    machine: Machine = Machine.IDLE
    homed: bool = False
    dialog: bool = False  # a dialog waits for the operator (program stop, link alert, confirmation)
    has_program: bool = False  # an open program that may run (no errors, inside the travel)
    capabilities: Capabilities = FRAME_PROTOCOL
    panel_attached: bool = False  # the simulator's panel is there to drive


@dataclass(frozen=True)
class Verdict:
    allowed: bool
    reason: str = ""  # English, "StateTable" context; "" when allowed


YES = Verdict(True)


def decide(control: str, inputs: Inputs) -> Verdict:
    """Whether ``control`` may be used in ``inputs``, and why not (see the module docstring)."""
    if control in ALWAYS:
        return YES
    capability = NEEDS_CAPABILITY.get(control)
    if capability and not getattr(inputs.capabilities, capability, False):
        return Verdict(False, CAPABILITY_REASONS[capability])
    if control in ("panel", "cover_switch"):
        return YES if inputs.panel_attached else Verdict(False, LINK_REASONS[Link.NONE])
    if inputs.link is not Link.UP and not (inputs.link is Link.DEGRADED and control in SAFE):
        return Verdict(False, LINK_REASONS[inputs.link])
    if control in LINK_ONLY:
        return YES
    return _by_state(control, inputs)


def _by_state(control: str, inputs: Inputs) -> Verdict:
    cell = CELLS[inputs.machine][control]
    if cell == ".":
        return Verdict(False, STATE_REASONS.get(inputs.machine) or IDLE_REASONS.get(control, ""))
    if inputs.dialog and control not in SAFE:
        return Verdict(False, DIALOG)
    if control in NEEDS_PROGRAM and not inputs.has_program:
        return Verdict(False, NO_PROGRAM)
    if cell == "h" and not inputs.homed:
        return Verdict(False, NOT_HOMED)
    return YES


def decide_all(inputs: Inputs) -> dict[str, Verdict]:
    return {control: decide(control, inputs) for control in CONTROLS}


JOB_SESSION_STATES = frozenset({"STARTING", "STREAMING", "PAUSED", "STOPPING", "RESUMING"})
RECOVERY_SESSION_STATES = frozenset({"INTERRUPTED", "RESUME_OFFERED", "RESTART_REQUIRED"})


PENDING = {"HOME": Machine.HOMING, "JOG": Machine.JOG, "SPINDLE": Machine.SPINDLE}


def machine_of(session_state: str, status_state: str | None, flags: str, check_mode: bool,
               pending: str | None = None) -> Machine:
    """The table's machine state from the session's state (``SessionState`` name), the last
    status's state and flags (None: no status yet), the check-mode switch and the verb of a
    command sent outside a job whose answer has not come (``HOME``, ``JOG``, ``SPINDLE``: it
    counts as running from the click, so nothing is queued behind it)."""
    if "C" in flags:
        return Machine.COVER_OPEN
    if status_state == "ALARM":
        return Machine.ALARM
    if session_state == "UPLOADING":
        return Machine.UPLOAD
    if "W" in flags:  # a touch-off jog at the stop is a jog (no Resume under it)
        return Machine.JOG if status_state == "JOG" or pending == "JOG" else Machine.PROGRAM_STOP
    if status_state == "HOLD" or session_state == "PAUSED":
        return Machine.HOLD
    if "S" in flags and status_state == "RUN":
        return Machine.RUN_SD
    if pending in PENDING and session_state == "READY" and status_state in ("IDLE", "RUN", pending):
        return PENDING[pending]
    if session_state in JOB_SESSION_STATES | RECOVERY_SESSION_STATES or status_state == "RUN":
        return Machine.RUN_HOST
    if status_state == "HOMING":
        return Machine.HOMING
    if status_state == "JOG":
        return Machine.JOG
    return Machine.CHECK_MODE if check_mode else Machine.IDLE


def link_of(connected: bool, session_state: str, link_state: str, has_status: bool) -> Link:
    """The table's link from the binder's view: ``link_state`` is the session's link
    (CONNECTED / DEGRADED / LOST / DISCONNECTED), a first status makes a link "up"."""
    if link_state == "LOST":
        return Link.LOST
    if not connected:
        return Link.CONNECTING if session_state == "CONNECTING" else Link.NONE
    if link_state == "DEGRADED":
        return Link.DEGRADED
    if not has_status or session_state == "CONNECTING":
        return Link.CONNECTING
    return Link.UP

# The operator's name of each control, for a refusal ("Jog refused: the machine is homing").
LABELS = {
    "home": QT_TRANSLATE_NOOP("StateTable", "Home"),
    "home_recover": QT_TRANSLATE_NOOP("StateTable", "Home after a fault"),
    "start": QT_TRANSLATE_NOOP("StateTable", "Start"),
    "start_here": QT_TRANSLATE_NOOP("StateTable", "Start here"),
    "pause": QT_TRANSLATE_NOOP("StateTable", "Pause"),
    "resume": QT_TRANSLATE_NOOP("StateTable", "Resume"),
    "stop": QT_TRANSLATE_NOOP("StateTable", "Stop"),
    "jog": QT_TRANSLATE_NOOP("StateTable", "Jog"),
    "spindle_on": QT_TRANSLATE_NOOP("StateTable", "Spindle on"),
    "spindle_off": QT_TRANSLATE_NOOP("StateTable", "Spindle off"),
    "zero": QT_TRANSLATE_NOOP("StateTable", "Work zero"),
    "check_mode": QT_TRANSLATE_NOOP("StateTable", "Check mode"),
    "override_travel": QT_TRANSLATE_NOOP("StateTable", "Override travel check"),
    "sd_save": QT_TRANSLATE_NOOP("StateTable", "Save to SD"),
    "sd_list": QT_TRANSLATE_NOOP("StateTable", "SD card list"),
    "sd_delete": QT_TRANSLATE_NOOP("StateTable", "Delete from SD"),
    "sd_run": QT_TRANSLATE_NOOP("StateTable", "Run from SD"),
    "mdi": QT_TRANSLATE_NOOP("StateTable", "MDI line"),
    "jog_hold": QT_TRANSLATE_NOOP("StateTable", "Hold to jog"),
    "outline": QT_TRANSLATE_NOOP("StateTable", "Trace outline"),
    "query": QT_TRANSLATE_NOOP("StateTable", "MDI command"),
    "connect": QT_TRANSLATE_NOOP("StateTable", "Connect"),
    "panel": QT_TRANSLATE_NOOP("StateTable", "Machine panel"),
    "cover_switch": QT_TRANSLATE_NOOP("StateTable", "Cover switch"),
    "work_offsets": QT_TRANSLATE_NOOP("StateTable", "Work offsets"),
    "go_to": QT_TRANSLATE_NOOP("StateTable", "Go to position"),
    "custom_commands": QT_TRANSLATE_NOOP("StateTable", "Custom command"),
    "feed_override": QT_TRANSLATE_NOOP("StateTable", "Feed override"),
    "spindle_override": QT_TRANSLATE_NOOP("StateTable", "Spindle override"),
    "rapid_override": QT_TRANSLATE_NOOP("StateTable", "Rapid override"),
    "machine_settings": QT_TRANSLATE_NOOP("StateTable", "Machine settings ($$)"),
    "unlock": QT_TRANSLATE_NOOP("StateTable", "Unlock ($X)"),
}
