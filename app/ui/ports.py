"""Port discovery for the connection bar: the simulators first (the mill's, then a GRBL
machine's), then serial ports, then the pseudo-terminals of ``cnc-sim --pty`` processes
running on this computer."""

from __future__ import annotations

import os
from pathlib import Path

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
    listed = {url for url, _ in ports}
    said = QCoreApplication.translate("Ports", "simulated machine (cnc-sim, process %1)")
    for path, pid in sim_ptys():
        if path not in listed:
            ports.append((path, f"{path} — {said.replace('%1', str(pid))}"))
    return ports


SIM_NAMES = ("backend_sim", "cnc-sim")


def sim_ptys(proc: Path = Path("/proc")) -> list[tuple[str, int]]:
    """(pseudo-terminal, process id) of every ``cnc-sim --pty`` this user can see: the
    ``/dev/pts/N`` its process holds open beyond its own standard streams (Linux; [] where
    there is no ``/proc``). Never raises: a process that ends meanwhile is left out."""
    found = []
    try:
        entries = [p for p in proc.iterdir() if p.name.isdigit()]
    except OSError:
        return []
    for entry in entries:
        try:
            args = (entry / "cmdline").read_bytes().split(b"\0")
            if not any(name.encode() in arg for arg in args for name in SIM_NAMES) or b"--pty" not in args:
                continue
            for fd in (entry / "fd").iterdir():
                target = os.readlink(fd)
                held = (target, int(entry.name))
                if int(fd.name) > 2 and target.startswith("/dev/pts/") and held not in found:
                    found.append(held)
        except (OSError, ValueError):
            continue
    return sorted(found)


def _pair(entry) -> tuple[str, str]:
    if isinstance(entry, str):
        return entry, entry
    if isinstance(entry, tuple | list):
        url = str(entry[0])
        return url, (f"{url} — {localize(entry[1])}" if len(entry) > 1 and entry[1] else url)
    url = str(getattr(entry, "url", None) or getattr(entry, "device", entry))
    text = localize(getattr(entry, "description", "") or "")
    return url, (f"{url} — {text}" if text and text != url else url)
