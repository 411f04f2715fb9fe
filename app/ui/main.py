"""``cnc-gui``: the operator's window.

``cnc-gui [FILE]`` opens the window (on the built-in simulator's port list);
``cnc-gui --demo FILE [--speed X] [--screenshot OUT.png]`` opens FILE, connects to the
simulator, homes, runs the job to the end at ``speed`` times real time, saves a
screenshot of the window, prints a one-line summary and exits 0 (1 if the job failed).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path


def parse_args(argv: list[str] | None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(prog="cnc-gui", description="Desktop controller for a small CNC mill.")
    parser.add_argument("file", nargs="?", help="G-code file to open")
    parser.add_argument("--demo", metavar="FILE", help="run FILE on the simulator to the end, then exit")
    parser.add_argument("--speed", type=float, default=20.0, help="simulator speed factor for --demo")
    parser.add_argument("--screenshot", metavar="PNG", help="where --demo saves a screenshot of the window")
    parser.add_argument("--connect", metavar="URL", help="connect at start (e.g. sim:// or /dev/ttyUSB0)")
    parser.add_argument("--dark", action="store_true", help="dark palette")
    parser.add_argument("--lang", choices=("vi", "en"),
                        help="language for this run (default: the one last chosen, else the system's)")
    return parser.parse_args(argv)


GIL_SWITCH_S = 0.0005


def make_app():
    """The QApplication, made once. Also shortens the GIL switch interval: the serial
    worker thread runs Python most of the time a job streams, and with the default
    5 ms every call from Qt into Python (each item's paint and boundingRect in a
    frame) could wait that long for the GIL; tens of such waits stalled a frame by
    50-100 ms. At 0.5 ms the GUI thread gets the GIL back at once (bench_ui measures it)."""
    sys.setswitchinterval(GIL_SWITCH_S)
    from PySide6.QtCore import QCoreApplication, Qt
    from PySide6.QtGui import QGuiApplication
    from PySide6.QtWidgets import QApplication

    QCoreApplication.setOrganizationName("cnc-mill-controller")
    QCoreApplication.setApplicationName("cnc-gui")
    if QApplication.instance() is not None:
        return QApplication.instance()
    # Fractional scale factors (125 %, 150 %) as they are: crisp on high-DPI screens.
    QGuiApplication.setHighDpiScaleFactorRoundingPolicy(Qt.HighDpiScaleFactorRoundingPolicy.PassThrough)
    return QApplication(sys.argv[:1])


def main(argv: list[str] | None = None) -> int:
    args = parse_args(argv)
    app = make_app()
    from PySide6.QtCore import QSettings

    from app.ui.language import apply_language, saved_language
    from app.ui.main_window import MainWindow, default_config_dir
    from app.ui.palette import apply_dark

    settings = QSettings(str(default_config_dir() / "window.ini"), QSettings.Format.IniFormat)
    apply_language(args.lang or saved_language(settings))  # before the widgets are made
    window = MainWindow(restore=not args.demo)
    if args.demo:
        window.resize(1600, 1000)
    if args.dark or window.prefs.dark:
        apply_dark(app, True)
    window.show()
    if args.demo:
        from app.ui.demo import DemoRunner

        demo = DemoRunner(window, Path(args.demo), args.speed, args.screenshot)
        demo.start()
        app.exec()
        print(demo.summary(), flush=True)
        return demo.exit_code
    if args.file:
        window.open_file(args.file)
    if args.connect:
        window.operator.connect_to(args.connect)
    return app.exec()


if __name__ == "__main__":
    sys.exit(main())
