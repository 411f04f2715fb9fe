"""The one error a feature raises: which parameter is wrong and the rule it breaks."""

from __future__ import annotations


class FeatureError(ValueError):
    """A bad feature parameter: ``field`` (the dataclass field, e.g. ``"stepover"``) and
    ``rule`` (what it must be, with the value given). ``str()`` is ``"field: rule"``."""

    def __init__(self, field: str, rule: str) -> None:
        super().__init__(f"{field}: {rule}")
        self.field = field
        self.rule = rule


def require(ok: bool, field: str, rule: str) -> None:
    """Raise ``FeatureError(field, rule)`` unless ``ok``."""
    if not ok:
        raise FeatureError(field, rule)


def positive(value: float, field: str) -> None:
    require(value > 0, field, f"must be > 0 (got {value:g})")


def not_negative(value: float, field: str) -> None:
    require(value >= 0, field, f"must be >= 0 (got {value:g})")
