"""Settings dialog: every field of the machine profile, one tab per section, each
range-checked with ``app.profile.check_value``; bad values are named and marked, and
the dialog stays open until they are fixed."""

from __future__ import annotations

from dataclasses import fields, replace

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, QEvent, Signal
from PySide6.QtWidgets import (
    QComboBox,
    QDialog,
    QDialogButtonBox,
    QFormLayout,
    QLabel,
    QLineEdit,
    QTabWidget,
    QVBoxLayout,
    QWidget,
)

from app.i18n import localize
from app.profile import MachineProfile, ProfileError, check_value, consistency_problems
from app.ui.language import LANGUAGES, current_language
from app.ui.numbers import fill, general, parse_number
from app.ui.settings.labels import CHOICES, choice_words, field_doc, field_label

TITLES = {
    "pid": QT_TRANSLATE_NOOP("SettingsDialog", "PID gains"),
    "motion": QT_TRANSLATE_NOOP("SettingsDialog", "Feeds && motion"),
    "link": QT_TRANSLATE_NOOP("SettingsDialog", "Link && heartbeat"),
    "axis": QT_TRANSLATE_NOOP("SettingsDialog", "Axis drive"),
    "spindle": QT_TRANSLATE_NOOP("SettingsDialog", "Spindle"),
    "travel": QT_TRANSLATE_NOOP("SettingsDialog", "Travel && offset"),
    "job": QT_TRANSLATE_NOOP("SettingsDialog", "Program stops && end"),
}
ORDER = ("pid", "motion", "link", "axis", "spindle", "travel", "job")


class ChoiceEdit(QComboBox):
    """A field that is one of a few numbered choices, shown in words; ``text``/``setText``
    read and write the number as the line edits of the other fields do."""

    def __init__(self, words: list[str], value: str, parent=None):
        super().__init__(parent)
        self.set_words(words)
        self.setText(value)

    def set_words(self, words: list[str]) -> None:
        index = max(self.currentIndex(), 0)
        self.clear()
        for number, word in enumerate(words):
            self.addItem(word, number)
        self.setCurrentIndex(min(index, len(words) - 1))

    def text(self) -> str:
        return str(self.currentData())

    def setText(self, value: str) -> None:  # noqa: N802 (the QLineEdit name the dialog uses)
        index = self.findData(int(float(value))) if value.strip() else -1
        self.setCurrentIndex(max(index, 0))


class SettingsDialog(QDialog):
    language_chosen = Signal(str)  # "vi" or "en": the window switches at once

    def __init__(self, profile: MachineProfile, parent=None):
        super().__init__(parent)
        self.profile = profile
        self.edits: dict[tuple[str, str], QLineEdit] = {}
        self.labels: dict[tuple[str, str], QLabel] = {}
        self.language = QComboBox()
        for code, name in LANGUAGES.items():
            self.language.addItem(name, code)
        self.language.setCurrentIndex(max(self.language.findData(current_language()), 0))
        self.language.activated.connect(lambda i: self.language_chosen.emit(self.language.itemData(i)))
        self.language_label = QLabel()
        self.language_label.setBuddy(self.language)
        language_row = QFormLayout()
        language_row.addRow(self.language_label, self.language)
        self.tabs = QTabWidget()
        self.tabs.setUsesScrollButtons(False)  # every tab title whole (Vietnamese ones are longer)
        for section in ORDER:
            self.tabs.addTab(self._section_page(section), "")
        self.error = QLabel("")
        self.error.setStyleSheet("color: #e05050;")
        self.error.setWordWrap(True)
        note = self.note = QLabel()
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
        layout.addLayout(language_row)
        layout.addWidget(self.tabs)
        layout.addWidget(note)
        layout.addWidget(self.error)
        layout.addWidget(buttons)
        self.retranslate_ui()

    def retranslate_ui(self) -> None:
        self.setWindowTitle(self.tr("Settings"))
        self.language_label.setText(self.tr("&Language"))
        self.language.setToolTip(self.tr("the window's language; it changes at once"))
        for index, section in enumerate(ORDER):
            self.tabs.setTabText(index, QCoreApplication.translate("SettingsDialog", TITLES[section]))
        note = self.tr("PID gains are pushed to the machine (SET) when you press OK while connected.")
        self.note.setText(note)
        for section in ORDER:
            self._label_section(section)

    def changeEvent(self, event) -> None:  # noqa: N802 (Qt override)
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate_ui()
        super().changeEvent(event)

    def _label_section(self, section: str) -> None:
        for spec in fields(getattr(self.profile, section)):
            lo, hi = spec.metadata["range"]
            doc = field_doc(spec.metadata.get("doc", ""))
            tip = fill(self.tr("range %1 … %2"), general(lo), general(hi))
            edit = self.edits[section, spec.name]
            if isinstance(edit, ChoiceEdit):
                edit.set_words(choice_words(spec.name))
                edit.setToolTip(field_label(spec.name))
            else:
                edit.setToolTip(f"{doc} — {tip}" if doc else tip)
            self.labels[section, spec.name].setText(field_label(spec.name))

    def _section_page(self, section: str) -> QWidget:
        page = QWidget()
        form = QFormLayout(page)
        values = getattr(self.profile, section)
        for spec in fields(values):
            value = general(getattr(values, spec.name))
            edit = ChoiceEdit(choice_words(spec.name), value) if spec.name in CHOICES else QLineEdit(value)
            self.edits[section, spec.name] = edit
            self.labels[section, spec.name] = label = QLabel()
            form.addRow(label, edit)
        return page

    def restore_defaults(self) -> None:
        self._fill(MachineProfile())

    def _fill(self, profile: MachineProfile) -> None:
        for (section, key), edit in self.edits.items():
            edit.setText(general(getattr(getattr(profile, section), key)))

    def checked_profile(self) -> tuple[MachineProfile | None, list[str]]:
        """The profile the fields describe, or None and the problems found."""
        problems, changes = [], {}
        for (section, key), edit in self.edits.items():
            try:
                title = QCoreApplication.translate("SettingsDialog", TITLES[section])
                value = check_value(getattr(self.profile, section), key, parse_number(edit.text()), title,
                                    text=True)
                changes.setdefault(section, {})[key] = value
                edit.setStyleSheet("")
            except ProfileError as exc:
                problems.append(localize(exc.args[0] if exc.args else str(exc)).replace("&&", "&"))
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
            self.error.setText(fill(self.tr("Not saved: %1"), "; ".join(problems)))
            return
        self.profile = profile
        super().accept()
