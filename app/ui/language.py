"""The window's language: Qt translators for ``app/ui`` (``resources/i18n/cnc_<lang>.qm``)
and Qt's own dialogs (``qtbase_<lang>.qm`` when Qt ships one), the default ``QLocale``
(decimal separator of the numbers shown) and the core's gettext catalogue, switched
together. Installing a translator makes Qt send ``LanguageChange`` to every widget,
whose ``changeEvent`` re-labels it: no restart.

The choice is remembered in the window's settings (``language``); with none saved the
system locale decides (Vietnamese when it is Vietnamese, else English).
"""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QCoreApplication, QEvent, QLibraryInfo, QLocale, QTranslator

from app import i18n

QM_DIR = Path(__file__).resolve().parents[2] / "resources" / "i18n"
LANGUAGES = {"vi": "Tiếng Việt", "en": "English"}  # each shown in its own language
SETTING = "language"


def system_language() -> str:
    """"vi" when the system locale is Vietnamese, else "en"."""
    return "vi" if QLocale.system().language() == QLocale.Language.Vietnamese else "en"


def saved_language(qsettings) -> str:
    """The language the operator chose last time, or the system's."""
    code = str(qsettings.value(SETTING, "") or "")
    return code if code in LANGUAGES else system_language()


class Translations:
    """The translators installed in the application, replaced on each switch."""

    def __init__(self):
        self.code = ""
        self._installed: list[QTranslator] = []

    def apply(self, code: str) -> str:
        """Switch everything to ``code`` ("vi" or "en"; anything else: English)."""
        code = code if code in LANGUAGES else "en"
        app = QCoreApplication.instance()
        for translator in self._installed:
            app.removeTranslator(translator)
            translator.deleteLater()
        self._installed = [t for t in (_load(QM_DIR, f"cnc_{code}"), _load(_qt_dir(), f"qtbase_{code}")) if t]
        QLocale.setDefault(QLocale(code))
        i18n.set_language(code)
        self.code = code
        for translator in self._installed:
            app.installTranslator(translator)  # each one posts LanguageChange to every widget
        app.sendPostedEvents(None, QEvent.Type.LanguageChange)  # re-labelled when this returns
        return code


def _qt_dir() -> Path:
    return Path(QLibraryInfo.path(QLibraryInfo.LibraryPath.TranslationsPath))


def _load(folder: Path, name: str) -> QTranslator | None:
    translator = QTranslator(QCoreApplication.instance())
    return translator if translator.load(name, str(folder)) else None


TRANSLATIONS = Translations()


def apply_language(code: str) -> str:
    """Switch the whole application to ``code``; returns the language now in use."""
    return TRANSLATIONS.apply(code)


def current_language() -> str:
    return TRANSLATIONS.code or "en"
