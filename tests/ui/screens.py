"""Screenshots of the window: used by the tests (into tmp_path) and to refresh the ones
in docs/screenshots (``QT_QPA_PLATFORM=offscreen python -m tests.ui.screens``; in
Vietnamese: ``python -m tests.ui.screens docs/screenshots/vi vi``)."""

from __future__ import annotations

import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SAMPLE = ROOT / "resources" / "samples" / "potrace_logo.ngc"


def preview_shot(window, wait, out: Path) -> Path:
    """The window previewing a real Inkscape sample (picture -> potrace -> Gcodetools)."""
    window.open_file(SAMPLE)
    wait(lambda: window.loaded is not None and window.loaded.path == SAMPLE, 30)
    window.docks["program"].raise_()
    return _save(window, wait, out / "preview.png")


def job_shot(window, wait, out: Path, speed: float = 10, fraction: float = 0.45) -> list[Path]:
    """Mid-job on the simulator: tool marker, finished part, live plot, machine panel."""
    if window.loaded is None:
        window.open_file(SAMPLE)
        wait(lambda: window.loaded is not None, 30)
    start_on_simulator(window, wait, speed)
    total = len(window.loaded.program.line_map)
    wait(lambda: window.binder.job_done >= fraction * total, 300)
    window.docks["plot"].raise_()
    shots = [_save(window, wait, out / "job.png")]
    window.docks["panel"].raise_()
    window.plots.setCurrentWidget(window.diagnostics)
    shots.append(_save(window, wait, out / "job-diagnostics.png"))
    window.operator.stop()
    return shots


def start_on_simulator(window, wait, speed: float) -> None:
    """Connect to the built-in simulator at ``speed``, home, and start the open program."""
    sd = Path(tempfile.mkdtemp(prefix="cnc-sd-"))
    window.operator.connect_to(f"sim://?speed={speed:g}&sd={sd}")
    wait(lambda: window.binder.status is not None and window.controls.buttons["home"].isEnabled(), 60)
    window.operator.home("NORMAL")
    wait(lambda: window.binder.status.homed and window.binder.status.state == "IDLE", 120)
    window.operator.start()


def settings_shot(window, wait, out: Path) -> Path:
    """The settings dialog (language and the first tab)."""
    dialog = window.operator.edit_settings()
    dialog.resize(max(dialog.sizeHint().width(), 620), 560)
    path = _save(dialog, wait, out / "settings.png")
    dialog.reject()
    return path


def states_shots(window, wait, out: Path, speed: float = 10) -> list[Path]:
    """The window in the states of its state table (issue 20): not homed, homing, a job
    from the SD card and held, the cover open, the link lost, a machine without a card."""
    out = out / "states"
    if window.loaded is None:
        window.open_file(SAMPLE)
        wait(lambda: window.loaded is not None, 30)
    sd = Path(tempfile.mkdtemp(prefix="cnc-sd-"))
    (sd / "square.nc").write_text("".join(f"G01 X{20 + 40 * (i % 2)} Y{20 + 40 * (i // 2 % 2)} F200\n"
                                          for i in range(80)))
    window.operator.connect_to(f"sim://?speed={speed:g}&sd={sd}")
    wait(lambda: window.binder.status is not None and window.controls.buttons["home"].isEnabled(), 30)
    window.docks["sd"].raise_()
    shots = [_save(window, wait, out / "not-homed.png")]
    window.operator.home("NORMAL")
    shots.append(_save(window, wait, out / "homing.png"))
    wait(lambda: window.binder.status.homed and window.binder.status.state == "IDLE"
         and window.binder.pending_motion is None, 120)
    window.sd_panel.list_requested.emit()
    wait(lambda: window.sd_panel.lines_of("square.nc") > 0, 30)
    window.operator.run_from_sd("square.nc")
    wait(lambda: "S" in window.binder.status.flags and window.binder.status.done >= 8, 60)
    shots.append(_save(window, wait, out / "sd-run.png"))
    window.operator.pause()
    wait(lambda: window.binder.status.state == "HOLD" and window.controls.buttons["resume"].isEnabled(), 30)
    shots.append(_save(window, wait, out / "sd-held.png"))
    window.operator.stop()
    wait(lambda: window.binder.status.state == "IDLE" and "S" not in window.binder.status.flags, 60)
    sim = window.link.sim
    sim.panel.set_cover(True)
    window.docks["panel"].raise_()
    wait(lambda: "C" in window.binder.status.flags, 30)
    shots.append(_save(window, wait, out / "cover-open.png"))
    sim.panel.set_cover(False)
    wait(lambda: "C" not in window.binder.status.flags, 30)
    window.docks["sd"].raise_()
    shots.append(_no_card_shot(window, wait, out / "no-sd-card.png"))
    sim.faults.unplug()
    wait(window.alert.isVisible, 30)
    shots.append(_save(window, wait, out / "link-lost.png"))
    shots.append(_save(window.alert, wait, out / "link-lost-alert.png"))
    window.alert.hide()
    return shots


def _no_card_shot(window, wait, path: Path) -> Path:
    """The same window as a machine without card, panel or cover would show it (a GRBL
    driver's capabilities): the card's controls off, the reason in their tooltips."""
    from dataclasses import replace

    from app.capabilities import Capabilities
    from app.ui.enabler import apply

    binder = window.binder
    no_card = Capabilities(sd_card=False, exact_resume=False, crc_link=False, oled_panel=False, cover=False)
    real = binder.inputs
    binder.inputs = lambda: replace(real(), capabilities=no_card)
    apply(window, binder.inputs())
    shot = _save(window, wait, path)
    binder.inputs = real
    binder.refresh_enabled()
    return shot


def _save(window, wait, path: Path) -> Path:
    end = time.monotonic() + 0.4  # let the 30 Hz refresh and the plots catch up
    wait(lambda: time.monotonic() > end, 5)
    path.parent.mkdir(parents=True, exist_ok=True)
    window.grab().save(str(path))
    return path


def shot_window(language: str = "en"):
    """(window, wait): a 1600 x 1000 window in ``language`` with fresh settings, and a wait
    that runs the event loop until a predicate holds (TimeoutError after its seconds)."""
    from app.ui.language import apply_language
    from app.ui.main import make_app

    app = make_app()
    apply_language(language)

    def wait(predicate, timeout):
        end = time.monotonic() + timeout
        while not predicate():
            if time.monotonic() > end:
                raise TimeoutError("screenshot step timed out")
            app.processEvents()
            time.sleep(0.005)

    return fresh_window(), wait


def fresh_window():
    """A shown 1600 x 1000 window with settings of its own (a new folder)."""
    from app.ui.main_window import MainWindow
    from app.ui.notifier import Notifier

    config = Path(tempfile.mkdtemp(prefix="cnc-config-"))
    window = MainWindow(config_dir=config, notifier=Notifier(show_boxes=False), restore=False)
    window.resize(1600, 1000)
    window.show()
    return window


def main(out: str = "docs/screenshots", language: str = "en") -> int:
    window, wait = shot_window(language)
    shots = [preview_shot(window, wait, Path(out)), settings_shot(window, wait, Path(out))]
    shots += job_shot(window, wait, Path(out))
    window.close()
    states = fresh_window()
    shots += states_shots(states, wait, Path(out))
    states.close()
    print("\n".join(str(p) for p in shots))
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
