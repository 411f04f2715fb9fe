"""The one error a feature raises: which parameter is wrong and the rule it breaks."""

from __future__ import annotations

from app.i18n import localize, msg


class FeatureError(ValueError):
    """A bad feature parameter: ``field`` (the dataclass field, e.g. ``"stepover"``) and
    ``rule`` (what it must be, with the value given; a core message, see ``app.i18n``).
    ``str()`` is ``"field: rule"`` in English, ``localized()`` in the operator's language."""

    def __init__(self, field: str, rule: str) -> None:
        super().__init__(msg("{field}: {rule}", field=field, rule=rule))
        self.field = field
        self.rule = rule

    def localized(self) -> str:
        """``field: rule`` in the operator's language."""
        return localize(self.args[0])


def require(ok: bool, field: str, rule: str) -> None:
    """Raise ``FeatureError(field, rule)`` unless ``ok``."""
    if not ok:
        raise FeatureError(field, rule)


def positive(value: float, field: str) -> None:
    require(value > 0, field, msg("must be > 0 (got {value:g})", value=float(value)))


def not_negative(value: float, field: str) -> None:
    require(value >= 0, field, msg("must be >= 0 (got {value:g})", value=float(value)))
