"""A screenshot of the feature dialog on the CAPP paper's worked example (the island
profile of its figure 4, parameters of its program N5-N6), for the README:
``QT_QPA_PLATFORM=offscreen python -m tests.ui.feature_screens [OUT [LANG]]`` writes
docs/screenshots/features-island.png (``docs/screenshots/vi vi``: the Vietnamese one);
the tests call ``island_shot(dialog, tmp_path)``."""

from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
# The paper's contour, moved 30 mm in X and Y: with 15 mm of stock around it and a 12 mm
# tool the original position would reach past X 0 and Y 0 of the travel.
PAPER_MOVED = ("G00 X40 Y40\nG01 X35 Y55\nG02 X45 Y65 R10\nG03 X70 Y65 R30\nG02 X80 Y55 R10\n"
               "G01 Y50\nG01 X75 Y40\nG01 X60 Y37\nG01 X40 Y40\n")
# G104 Z-5 K5 H12 D12 E0 T02 / G105 P7 Q15 B75 C1 R2 M15 U0.5 W0 S1000 F150
PAPER_VALUES = {"tool": 2, "tool_diameter": 12, "top": 0, "depth": 5, "stepover": 75, "stepdown": 1,
                "clearance": 2, "stock": 15, "finish_xy": 0.5, "finish_z": 0, "rpm": 1000, "feed": 150,
                "side": "outside"}


def show_paper_island(dialog, folder: Path) -> None:
    """Make the dialog's job the paper's island profile (its contour written to ``folder``)."""
    contour = Path(folder) / "paper-island.nc"
    contour.write_text(PAPER_MOVED)
    dialog.job.clear()
    dialog.list.clear()
    dialog.add_feature("profile")
    dialog.job[0]["values"].update(PAPER_VALUES, contour=str(contour))
    dialog._select(0)
    dialog.refresh()


def island_shot(dialog, out: Path) -> Path:
    """Save a picture of ``dialog`` showing the paper's island into ``out``."""
    show_paper_island(dialog, out)
    dialog.preview.fit()
    path = Path(out) / "features-island.png"
    path.parent.mkdir(parents=True, exist_ok=True)
    dialog.grab().save(str(path))
    return path


def main(out: str = "docs/screenshots", language: str = "en") -> int:
    import tempfile

    from app.profile import MachineProfile
    from app.ui.features.dialog import FeatureDialog
    from app.ui.language import apply_language
    from app.ui.main import make_app

    app = make_app()
    apply_language(language)

    with tempfile.TemporaryDirectory() as folder:
        dialog = FeatureDialog(MachineProfile(), lambda path: None, Path(folder))
        dialog.show()
        app.processEvents()
        show_paper_island(dialog, Path(folder))
        for _ in range(20):
            app.processEvents()
        dialog.preview.fit()
        app.processEvents()
        target = ROOT / out / "features-island.png"
        dialog.grab().save(str(target))
        print(target)
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
