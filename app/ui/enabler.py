"""The state table applied: every control of the window takes its enabled state, and the
reason it is off, from ``app/ui/state_table.py``, in this one place.

``controls_of(window)`` lists the widgets and actions (buttons, menu actions and their
shortcuts, panel controls) behind each control of the table; ``apply(window, inputs)``
enables them per ``decide_all`` and appends the translated reason to the tooltip of
those that are off ("not now: ..."), so the operator reads why; the resend counters
are hidden on a machine without a checked (CRC) link.
"""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication
from PySide6.QtGui import QAction

from app.ui.state_table import OVERRIDE_CONTROLS, Inputs, Verdict, decide_all

SUFFIX = "why_not_suffix"  # the property holding what apply() appended to a tooltip


def reason_text(verdict: Verdict) -> str:
    """The verdict's reason in the operator's language ("" when allowed)."""
    return QCoreApplication.translate("StateTable", verdict.reason) if verdict.reason else ""


def controls_of(window) -> dict[str, list]:
    """Control name -> the widgets and actions it enables (see the module docstring)."""
    c, a, sd = window.controls, window.actions_by_name, window.sd_panel
    both = {name: [c.buttons[name], a[name]] for name in
            ("home", "home_recover", "start", "pause", "resume", "stop", "spindle_on", "spindle_off")}
    alarm = getattr(getattr(window, "grbl", None), "alarm", None)  # issue 23: the alarm banner's buttons
    grbl = {name: [a[name]] if name in a else [] for name in ("machine_settings", "unlock")}
    prompt = getattr(getattr(window, "program_stops", None), "prompt", None)  # a program stop's answers:
    if prompt is not None:  # Continue only once the machine is seen waiting (an SD run's notice
        both["resume"].append(prompt.continue_button)  # comes a moment before the status saying so)
        both["stop"].append(prompt.stop_button)
    if alarm is not None:
        both["home"].append(alarm.buttons["home"])
        both["stop"].append(alarm.buttons["reset"])
        grbl["unlock"].append(alarm.buttons["unlock"])
    return {
        **both,
        **grbl,
        "start_here": [window.program_panel.start_here_action],
        "jog": [*(() if c.jog.hold_mode else c.jog.buttons.values()),
                *(a[n] for n in a if n.startswith("jog_"))],
        "outline": [window.outline.button],
        "jog_hold": [*(c.jog.buttons.values() if c.jog.hold_mode else ())],  # and the keys: OperatorActions
        "zero": [*(b for k, b in c.buttons.items() if k.startswith("zero_")), a["zero_xy"], a["zero_z"],
                 *window.dro_panel.zero.values()],
        "check_mode": [c.check_mode, a["check"]],
        "override_travel": [c.override_travel],
        "sd_save": [sd.save],
        "sd_list": [sd.refresh],
        "sd_delete": [sd.delete],
        "sd_run": [sd.run],
        "mdi": [],  # the MDI box is the "query" control; each line is checked as its own control
        "query": [window.console.mdi, window.console.send],
        "connect": [window.connection.button, a["connect"]],
        "panel": list(window.machine_panel.buttons.values()),
        "cover_switch": [window.machine_panel.cover],
        "work_offsets": [window.dro_panel.wcs, window.dro_panel.table],
        "go_to": [window.dro_panel.go_to, window.dro_panel.go_zero],
        "custom_commands": list(window.custom_bar.buttons),
        **{control: [*c.overrides.controls(verb), *_actions_of(a, f"override_{verb.lower()}_")]
           for verb, control in OVERRIDE_CONTROLS.items()},
    }


def _actions_of(actions: dict, prefix: str) -> list:
    return [action for name, action in actions.items() if name.startswith(prefix)]


def apply(window, inputs: Inputs) -> dict[str, Verdict]:
    """Enable every control per the table; the reason goes into the tooltip of those off."""
    verdicts = decide_all(inputs)
    window.console.counters.setVisible(inputs.capabilities.crc_link)  # resends mean nothing without CRC
    for name, targets in controls_of(window).items():
        verdict = verdicts[name]
        reason = reason_text(verdict)
        for target in targets:
            target.setEnabled(verdict.allowed)
            _set_reason(target, reason)
    return verdicts


def _set_reason(target, reason: str) -> None:
    tip, old = target.toolTip(), target.property(SUFFIX) or ""
    base = tip[: -len(old)] if old and tip.endswith(old) else tip
    plain = target.text().replace("&", "") if isinstance(target, QAction) else None
    if plain is not None and base in (plain, plain.removesuffix("…")):
        base = ""  # a QAction's tooltip defaults to its text (without the ellipsis)
    suffix = "" if not reason else ("\n" if base else "") + QCoreApplication.translate(
        "StateTable", "Not now: %1").replace("%1", reason)
    target.setProperty(SUFFIX, suffix)
    target.setToolTip(base + suffix)
