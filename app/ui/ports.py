"""Port discovery for the connection bar: the simulators first (the mill's, then a GRBL
machine's), then serial ports."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication

from app.i18n import localize


def _simulator() -> tuple[str, str]:
    return "sim://", QCoreApplication.translate("Ports", "Built-in simulator (sim://)")


def _grbl_simulator() -> tuple[str, str]:
    return "sim://grbl", QCoreApplication.translate("Ports", "Built-in GRBL 1.1 simulator (sim://grbl)")


def available_ports() -> list[tuple[str, str]]:
    """(url, description) pairs; never raises (a vanished port is simply not listed)."""
    try:
        from app.comm.transport import list_ports

        found = list(list_ports())
    except Exception:  # noqa: BLE001 (discovery must never break the window)
        found = [_simulator()]
    ports = [_pair(entry) for entry in found]
    if not any(url.startswith("sim://") for url, _ in ports):
        ports.insert(0, _simulator())
    if not any(url.startswith("sim://grbl") for url, _ in ports):
        ports.insert(1, _grbl_simulator())
    return ports


def _pair(entry) -> tuple[str, str]:
    if isinstance(entry, str):
        return entry, entry
    if isinstance(entry, tuple | list):
        url = str(entry[0])
        return url, (f"{url} — {localize(entry[1])}" if len(entry) > 1 and entry[1] else url)
    url = str(getattr(entry, "url", None) or getattr(entry, "device", entry))
    text = localize(getattr(entry, "description", "") or "")
    return url, (f"{url} — {text}" if text and text != url else url)
