"""The 3-D view of the program: presets, fit, legend, the largest deviation, and the
OpenGL widget (``glview``), or a message where OpenGL cannot start.

``Preview3D(probe=gl_problem)`` asks ``probe()`` before it makes any OpenGL object:
a reason (no context, too old a version) leaves a message in its place, says so in
``unavailable``, and the window keeps its 2-D view. The GL widget is made the first
time the view is shown, and the mesh of a program is built then, on a thread
(``MeshBuilder``): the positions first, drawn at once, then the levels of detail.
``follow(window)`` follows the open program, the job's progress, the tool position and
the measured path by the window's signals (``feed.WindowFeed``).
"""

from __future__ import annotations

import threading

import numpy as np
from PySide6.QtCore import QCoreApplication, QEvent, QObject, Qt, Signal
from PySide6.QtGui import QColor, QGuiApplication, QOffscreenSurface, QOpenGLContext
from PySide6.QtWidgets import QHBoxLayout, QLabel, QPushButton, QStackedWidget, QVBoxLayout, QWidget

from app.gcode.ops import RAPID
from app.ui.numbers import decimal
from app.ui.preview.widget import DONE_COLOUR, group_colours, legend_entries
from app.ui.preview3d import scene
from app.ui.preview3d.camera import PRESETS
from app.ui.preview3d.feed import WindowFeed
from app.ui.preview3d.measured import TOLERANCE_MM, MeasuredPath, deviation_colour
from app.ui.preview3d.mesh import PathMesh

AXIS_FRACTION = 0.12  # axes as long as this much of the travel
JUMP_HALF_HEIGHT = 4.0  # mm of view around the largest deviation
NO_GL_WIDGETS = ("offscreen", "minimal")  # Qt platforms whose windows cannot show a QOpenGLWidget


def gl_problem() -> str:
    """Why this machine cannot draw the 3-D view ("" when it can): a 3.3 core context."""
    from app.ui.preview3d.glview import surface_format

    platform = QGuiApplication.platformName()
    if platform in NO_GL_WIDGETS:  # contexts may work there, but not an OpenGL widget's frame buffer
        said = QCoreApplication.translate("Preview3D", "the %1 platform cannot show OpenGL widgets")
        return said.replace("%1", platform)
    context = QOpenGLContext()
    context.setFormat(surface_format())
    if not context.create():
        return QCoreApplication.translate("Preview3D", "no OpenGL context could be created on this display")
    surface = QOffscreenSurface()
    surface.setFormat(context.format())
    surface.create()
    made = context.makeCurrent(surface)
    version = (context.format().majorVersion(), context.format().minorVersion())
    context.doneCurrent()
    if not made:
        return QCoreApplication.translate("Preview3D", "the OpenGL context could not be used")
    if version < (3, 3):
        return QCoreApplication.translate("Preview3D", "OpenGL %1.%2 found, 3.3 needed").replace(
            "%1", str(version[0])).replace("%2", str(version[1]))
    return ""


class MeshBuilder(QObject):
    """Builds a ``PathMesh`` and its levels off the GUI thread; results come back queued."""

    built = Signal(object, int)  # mesh, token
    levels_built = Signal(object, int)

    def __init__(self, parent=None):
        super().__init__(parent)
        self.token = 0
        self.busy = False

    def build(self, geometry) -> int:
        self.token += 1
        self.busy = True
        token = self.token
        threading.Thread(target=self._run, args=(geometry, token), name="mesh3d", daemon=True).start()
        return token

    def _run(self, geometry, token: int) -> None:
        from app.ui.loader import _yield_cpu

        mesh = PathMesh.from_geometry(geometry)
        self.built.emit(mesh, token)
        _yield_cpu()  # the levels are background work
        mesh.build_levels()
        self.busy = token != self.token
        self.levels_built.emit(mesh, token)


