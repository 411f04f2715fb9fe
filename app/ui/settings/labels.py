"""Labels and tooltips of the machine profile's fields in the settings dialog, each
translated in the "SettingsFields" context. A field missing here shows its name (and
the language test names it)."""

from __future__ import annotations

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication

LABELS = {
    "supply_v": QT_TRANSLATE_NOOP("SettingsFields", "supply voltage (V)"),
    "bridge_drop_v": QT_TRANSLATE_NOOP("SettingsFields", "bridge drop (V)"),
    "no_load_rpm": QT_TRANSLATE_NOOP("SettingsFields", "no-load speed (rpm)"),
    "gear_ratio": QT_TRANSLATE_NOOP("SettingsFields", "gear ratio"),
    "encoder_ppr": QT_TRANSLATE_NOOP("SettingsFields", "encoder pulses per turn"),
    "quadrature": QT_TRANSLATE_NOOP("SettingsFields", "quadrature edges"),
    "lead_mm": QT_TRANSLATE_NOOP("SettingsFields", "screw lead (mm)"),
    "x_max": QT_TRANSLATE_NOOP("SettingsFields", "X travel (mm)"),
    "y_max": QT_TRANSLATE_NOOP("SettingsFields", "Y travel (mm)"),
    "z_max": QT_TRANSLATE_NOOP("SettingsFields", "Z travel (mm)"),
    "home_backoff_mm": QT_TRANSLATE_NOOP("SettingsFields", "home back-off (mm)"),
    "work_x": QT_TRANSLATE_NOOP("SettingsFields", "work offset X (mm)"),
    "work_y": QT_TRANSLATE_NOOP("SettingsFields", "work offset Y (mm)"),
    "work_z": QT_TRANSLATE_NOOP("SettingsFields", "work offset Z (mm)"),
    "rapid_mm_min": QT_TRANSLATE_NOOP("SettingsFields", "rapid feed (mm/min)"),
    "max_feed_mm_min": QT_TRANSLATE_NOOP("SettingsFields", "maximum feed (mm/min)"),
    "accel_mm_s2": QT_TRANSLATE_NOOP("SettingsFields", "acceleration (mm/s²)"),
    "jerk_mm_s3": QT_TRANSLATE_NOOP("SettingsFields", "jerk (mm/s³)"),
    "junction_deviation_mm": QT_TRANSLATE_NOOP("SettingsFields", "junction deviation (mm)"),
    "arc_tolerance_mm": QT_TRANSLATE_NOOP("SettingsFields", "arc tolerance (mm)"),
    "homing_mm_min": QT_TRANSLATE_NOOP("SettingsFields", "homing feed (mm/min)"),
    "kp": QT_TRANSLATE_NOOP("SettingsFields", "Kp (proportional)"),
    "ki": QT_TRANSLATE_NOOP("SettingsFields", "Ki (integral)"),
    "kd": QT_TRANSLATE_NOOP("SettingsFields", "Kd (derivative)"),
    "rate_hz": QT_TRANSLATE_NOOP("SettingsFields", "control loop rate (Hz)"),
    "following_error_mm": QT_TRANSLATE_NOOP("SettingsFields", "following error limit (mm)"),
    "heartbeat_s": QT_TRANSLATE_NOOP("SettingsFields", "heartbeat period (s)"),
    "degraded_s": QT_TRANSLATE_NOOP("SettingsFields", "degraded after (s)"),
    "lost_s": QT_TRANSLATE_NOOP("SettingsFields", "lost after (s)"),
    "baud": QT_TRANSLATE_NOOP("SettingsFields", "baud rate"),
    "optional_stop": QT_TRANSLATE_NOOP("SettingsFields", "optional stop M01 (1 holds, 0 skips)"),
    "stop_spindle": QT_TRANSLATE_NOOP("SettingsFields", "stop the spindle at M00/M01"),
    "after_job": QT_TRANSLATE_NOOP("SettingsFields", "after the job"),
}
DOCS = (  # the profile's own field docs (app/profile.py), listed so they are translated
    QT_TRANSLATE_NOOP("SettingsFields", "motor supply voltage"),
    QT_TRANSLATE_NOOP("SettingsFields", "voltage lost in the L298N"),
    QT_TRANSLATE_NOOP("SettingsFields", "output shaft rpm unloaded at supply_v"),
    QT_TRANSLATE_NOOP("SettingsFields", "motor turns per output turn"),
    QT_TRANSLATE_NOOP("SettingsFields", "pulses per motor turn per channel"),
    QT_TRANSLATE_NOOP("SettingsFields", "edges counted per pulse"),
    QT_TRANSLATE_NOOP("SettingsFields", "lead screw travel per output turn"),
    QT_TRANSLATE_NOOP("SettingsFields", "back-off from each switch after homing"),
    QT_TRANSLATE_NOOP("SettingsFields", "default work offset X"),
    QT_TRANSLATE_NOOP("SettingsFields", "default work offset Y"),
    QT_TRANSLATE_NOOP("SettingsFields", "default work offset Z"),
    QT_TRANSLATE_NOOP("SettingsFields", "G00 feed"),
    QT_TRANSLATE_NOOP("SettingsFields", "cap on programmed feeds"),
    QT_TRANSLATE_NOOP("SettingsFields", "chord error when arcs become lines"),
    QT_TRANSLATE_NOOP("SettingsFields", "M01 holds the job (1) or is skipped (0)"),
    QT_TRANSLATE_NOOP("SettingsFields", "M00/M01 also stop the spindle (1)"),
    QT_TRANSLATE_NOOP("SettingsFields", "after the job: 0 stay, 1 lift Z, 2 work zero X0 Y0, 3 home"),
)
# Fields whose number is one of a few choices: the words shown for 0, 1, 2, ...
CHOICES = {
    "after_job": (QT_TRANSLATE_NOOP("SettingsFields", "stay where it ends"),
                  QT_TRANSLATE_NOOP("SettingsFields", "lift Z to the top"),
                  QT_TRANSLATE_NOOP("SettingsFields", "lift Z, then go to work X0 Y0"),
                  QT_TRANSLATE_NOOP("SettingsFields", "home the machine")),
    "optional_stop": (QT_TRANSLATE_NOOP("SettingsFields", "skip M01"),
                      QT_TRANSLATE_NOOP("SettingsFields", "hold at M01")),
    "stop_spindle": (QT_TRANSLATE_NOOP("SettingsFields", "keep the spindle turning"),
                     QT_TRANSLATE_NOOP("SettingsFields", "stop the spindle")),
}


def choice_words(name: str) -> list[str]:
    """The words of field ``name``'s choices in the current language ([] if it has none)."""
    return [QCoreApplication.translate("SettingsFields", text) for text in CHOICES.get(name, ())]


def field_label(name: str) -> str:
    """The label of profile field ``name`` in the current language."""
    if name in LABELS:
        return QCoreApplication.translate("SettingsFields", LABELS[name])
    return name.replace("_", " ")


def field_doc(doc: str) -> str:
    """A field's doc from ``app/profile.py`` in the current language."""
    return QCoreApplication.translate("SettingsFields", doc) if doc else ""
