"""The keyboard's hold-to-jog, as Candle and UGS bind it: the arrow keys jog X and Y,
PageUp/PageDown jog Z, for as long as they are held; two arrow keys jog the diagonal.

``HoldJogKeys(window, panel)`` filters the application's key events for ``window``: a
press (auto-repeats ignored) of one of ``KEYS`` with no modifier calls
``panel.set_held(key, True)``, its release ``set_held(key, False)``. Keys typed into a
text field, a spin box or a combo box stay theirs. When the window loses the keyboard
(another window, the application in the background) every held key counts as released,
since its release would never come here.
"""

from __future__ import annotations

from PySide6.QtCore import QEvent, QObject, Qt
from PySide6.QtWidgets import QAbstractSpinBox, QApplication, QComboBox, QLineEdit, QPlainTextEdit, QTextEdit

KEYS = {Qt.Key.Key_Left: "X-", Qt.Key.Key_Right: "X+", Qt.Key.Key_Up: "Y+", Qt.Key.Key_Down: "Y-",
        Qt.Key.Key_PageUp: "Z+", Qt.Key.Key_PageDown: "Z-"}
TYPING = (QLineEdit, QPlainTextEdit, QTextEdit, QAbstractSpinBox, QComboBox)
FREE = Qt.KeyboardModifier.NoModifier | Qt.KeyboardModifier.KeypadModifier


class HoldJogKeys(QObject):
    """See the module docstring."""

    def __init__(self, window, panel) -> None:
        super().__init__(window)
        self.window, self.panel = window, panel
        self.pressed: set[str] = set()
        QApplication.instance().installEventFilter(self)

    def eventFilter(self, watched, event) -> bool:  # noqa: N802 (Qt override)
        kind = event.type()
        if kind in (QEvent.Type.KeyPress, QEvent.Type.KeyRelease):
            return self._key(watched, event, kind == QEvent.Type.KeyPress)
        if kind == QEvent.Type.ApplicationDeactivate or (kind == QEvent.Type.WindowDeactivate
                                                         and watched is self.window):
            self.release_all()
        return False

    def _key(self, watched, event, down: bool) -> bool:
        key = KEYS.get(Qt.Key(event.key()))
        if key is None or not self._ours(watched):
            return False
        if down and (event.modifiers() & ~FREE or event.isAutoRepeat()):
            return event.isAutoRepeat() and key in self.pressed  # a held key's repeats are ours
        if not down and event.isAutoRepeat():
            return key in self.pressed
        if down:
            self.pressed.add(key)
        elif key not in self.pressed:
            return False
        else:
            self.pressed.discard(key)
        self.panel.set_held(key, down)
        return True

    def _ours(self, watched) -> bool:
        """A key event for this window, not for a field the operator types into."""
        if not isinstance(watched, QObject) or not hasattr(watched, "window"):
            return False
        try:
            if watched.window() is not self.window:
                return False
        except TypeError:
            return False
        typing = (watched, QApplication.focusWidget())  # an ignored key goes on to the parents
        return not any(isinstance(widget, TYPING) for widget in typing)

    def release_all(self) -> None:
        for key in list(self.pressed):
            self.pressed.discard(key)
            self.panel.set_held(key, False)

    def detach(self) -> None:
        QApplication.instance().removeEventFilter(self)
