"""Numbers shown in the window follow the chosen language (Vietnamese: 1.234,5;
English: 1,234.5); G-code, the protocol and files always use a point. Entry fields
take either separator (``parse_number``)."""

from __future__ import annotations

from PySide6.QtCore import QLocale


def decimal(value: float, places: int = 2) -> str:
    """``value`` with ``places`` decimals in the current language."""
    return QLocale().toString(float(value), "f", places)


def integer(value: int) -> str:
    """A count with the language's thousands separator."""
    return QLocale().toString(int(value))


def general(value: float) -> str:
    """Like ``f"{value:g}"`` with the language's decimal separator."""
    text = f"{value:g}"
    return text.replace(".", QLocale().decimalPoint()) if "e" not in text else text


def parse_number(text: str) -> str:
    """Text typed with a decimal comma or point, as the point form Python reads
    ("1,5" -> "1.5", "1.234,5" -> "1234.5", "1,234.5" -> "1234.5")."""
    text = text.strip().replace(" ", "").replace("\u00a0", "")
    if "," in text and "." in text:
        decimal_mark = "," if text.rfind(",") > text.rfind(".") else "."
        group = "." if decimal_mark == "," else ","
        text = text.replace(group, "")
    return text.replace(",", ".")


def fill(template: str, *values) -> str:
    """Qt's ``%1``, ``%2``... markers of a translated ``template`` replaced by ``values``
    (what ``QString.arg`` does; PySide6 returns plain ``str``)."""
    for number in range(len(values), 0, -1):  # %10 before %1
        template = template.replace(f"%{number}", str(values[number - 1]))
    return template