class Preview3D(QWidget):
    gl_failed = Signal(str)

    def __init__(self, parent=None, probe=gl_problem, travel=(150.0, 150.0, 30.0), offset=(0.0, 0.0, 20.0)):
        super().__init__(parent)
        self.probe = probe
        self.unavailable = ""  # why the 3-D view cannot be drawn ("" until known otherwise)
        self.gl = None  # PathGLView, made when first shown
        self.model = None  # the PreviewModel shown (its geometry is the mesh's source)
        self.mesh: PathMesh | None = None
        self.measured = MeasuredPath()
        self.tools: dict = {}
        self.tool_number = None
        self._tool_lines = None  # the program's lines, until its tool is looked up
        self.tool_at = None
        self.mark_at = None
        self._fit_next = True
        self._travel = (travel, offset)
        self.builder = MeshBuilder(self)
        self.builder.built.connect(self._mesh_built)
        self.builder.levels_built.connect(self._levels_built)
        self._built_for = None  # the model whose mesh was asked for
        self._done_seq = -1
        self.feed = None
        self._build_ui()
        self.retranslate_ui()

    def _build_ui(self) -> None:
        self.buttons = {name: QPushButton() for name in (*PRESETS, "fit", "largest")}
        for name in PRESETS:
            self.buttons[name].clicked.connect(lambda _=False, n=name: self.preset(n))
        self.buttons["fit"].clicked.connect(self.fit)
        self.buttons["largest"].clicked.connect(self.jump_to_largest)
        self.deviation_label = QLabel()
        self.legend = QLabel()
        self.legend.setTextFormat(Qt.TextFormat.RichText)
        self.message = QLabel()
        self.message.setWordWrap(True)
        self.message.setAlignment(Qt.AlignmentFlag.AlignCenter)
        self.stack = QStackedWidget()
        self.stack.addWidget(self.message)
        bar = QHBoxLayout()
        for name in (*PRESETS, "fit"):
            bar.addWidget(self.buttons[name])
        bar.addStretch(1)
        bar.addWidget(self.deviation_label)
        bar.addWidget(self.buttons["largest"])
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addLayout(bar)
        layout.addWidget(self.stack, 1)
        layout.addWidget(self.legend)

    # -- language -----------------------------------------------------------------------

    def retranslate_ui(self) -> None:
        labels = {"top": self.tr("Top"), "front": self.tr("Front"), "side": self.tr("Side"),
                  "isometric": self.tr("Isometric"), "fit": self.tr("Fit"),
                  "largest": self.tr("Largest deviation")}
        for name, text in labels.items():
            self.buttons[name].setText(text)
        self.buttons["largest"].setToolTip(self.tr("Show where the measured path strayed farthest from the "
                                                   "programmed one"))
        self.setToolTip(self.tr("drag: orbit · right drag or Shift+drag: pan · wheel: zoom at the cursor"))
        if self.unavailable:
            self._show_unavailable()
        elif self.gl is None:
            self.message.setText(self.tr("The 3-D view starts when it is shown."))
        self._update_legend()

    def changeEvent(self, event) -> None:  # noqa: N802 (Qt override)
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate_ui()
        super().changeEvent(event)

    # -- OpenGL, or why not ---------------------------------------------------------------

    def showEvent(self, event) -> None:  # noqa: N802 (Qt override)
        super().showEvent(event)
        self.start_gl()

    def start_gl(self) -> bool:
        """Make the GL widget (once); False, with the message shown, where it cannot start."""
        if self.gl is not None or self.unavailable:
            return self.gl is not None
        problem = self.probe()
        if problem:
            self._gl_failed(problem)
            return False
        from app.ui.preview3d.glview import PathGLView

        self.gl = PathGLView()
        self.gl.measured = self.measured
        self.gl.gl_failed.connect(self._gl_failed)
        self.stack.addWidget(self.gl)
        self.stack.setCurrentWidget(self.gl)
        self._update_lines()
        self._build_mesh()
        return True

    def _gl_failed(self, reason: str) -> None:
        self.unavailable = reason
        if self.gl is not None:
            self.stack.removeWidget(self.gl)
            self.gl.deleteLater()
            self.gl = None
        self._show_unavailable()
        self.gl_failed.emit(reason)

    def _show_unavailable(self) -> None:
        self.message.setText(self.tr("The 3-D view cannot start: %1.\nThe 2-D view shows the program.")
                             .replace("%1", self.unavailable))
        self.stack.setCurrentWidget(self.message)
        for button in self.buttons.values():
            button.setEnabled(False)

    # -- the program ----------------------------------------------------------------------

    def show_model(self, model, program=None, keep_camera: bool = False) -> None:
        """Draw ``model`` (a ``PreviewModel``); ``keep_camera``: the same program, finer."""
        self.model = model
        self._fit_next = not keep_camera
        if not keep_camera:
            self.measured.clear()
            self.mark_at = None
            self.deviation_label.clear()
            self.tool_number, self._tool_lines = None, getattr(program, "lines", None) or []
        self._update_legend()
        self._update_lines()
        self._build_mesh()

    def _build_mesh(self) -> None:
        if self.gl is None or self.model is self._built_for:
            return
        self._built_for = self.model
        if self.model is None or self.model.empty:
            self.mesh = None
            self.gl.set_mesh(None)
            return
        self.builder.build(self.model.geometry)

    def _mesh_built(self, mesh: PathMesh, token: int) -> None:
        if token != self.builder.token or self.gl is None:
            return
        self.mesh = mesh
        self.gl.set_mesh(mesh, fit=self._fit_next)
        self._fit_next = False
        self._update_lines()

    def _levels_built(self, mesh: PathMesh, token: int) -> None:
        if token == self.builder.token and self.gl is not None and mesh is self.mesh:
            self.gl.levels_ready()

    def set_tools(self, tools: dict) -> None:
        self.tools = dict(tools)
        self._update_lines()

    def set_travel(self, travel, offset) -> None:
        """Travel (x, y, z max, machine mm) and the work offset: the box in work coordinates."""
        self._travel = (tuple(travel), tuple(offset))
        self._update_lines()

    def _update_lines(self) -> None:
        travel, offset = self._travel
        low = -np.asarray(offset, float)
        high = low + np.asarray(travel, float)
        rows = [scene.box_lines(low, high), scene.axes_lines(max(travel) * AXIS_FRACTION)]
        if self.tool_at is not None:
            diameter, _ = scene.tool_diameter(self.tools, self._program_tool())
            rows.append(scene.tool_lines(self.tool_at, diameter))
        if self.mark_at is not None:
            rows.append(scene.mark_lines(self.mark_at, JUMP_HALF_HEIGHT))
        if self.gl is not None:
            self.gl.set_lines(np.concatenate(rows))

    def _program_tool(self) -> int | None:
        """The tool the program asks for, looked up when the tool is first drawn rather
        than while a file opens (the first SCAN_LINES lines; a file's ``Lines`` decodes
        those alone)."""
        if self._tool_lines is not None:
            self.tool_number, self._tool_lines = scene.program_tool(self._tool_lines), None
        return self.tool_number

    def _update_legend(self) -> None:
        colours = group_colours()
        swatch = '<span style="color:{}">■</span> {}'
        parts = [swatch.format(colours[group], label) for group, label in legend_entries(self.model)]
        if parts:
            parts.append(swatch.format(DONE_COLOUR, self.tr("done")))
        steps = (0.0, TOLERANCE_MM / 2, TOLERANCE_MM)
        ramp = [QColor.fromRgbF(*(float(c) for c in deviation_colour(d))).name() for d in steps]
        samples = [swatch.format(colour, decimal(d, 2)) for colour, d in zip(ramp, steps, strict=True)]
        title = self.tr("measured:")
        parts.append(f"{title} {' '.join(samples)} mm")
        self.legend.setText("&nbsp;&nbsp;".join(parts))

    # -- the camera -----------------------------------------------------------------------

    def preset(self, name: str) -> None:
        if self.gl is not None:
            self.gl.camera.preset(name)
            self.gl.fit()

    def fit(self) -> None:
        if self.gl is not None:
            self.gl.fit()

    # -- a job ----------------------------------------------------------------------------

    def follow(self, window) -> None:
        """Follow ``window``'s program, job, tool and measured path (by its signals)."""
        self.feed = WindowFeed(window, self)

    def begin_job(self) -> None:
        self.measured.clear()
        self.mark_at = None
        self.deviation_label.clear()
        self.set_done(-1)

    def _executing_rapid(self, done: int) -> bool:
        """Whether the move after device line ``done`` (the last finished) is a rapid."""
        if self.model is None or self.model.empty:
            return False
        kind = self.model.toolpath.kind
        move = self.model.move_of_device_line(done + 1)
        return 0 <= move < len(kind) and int(kind[move]) == RAPID

    def set_done(self, seq: int) -> None:
        """The job has finished device line ``seq``: one uniform (O(log n) to find the vertex)."""
        self._done_seq = seq
        if self.model is None or self.mesh is None or self.gl is None:
            return
        self.gl.set_done_vertex(self.mesh.vertex_of_move(self.model.move_of_device_line(seq)))

    def set_tool(self, x: float, y: float, z: float) -> None:
        self.tool_at = (x, y, z)
        self._update_lines()

    def add_measured(self, measured: np.ndarray, commanded: np.ndarray, done=None) -> None:
        """New rows of the job's measured path, each taken during the move after its
        ``done`` (the last finished device line when the machine reported it; default:
        the job's last finished line now)."""
        rows = np.atleast_2d(measured)
        dones = [self._done_seq] * len(rows) if done is None else [int(d) for d in done]
        for m, c, d in zip(rows, np.atleast_2d(commanded), dones, strict=True):
            self.measured.append(m, c, self._executing_rapid(d))
        if self.gl is not None:
            self.gl.update()

    def jump_to_largest(self) -> None:
        """Say how far the measured path strayed at most, mark the place and look at it."""
        worst = self.measured.largest()
        if worst is None:
            self.deviation_label.setText(self.tr("no cut measured yet"))
            return
        x, y, z = (decimal(v, 3) for v in worst.measured)
        self.deviation_label.setText(self.tr("largest deviation %1 mm at X %2 Y %3 Z %4")
                                     .replace("%1", decimal(worst.distance, 3)).replace("%2", x)
                                     .replace("%3", y).replace("%4", z))
        self.mark_at = tuple(worst.measured)
        self._update_lines()
        if self.gl is not None:
            self.gl.camera.look_at(worst.measured, JUMP_HALF_HEIGHT)
            self.gl.update()
