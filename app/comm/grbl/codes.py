"""GRBL 1.1's numbered answers in words: ``error:N``, ``ALARM:N`` and the ``$`` settings.

Written from GRBL's public interface and settings documentation. Every text is a
gettext template (``N_``), so ``error_text(N)``/``alarm_text(N)`` give a ``Message``
the window and the console localize. A code GRBL does not document (grblHAL adds its
own) gets a text that says so and keeps the number.
"""

from __future__ import annotations

from dataclasses import dataclass

from app.i18n import N_, Message, msg

ERRORS: dict[int, str] = {
    1: N_("a G-code word has no letter"),
    2: N_("a number is missing or badly written"),
    3: N_("the '$' command is not known"),
    4: N_("a value that must be positive is negative"),
    5: N_("homing is not enabled in the settings ($22)"),
    6: N_("the step pulse must be at least 3 microseconds"),
    7: N_("the settings memory could not be read: defaults restored"),
    8: N_("this '$' command needs the machine idle"),
    9: N_("G-code is locked out during an alarm or a jog"),
    10: N_("soft limits need homing enabled"),
    11: N_("the line is too long for the machine"),
    12: N_("the setting would make the step rate too high"),
    13: N_("the safety door is open"),
    14: N_("the build-info or startup line is too long to store"),
    15: N_("the jog would leave the machine's travel"),
    16: N_("the jog command is not valid (no '=' or a word jogs do not take)"),
    17: N_("laser mode needs a PWM spindle output"),
    20: N_("unsupported or invalid G-code command"),
    21: N_("two commands of the same modal group on one line"),
    22: N_("no feed rate has been set"),
    23: N_("the command needs a whole number"),
    24: N_("two commands on the line both need the axis words"),
    25: N_("a word is repeated on the line"),
    26: N_("the command needs axis words and the line has none"),
    27: N_("the line number is not valid"),
    28: N_("the command is missing a value it needs"),
    29: N_("G59.1, G59.2 and G59.3 are not supported"),
    30: N_("G53 is only allowed with G0 and G1"),
    31: N_("axis words on a line where nothing uses them"),
    32: N_("an arc needs at least one axis word in its plane"),
    33: N_("the motion's target is not valid"),
    34: N_("the arc's radius cannot reach its end point"),
    35: N_("an arc needs at least one centre offset (I, J, K) in its plane"),
    36: N_("words on the line that no command uses"),
    37: N_("G43.1 applies only to the tool length axis"),
    38: N_("the tool number is higher than the machine supports"),
}

ALARMS: dict[int, str] = {
    1: N_("hard limit switch hit: the position is probably lost; home the machine again"),
    2: N_("a move would leave the machine's travel (soft limit): the position is kept; "
          "the alarm may be unlocked"),
    3: N_("reset while moving: steps may be lost; home the machine again"),
    4: N_("probe fail: the probe was not in the expected state before the probe cycle"),
    5: N_("probe fail: the probe did not touch within the programmed travel"),
    6: N_("homing fail: homing was reset"),
    7: N_("homing fail: the safety door was opened during homing"),
    8: N_("homing fail: pulling off did not clear the limit switch (pull-off $27, wiring)"),
    9: N_("homing fail: no limit switch found within the search distance ($130-$132, wiring)"),
    10: N_("homing fail: the second switch of a dual axis did not trigger"),
}

# Alarms after which GRBL cannot vouch for the position (homing is the way out).
POSITION_LOST = frozenset({1, 3, 6, 7, 8, 9, 10})
# Critical alarms (hard and soft limit): GRBL answers nothing but a reset (0x18) until it
# gets one ("[MSG:Reset to continue]"); after the reset it is locked like the others.
RESET_FIRST = frozenset({1, 2})

# Why GRBL holds: the substate of ``Hold:n`` and ``Door:n`` in a status report.
HOLDS: dict[str, str] = {
    "Hold:0": N_("feed hold complete: Resume goes on"),
    "Hold:1": N_("feed hold: the machine is slowing down to a stop"),
    "Door:0": N_("safety door closed: Resume goes on"),
    "Door:1": N_("safety door open: the machine stopped; close it to go on"),
    "Door:2": N_("safety door opened: the machine is stopping (parking)"),
    "Door:3": N_("safety door closed: the machine is restoring from parking"),
}


def error_text(code: int) -> Message:
    """``error:code`` in words."""
    template = ERRORS.get(code)
    return msg(template) if template else msg("error {code} (not in GRBL 1.1's list)", code=code)


def alarm_text(code: int) -> Message:
    """``ALARM:code`` in words."""
    template = ALARMS.get(code)
    return msg(template) if template else msg("alarm {code} (not in GRBL 1.1's list)", code=code)


def hold_text(state: str) -> Message | str:
    """``Hold:0`` .. ``Door:3`` (a status's state with its substate) in words; a plain
    ``Hold`` or ``Door`` as GRBL names it; "" for a state that is not a hold."""
    if state in HOLDS:
        return msg(HOLDS[state])
    if state.split(":")[0] in ("Hold", "Door"):
        return msg("held ({state})", state=state)
    return ""


