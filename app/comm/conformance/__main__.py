"""``python -m app.comm.conformance PORT [--quick] [--report FILE] [--section NAME]``.

Runs the checks of docs/protocol.md against the machine on PORT (a serial port, or
any pyserial URL: ``socket://``, ``sim://?speed=10``) and prints a pass/fail table;
``--report FILE`` also writes it (``.json``: JSON, else Markdown). Exit status 0 when
every check passed, 1 when one failed, 2 when the port cannot be opened.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import serial

from app.comm.conformance.result import failed, render_json, render_markdown, render_text
from app.comm.conformance.runner import SECTIONS, run

HANDLER_PACKAGES = ("backend_sim",)  # pyserial finds sim:// there; the kit never imports it


def open_port(url: str):
    for package in HANDLER_PACKAGES:
        if package not in serial.protocol_handler_packages:
            serial.protocol_handler_packages.append(package)
    return serial.serial_for_url(url, baudrate=115200, timeout=0.01)


def panel_cover(port):
    """``open(bool)`` through the simulator's panel when the port is ``sim://`` (its
    documented ``sim.panel.set_cover``); None for a real port."""
    sim = getattr(port, "sim", None)
    panel = getattr(sim, "panel", None)
    return getattr(panel, "set_cover", None)


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="python -m app.comm.conformance",
        description="Check a machine's firmware against docs/protocol.md.",
    )
    p.add_argument("port", help="serial port or pyserial URL (/dev/ttyACM0, socket://host:port, sim://)")
    p.add_argument("--quick", action="store_true", help="leave out homing and real motion")
    p.add_argument("--report", metavar="FILE", help="write the table to FILE (.json: JSON, else Markdown)")
    p.add_argument("--section", action="append", choices=list(SECTIONS), help="run only these sections")
    return p


def write_report(path: str, results, title: str) -> None:
    text = render_json(results, title) if path.endswith(".json") else render_markdown(results, title)
    Path(path).write_text(text, encoding="utf-8")


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        port = open_port(args.port)
    except (OSError, ValueError) as exc:
        print(f"conformance: cannot open {args.port}: {exc}", file=sys.stderr)
        return 2
    try:
        results = run(
            port,
            quick=args.quick,
            sections=args.section,
            cover=panel_cover(port),
            progress=lambda text: print(f"... {text}", file=sys.stderr, flush=True),
        )
    finally:
        port.close()
    print(render_text(results))
    if args.report:
        write_report(args.report, results, args.port)
    return 1 if failed(results) else 0


if __name__ == "__main__":
    sys.exit(main())
