"""The operator's main window: the preview in the middle, program on the left,
machine controls / SD card / machine panel on the right, live plot and console below,
connection bar on top, progress in the status bar. Window state is restored on start.

Wiring lives elsewhere: ``menus.py`` (actions and shortcuts), ``session_binder.py``
(worker events -> widgets), ``operator.py`` (operator requests -> worker calls).
"""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import (
    QT_TRANSLATE_NOOP,
    QByteArray,
    QCoreApplication,
    QEvent,
    QSettings,
    QStandardPaths,
    Qt,
)
from PySide6.QtWidgets import QDockWidget, QMainWindow, QTabWidget, QWidget

from app.gcode.tools import FILE_NAME as TOOLS_FILE
from app.gcode.tools import load_tools
from app.i18n import localize
from app.ui.connection_bar import ConnectionBar
from app.ui.console import ConsoleView
from app.ui.controls import MachineControls
from app.ui.custom_bar import CustomBar
from app.ui.dro_panel import DroPanel
from app.ui.keep_awake import KeepAwake
from app.ui.language import SETTING, apply_language, current_language
from app.ui.link import MachineLink
from app.ui.link_alert import LinkAlert
from app.ui.live_panel import LivePanel
from app.ui.loader import ProgramLoader
from app.ui.machine_panel import MachinePanelView
from app.ui.notifier import Notifier
from app.ui.plot.diagnostics import DiagnosticsView
from app.ui.plot.history import PositionHistory
from app.ui.plot.position_plot import PositionPlot
from app.ui.preview.widget import PreviewWidget
from app.ui.preview3d.view import Preview3D
from app.ui.program.program_panel import ProgramPanel
from app.ui.sd_panel import SdPanel
from app.ui.settings.prefs import FILE_NAME as PREFS_FILE
from app.ui.settings.prefs import Prefs, from_legacy, load_prefs, save_prefs
from app.ui.settings.store import FILE_NAME, load_settings
from app.ui.status_bar import JobStatusBar
from app.ui.window_state import FILE_NAME as WINDOW_FILE
from app.ui.window_state import load_window_state, save_window_state

STATE_VERSION = 1
DOCK_TITLES = {
    "program": QT_TRANSLATE_NOOP("MainWindow", "Program"),
    "controls": QT_TRANSLATE_NOOP("MainWindow", "Machine controls"),
    "sd": QT_TRANSLATE_NOOP("MainWindow", "SD card"),
    "panel": QT_TRANSLATE_NOOP("MainWindow", "Machine panel"),
    "plot": QT_TRANSLATE_NOOP("MainWindow", "Live position"),
    "console": QT_TRANSLATE_NOOP("MainWindow", "Console"),
    "dro": QT_TRANSLATE_NOOP("MainWindow", "Position and work offsets"),
    "live": QT_TRANSLATE_NOOP("MainWindow", "Live modal state"),
}


def default_config_dir() -> Path:
    return Path(QStandardPaths.writableLocation(QStandardPaths.StandardLocation.AppConfigLocation))


