"""Operator messages of the Qt-free core (``app.gcode``, ``app.comm``) in the
operator's language, through Python's ``gettext``.

A core module builds a message with ``msg("unknown word {letter}", letter="Q")``: a
``Message`` is a plain ``str`` holding the English text (so logs, tests and ``==`` see
English) that also keeps its template and values. Whoever shows it to an operator calls
``localize(text)``: the template is looked up in the catalogue of the current language
(``resources/i18n/<lang>/LC_MESSAGES/cnc.mo``) and filled with the same values; a text
with no catalogue entry stays as it is.

The language follows ``LANGUAGE``/``LC_ALL``/``LC_MESSAGES``/``LANG`` (as ``gettext``
does) until ``set_language(code)`` chooses one ("vi", "en"); the window calls it when
the operator switches. Adding a message: write it with ``msg()`` (or ``N_()`` for a
constant looked up later), run ``make i18n``, translate it in the ``.po``.
"""

from __future__ import annotations

import gettext as _gettext
from pathlib import Path

DOMAIN = "cnc"
LOCALE_DIR = Path(__file__).resolve().parent.parent / "resources" / "i18n"
LANGUAGES = ("vi", "en")

_catalogue: _gettext.NullTranslations | None = None


def N_(template: str) -> str:  # noqa: N802 (the gettext convention)
    """Marks ``template`` for the catalogue without translating it now."""
    return template


class Message(str):
    """English text that remembers its template and values, for ``localize``."""

    template: str
    args: dict

    def __new__(cls, template: str, **args) -> Message:
        self = super().__new__(cls, template.format(**args) if args else template)
        self.template = template
        self.args = args
        return self

    def __reduce__(self):  # the helper process pickles diagnostics
        return (_rebuild, (self.template, self.args))


def _rebuild(template: str, args: dict) -> Message:
    return Message(template, **args)


def msg(template: str, **args) -> Message:
    """A core message: ``template`` with ``{name}`` fields, filled with ``args``."""
    return Message(template, **args)


def joined(messages) -> str:
    """``messages`` as one message, ``"; "`` between them ("" for none), each still
    translated on its own by ``localize``."""
    out = ""
    for message in messages:
        out = msg("{first}; {then}", first=out, then=message) if out else message
    return out


def set_language(code: str | None) -> None:
    """Show core messages in ``code`` ("vi", "en"); None: follow the environment."""
    global _catalogue
    languages = [code] if code else None
    _catalogue = _gettext.translation(DOMAIN, LOCALE_DIR, languages=languages, fallback=True)


def language() -> str:
    """The language core messages are shown in now ("en" when no catalogue applies)."""
    info = _translations().info()
    return info.get("language", "en") or "en"


def _translations() -> _gettext.NullTranslations:
    if _catalogue is None:
        set_language(None)
    return _catalogue


def gettext(text: str) -> str:
    """``text`` in the current language (itself when the catalogue has no entry)."""
    return _translations().gettext(text)


class _CommaDecimal(float):
    """A number formatted with a decimal comma (and a point between thousands)."""

    def __format__(self, spec: str) -> str:
        return float.__format__(self, spec).translate(_SWAP_SEPARATORS)


class _CommaInt(int):
    """A whole number whose thousands are separated by a point (``{n:,}``: 1.000.000)."""

    def __format__(self, spec: str) -> str:
        return int.__format__(self, spec).translate(_SWAP_SEPARATORS)


_SWAP_SEPARATORS = str.maketrans(".,", ",.")
COMMA_DECIMAL = frozenset({"vi"})  # languages that write 1,5 for one and a half


def _value(value):
    if isinstance(value, Message):
        return localize(value)
    if isinstance(value, float) and language() in COMMA_DECIMAL:
        return _CommaDecimal(value)
    if isinstance(value, int) and not isinstance(value, bool) and language() in COMMA_DECIMAL:
        return _CommaInt(value)

    return value


def localize(text: str) -> str:
    """A core text for the operator: a ``Message`` in the current language, any other
    string looked up whole in the catalogue (itself when not there)."""
    if isinstance(text, Message):
        values = {k: _value(v) for k, v in text.args.items()}
        template = gettext(text.template)
        try:
            return template.format(**values) if values else template
        except (KeyError, IndexError, ValueError):  # a bad translation must not hide the message
            return str(text)
    return gettext(text) if text else text
