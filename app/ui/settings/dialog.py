"""Settings dialog: every field of the machine profile, one tab per section, each
range-checked with ``app.profile.check_value``; bad values are named and marked, and
the dialog stays open until they are fixed."""

from __future__ import annotations

from dataclasses import fields, replace

from PySide6.QtWidgets import (
    QDialog,
    QDialogButtonBox,
    QFormLayout,
    QLabel,
    QLineEdit,
    QTabWidget,
    QVBoxLayout,
    QWidget,
)

from app.profile import MachineProfile, ProfileError, check_value, consistency_problems

TITLES = {
    "pid": "PID gains", "motion": "Feeds && motion", "link": "Link && heartbeat",
    "axis": "Axis drive", "spindle": "Spindle", "travel": "Travel && offset",
}
ORDER = ("pid", "motion", "link", "axis", "spindle", "travel")


class SettingsDialog(QDialog):
    def __init__(self, profile: MachineProfile, parent=None):
        super().__init__(parent)
        self.setWindowTitle("Settings")
        self.profile = profile
        self.edits: dict[tuple[str, str], QLineEdit] = {}
        self.tabs = QTabWidget()
        for section in ORDER:
            self.tabs.addTab(self._section_page(section), TITLES[section])
        self.error = QLabel("")
        self.error.setStyleSheet("color: #e05050;")
        self.error.setWordWrap(True)
        note = QLabel("PID gains are pushed to the machine (SET) when you press OK while connected.")
        note.setWordWrap(True)
        buttons = QDialogButtonBox(
            QDialogButtonBox.StandardButton.Ok
            | QDialogButtonBox.StandardButton.Cancel
            | QDialogButtonBox.StandardButton.RestoreDefaults
        )
        buttons.accepted.connect(self.accept)
        buttons.rejected.connect(self.reject)
        buttons.button(QDialogButtonBox.StandardButton.RestoreDefaults).clicked.connect(self.restore_defaults)
        self.button_box = buttons
        layout = QVBoxLayout(self)
        layout.addWidget(self.tabs)
        layout.addWidget(note)
        layout.addWidget(self.error)
        layout.addWidget(buttons)

    def _section_page(self, section: str) -> QWidget:
        page = QWidget()
        form = QFormLayout(page)
        values = getattr(self.profile, section)
        for spec in fields(values):
            lo, hi = spec.metadata["range"]
            edit = QLineEdit(f"{getattr(values, spec.name):g}")
            doc = spec.metadata.get("doc", "")
            edit.setToolTip(f"{doc + ' — ' if doc else ''}range {lo:g} … {hi:g}")
            self.edits[section, spec.name] = edit
            form.addRow(spec.name.replace("_", " "), edit)
        return page

    def restore_defaults(self) -> None:
        self._fill(MachineProfile())

    def _fill(self, profile: MachineProfile) -> None:
        for (section, key), edit in self.edits.items():
            edit.setText(f"{getattr(getattr(profile, section), key):g}")

    def checked_profile(self) -> tuple[MachineProfile | None, list[str]]:
        """The profile the fields describe, or None and the problems found."""
        problems, changes = [], {}
        for (section, key), edit in self.edits.items():
            try:
                value = check_value(getattr(self.profile, section), key, edit.text().strip(), TITLES[section],
                                    text=True)
                changes.setdefault(section, {})[key] = value
                edit.setStyleSheet("")
            except ProfileError as exc:
                problems.append(str(exc).replace("&&", "&"))
                edit.setStyleSheet("background: rgba(255, 60, 60, 80);")
        if problems:
            return None, problems
        sections = {name: replace(getattr(self.profile, name), **vals) for name, vals in changes.items()}
        profile = replace(self.profile, **sections)
        rules = consistency_problems(profile)
        return (None, rules) if rules else (profile, [])

    def accept(self) -> None:
        profile, problems = self.checked_profile()
        if problems:
            self.error.setText("Not saved: " + "; ".join(problems))
            return
        self.profile = profile
        super().accept()