class MainWindow(QMainWindow):
    def __init__(self, config_dir: Path | None = None, notifier: Notifier | None = None, port_lister=None,
                 restore: bool = True):
        super().__init__()
        self.setAcceptDrops(True)
        self.config_dir = Path(config_dir) if config_dir else default_config_dir()
        self.qsettings = QSettings(str(self.config_dir / "window.ini"), QSettings.Format.IniFormat)
        self.notifier = notifier or Notifier(self)
        self.prefs, prefs_problem = self._load_prefs()
        loaded = load_settings(self.config_dir / FILE_NAME)
        self.profile = loaded.profile
        self.loaded = None  # LoadedProgram of the open file
        self.history = PositionHistory()
        self.keep_awake = KeepAwake()
        self.link = MachineLink(self, self.profile)
        self.loader = ProgramLoader(self, self.profile.motion.arc_tolerance_mm)
        tools = load_tools(self.config_dir / TOOLS_FILE)
        self.tools = self.loader.tools = tools.tools
        self._build_widgets(port_lister)
        self._build_docks()
        from app.ui.cover_banner import CoverBanner
        from app.ui.custom_commands import CustomCommands
        from app.ui.dro import Dro
        from app.ui.hold_jog_keys import HoldJogKeys
        from app.ui.live_state import LiveState
        from app.ui.menus import build_menus
        from app.ui.operator_actions import OperatorActions
        from app.ui.outline import OutlineBox
        from app.ui.preflight import Preflight
        from app.ui.program_stops import ProgramStops
        from app.ui.session_binder import SessionBinder
        from app.ui.start_here import StartHere

        self.operator = OperatorActions(self)
        self.hold_jog_keys = HoldJogKeys(self, self.controls.jog)
        self.outline = OutlineBox(self)
        self.controls.layout().insertWidget(1, self.outline)
        self.binder = SessionBinder(self)
        self.preview3d.follow(self)
        self.program_stops = ProgramStops(self)
        self.cover_banner = CoverBanner(self)
        self.preflight = Preflight(self)
        self.dro = Dro(self, self.dro_panel)
        self.live_state = LiveState(self, self.live_panel)
        self.custom_commands = CustomCommands(self, self.custom_bar)
        self.start_here = StartHere(self)
        self.actions_by_name = build_menus(self)
        from app.ui.grbl_window import GrblWindow

        self.grbl = GrblWindow(self)  # issue 23: settings, unlock, $G/$# and holds on a GRBL machine
        self.retranslate_ui()  # applies the state table too
        if restore:
            self.restore_state()
        for problem in (prefs_problem, loaded.problem):
            if problem:
                self.notifier.warning(self.tr("Settings"), localize(problem))
        if tools.problem:
            self.notifier.warning(self.tr("Tool table"), localize(tools.problem))

    def _build_widgets(self, port_lister) -> None:
        travel = (self.profile.travel.x_max, self.profile.travel.y_max)
        offset = self.profile.travel.work_offset()[:2]
        self.preview = PreviewWidget(travel=travel, offset=offset)
        self.preview3d = Preview3D(travel=travel + (self.profile.travel.z_max,),
                                   offset=self.profile.travel.work_offset())
        self.views = QTabWidget()  # 2-D, 3-D (the 2-D view where OpenGL cannot start)
        self.views.addTab(self.preview, "")
        self.views.addTab(self.preview3d, "")
        self.preview3d.gl_failed.connect(lambda: self.views.setCurrentWidget(self.preview))
        self.setCentralWidget(self.views)
        kwargs = {"lister": port_lister} if port_lister else {}
        self.connection = ConnectionBar(**kwargs)
        bar = self.connection_toolbar = self.addToolBar("")
        bar.setObjectName("connection_toolbar")
        bar.addWidget(self.connection)
        self.custom_bar = CustomBar()
        custom = self.custom_toolbar = self.addToolBar("")
        custom.setObjectName("custom_toolbar")
        custom.addWidget(self.custom_bar)
        self.program_panel = ProgramPanel()
        self.controls = MachineControls()
        self.sd_panel = SdPanel()
        self.machine_panel = MachinePanelView()
        self.dro_panel = DroPanel()
        self.live_panel = LivePanel()
        self.position_plot = PositionPlot(self.history)
        self.diagnostics = DiagnosticsView(self.history)
        self.plots = QTabWidget()
        self.plots.addTab(self.position_plot, "")
        self.plots.addTab(self.diagnostics, "")
        self.console = ConsoleView()
        self.status = JobStatusBar()
        self.setStatusBar(self.status)
        self.alert = LinkAlert(self)

    def _dock(self, name: str, widget: QWidget, area) -> QDockWidget:
        dock = QDockWidget(self)
        dock.setObjectName(name)
        dock.setWidget(widget)
        self.addDockWidget(area, dock)
        return dock

    def _build_docks(self) -> None:
        left, right, bottom = (Qt.DockWidgetArea.LeftDockWidgetArea, Qt.DockWidgetArea.RightDockWidgetArea,
                               Qt.DockWidgetArea.BottomDockWidgetArea)
        self.docks = {
            "program": self._dock("program_dock", self.program_panel, left),
            "controls": self._dock("controls_dock", self.controls, right),
            "sd": self._dock("sd_dock", self.sd_panel, right),
            "panel": self._dock("panel_dock", self.machine_panel, right),
            "plot": self._dock("plot_dock", self.plots, bottom),
            "console": self._dock("console_dock", self.console, bottom),
            "dro": self._dock("dro_dock", self.dro_panel, right),
            "live": self._dock("live_dock", self.live_panel, right),
        }
        # Side columns run the full height; the plot and console sit under the preview only.
        self.setCorner(Qt.Corner.BottomLeftCorner, left)
        self.setCorner(Qt.Corner.BottomRightCorner, right)
        self.tabifyDockWidget(self.docks["sd"], self.docks["panel"])
        self.tabifyDockWidget(self.docks["panel"], self.docks["dro"])
        self.tabifyDockWidget(self.docks["dro"], self.docks["live"])
        self.tabifyDockWidget(self.docks["plot"], self.docks["console"])
        self.docks["sd"].raise_()
        self.docks["plot"].raise_()
        self.resize(1400, 900)
        self._sized = False
        self._has_saved_layout = False
        self._default_state = self.saveState(STATE_VERSION)

    def showEvent(self, event) -> None:  # noqa: N802 (Qt override)
        super().showEvent(event)
        if not self._sized and not self._has_saved_layout:
            self._sized = True
            side = [self.docks["program"], self.docks["controls"]]
            self.resizeDocks(side, [330, 370], Qt.Orientation.Horizontal)
            self.resizeDocks([self.docks["plot"]], [int(self.height() * 0.3)], Qt.Orientation.Vertical)

    # -- language ---------------------------------------------------------------------

    @property
    def language(self) -> str:
        return current_language()

    def set_language(self, code: str) -> None:
        """Switch the window (and the core's messages) to ``code`` at once and remember it."""
        code = apply_language(code)
        self.qsettings.setValue(SETTING, code)

    def retranslate_ui(self) -> None:
        name = self.loaded.path.name if self.loaded is not None else ""
        title = self.tr("CNC mill controller")
        self.setWindowTitle(f"{name} — {title}" if name else title)
        self.connection_toolbar.setWindowTitle(self.tr("Connection"))
        self.custom_toolbar.setWindowTitle(self.tr("Custom commands"))
        self.views.setTabText(0, self.tr("2-D view"))
        self.views.setTabText(1, self.tr("3-D view"))
        self.plots.setTabText(0, self.tr("Position"))
        self.plots.setTabText(1, self.tr("Diagnostics (commanded vs measured)"))
        for key, dock in self.docks.items():
            dock.setWindowTitle(QCoreApplication.translate("MainWindow", DOCK_TITLES[key]))
        if hasattr(self, "actions_by_name"):
            from app.ui.menus import retranslate_menus

            retranslate_menus(self)
            self.binder.refresh_enabled()  # the state table's reasons, in the new language

    def changeEvent(self, event) -> None:  # noqa: N802 (Qt override)
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate_ui()
        super().changeEvent(event)

    # -- files ------------------------------------------------------------------------

    def open_file(self, path: str | Path, wait: bool = False) -> None:
        from app.ui.features.hooks import offer_point_import

        if offer_point_import(self, path):  # a point list: its options step comes first
            return
        self.status.showMessage(self.tr("Loading %1…").replace("%1", Path(path).name))
        size = self.preview.view.size()  # the loader prepares the first picture for it
        self.loader.view_size = (size.width(), size.height())
        self.loader.load(path, wait=wait)

    def dragEnterEvent(self, event) -> None:  # noqa: N802 (Qt override)
        if event.mimeData().hasUrls():
            event.acceptProposedAction()

    def dropEvent(self, event) -> None:  # noqa: N802 (Qt override)
        urls = [u for u in event.mimeData().urls() if u.isLocalFile()]
        if urls:
            self.open_file(urls[0].toLocalFile())
            event.acceptProposedAction()

    # -- preferences (recent files, dark palette) ----------------------------------------

    def _load_prefs(self) -> tuple[Prefs, str]:
        """``prefs.json``; the first time, what an older version kept in ``window.ini``
        (moved over once written, so the two never disagree)."""
        path = self.config_dir / PREFS_FILE
        legacy = [key for key in ("recent_files", "dark") if self.qsettings.contains(key)]
        if path.exists() or not legacy:
            loaded = load_prefs(path)
            return loaded.prefs, loaded.problem
        prefs = from_legacy(self.qsettings.value("recent_files", []), self.qsettings.value("dark", False))
        try:
            save_prefs(path, prefs)
        except OSError:
            return prefs, ""  # left in window.ini: migrated by a later start that can write
        for key in legacy:
            self.qsettings.remove(key)
        return prefs, ""

    def update_prefs(self, prefs: Prefs) -> None:
        """Keep and save ``prefs`` atomically; a failed write is shown in the status bar."""
        self.prefs = prefs
        try:
            save_prefs(self.config_dir / PREFS_FILE, prefs)
        except OSError as exc:
            self.status.showMessage(self.tr("Preferences not saved: %1").replace("%1", str(exc)))

    # -- window state -----------------------------------------------------------------

    def restore_state(self) -> None:
        """Geometry and docks from ``window.json``; a damaged file is set aside and named."""
        saved = load_window_state(self.config_dir / WINDOW_FILE)
        if saved.geometry is not None:
            self.restoreGeometry(QByteArray(saved.geometry))
        if saved.state is not None:
            self._has_saved_layout = self.restoreState(QByteArray(saved.state), STATE_VERSION)
        if saved.problem:
            self.notifier.warning(self.tr("Window layout"), saved.problem)

    def save_state(self) -> None:
        """Write geometry and docks atomically; a failed write loses only this layout."""
        try:
            save_window_state(self.config_dir / WINDOW_FILE, bytes(self.saveGeometry().data()),
                              bytes(self.saveState(STATE_VERSION).data()))
        except OSError as exc:
            self.status.showMessage(self.tr("Window layout not saved: %1").replace("%1", str(exc)))

    def reset_layout(self) -> None:
        self.restoreState(self._default_state, STATE_VERSION)
        for dock in self.docks.values():
            dock.show()

    def closeEvent(self, event) -> None:  # noqa: N802 (Qt override)
        self.save_state()
        self.shutdown()
        super().closeEvent(event)

    def shutdown(self) -> None:
        self.hold_jog_keys.detach()
        self.keep_awake.stop()
        self.machine_panel.set_panel(None)
        self.link.shutdown()