def unlock_advice(code: int | None, homing: bool = True) -> Message:
    """What to tell the operator before ``$X``: why the machine is locked and the risk.
    ``homing``: the machine has a homing cycle (``$22``); without one there is nothing to
    home, and the advice is to check the position and work zero instead."""
    if not homing and (code is None or code in RESET_FIRST or code in POSITION_LOST):
        return _unlock_advice_without_homing(code)
    if code in RESET_FIRST:
        return msg("Alarm {code}: {what}. The machine answers nothing until it is reset: reset it, "
                   "then home ($H) it, since the position may be lost.", code=code, what=alarm_text(code))
    if code is None:
        return msg("The machine starts locked until it is homed ($H). Unlocking ($X) without homing "
                   "means it does not know where it is: jog carefully and home soon.")
    if code in POSITION_LOST:
        return msg("Alarm {code}: {what}. Unlocking ($X) keeps the position the machine believes, "
                   "which may be wrong: home ($H) instead if you can.", code=code, what=alarm_text(code))
    return msg("Alarm {code}: {what}. Unlocking ($X) lets the machine move again.", code=code,
               what=alarm_text(code))


def _unlock_advice_without_homing(code: int | None) -> Message:
    """``unlock_advice`` where the position may be wrong and there is no homing to fix it."""
    if code in RESET_FIRST:
        return msg("Alarm {code}: {what}. The machine answers nothing until it is reset: reset it, then "
                   "unlock ($X) it; it has no homing, so check its position and work zero before cutting.",
                   code=code, what=alarm_text(code))
    if code is None:
        return msg("The machine is in alarm (since before this connection). Unlocking ($X) lets it move "
                   "again; it has no homing, so check its position and work zero before cutting.")
    return msg("Alarm {code}: {what}. Unlocking ($X) keeps the position the machine believes, which "
               "may be wrong; it has no homing: set the work zero again before cutting.", code=code,
               what=alarm_text(code))


@dataclass(frozen=True)
class SettingInfo:
    """One ``$n`` setting: its name, unit and meaning (templates for ``msg``)."""

    number: int
    name: str
    unit: str
    meaning: str


def _s(number: int, name: str, unit: str, meaning: str) -> SettingInfo:
    return SettingInfo(number, name, unit, meaning)


_AXIS_SETTINGS = []
for _base, _name, _unit, _meaning in (
        (100, N_("{axis} steps per mm"), "step/mm", N_("steps the {axis} motor makes per millimetre")),
        (110, N_("{axis} maximum rate"), "mm/min", N_("fastest {axis} speed; also the G0 rapid rate")),
        (120, N_("{axis} acceleration"), "mm/s²", N_("{axis} acceleration used by the planner")),
        (130, N_("{axis} maximum travel"), "mm", N_("{axis} travel from the homing switch; bounds "
                                                     "the soft limits and the homing search"))):
    for _k, _axis in enumerate("XYZ"):
        _AXIS_SETTINGS.append((_base + _k, _name, _unit, _meaning, _axis))

SETTINGS: dict[int, SettingInfo] = {s.number: s for s in (
    _s(0, N_("step pulse time"), "µs", N_("length of each step pulse (at least 3)")),
    _s(1, N_("step idle delay"), "ms", N_("how long the motors stay powered after a stop; 255: always")),
    _s(2, N_("step pulse invert"), N_("mask"), N_("inverts the step signal of the axes set (bits ZYX)")),
    _s(3, N_("step direction invert"), N_("mask"), N_("inverts the direction of the axes set (bits ZYX)")),
    _s(4, N_("invert step enable pin"), N_("on/off"), N_("inverts the stepper driver enable signal")),
    _s(5, N_("invert limit pins"), N_("on/off"), N_("inverts all limit switch inputs")),
    _s(6, N_("invert probe pin"), N_("on/off"), N_("inverts the probe input")),
    _s(10, N_("status report options"), N_("mask"), N_("1: machine position (else work position); "
                                                       "2: buffer use in reports")),
    _s(11, N_("junction deviation"), "mm", N_("how fast corners are taken; lower is slower")),
    _s(12, N_("arc tolerance"), "mm", N_("largest distance of the arc's chords from the true arc")),
    _s(13, N_("report in inches"), N_("on/off"), N_("positions and rates reported in inches")),
    _s(20, N_("soft limits"), N_("on/off"), N_("refuse moves outside the travel (needs homing)")),
    _s(21, N_("hard limits"), N_("on/off"), N_("stop at once with an alarm when a limit switch trips")),
    _s(22, N_("homing cycle"), N_("on/off"), N_("enables $H; the machine starts locked until homed")),
    _s(23, N_("homing direction invert"), N_("mask"),
       N_("axes set home to their negative end (bits ZYX)")),
    _s(24, N_("homing locate feed"), "mm/min", N_("slow feed that locates the switch precisely")),
    _s(25, N_("homing search seek"), "mm/min", N_("fast feed that finds the switch first")),
    _s(26, N_("homing switch debounce"), "ms", N_("pause between homing phases for the switch to settle")),
    _s(27, N_("homing pull-off"), "mm", N_("distance moved back off the switch after homing")),
    _s(30, N_("maximum spindle speed"), "rpm", N_("speed at full PWM output")),
    _s(31, N_("minimum spindle speed"), "rpm", N_("speed at the lowest PWM output")),
    _s(32, N_("laser mode"), N_("on/off"), N_("moves do not stop when the spindle (laser) power changes")),
)}


def setting_info(number: int) -> SettingInfo:
    """Name, unit and meaning of ``$number`` (axis settings filled in); unknown: a plain one."""
    info = SETTINGS.get(number)
    if info is not None:
        return info
    for base, name, unit, meaning, axis in _AXIS_SETTINGS:
        if base == number:
            return SettingInfo(number, msg(name, axis=axis), unit, msg(meaning, axis=axis))
    return SettingInfo(number, msg("setting {number}", number=number), "",
                       msg("not in GRBL 1.1's list (a grblHAL or build-specific setting)"))
