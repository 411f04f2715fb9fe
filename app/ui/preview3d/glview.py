"""The OpenGL widget of the 3-D view: draws a ``PathMesh``, a measured path and a few
coloured lines (travel box, work zero axes, tool, mark) through Qt's own OpenGL
classes (no PyOpenGL).

Geometry goes to the GPU once per model (``set_mesh``); the progress of a job is a
uniform (``set_done_vertex``: O(1), nothing uploaded), the measured path only sends
its new rows. While the camera moves, the path is drawn from the mesh's level of
detail sized to the pixels and a frame budget; SETTLE_MS after the last move full
detail is drawn again, a slice per frame for a big one (``fullframe``): the coarsest
level whose cells are at most FULL_CELL_PIXELS of a pixel (it draws the same picture
as every segment, but for a few pixels one off: ``tests/ui/test_preview3d_full.py``),
or every segment when no level is that fine; of either only the chunks the camera
sees (``chunks``), and the pictures of the last poses are kept for when the camera
comes back (``FullFrame``). Path lines are opaque (rapids a darker
colour, not see-through), so a line drawn twice looks as drawn once. A context
or shader that cannot be made ends in ``gl_failed`` with the reason, and the widget
then draws nothing.
"""

from __future__ import annotations

import ctypes
import time

import numpy as np
from PySide6.QtCore import QPointF, QSize, Qt, QTimer, Signal
from PySide6.QtGui import QColor, QMatrix4x4, QSurfaceFormat
from PySide6.QtOpenGL import QOpenGLBuffer, QOpenGLShader, QOpenGLShaderProgram, QOpenGLVertexArrayObject
from PySide6.QtOpenGLWidgets import QOpenGLWidget

from app.ui.preview.widget import DONE_COLOUR, group_colours
from app.ui.preview3d import shaders
from app.ui.preview3d.camera import Camera
from app.ui.preview3d.chunks import visible_runs
from app.ui.preview3d.fullframe import SLICE_SEGMENTS, FullFrame, FullSource
from app.ui.preview3d.measured import RAMP, TOLERANCE_MM, MeasuredPath
from app.ui.preview3d.mesh import PathMesh

SETTLE_MS = 50  # full detail this long after the camera stops (a drag moves every ~16 ms)
MOVING_BUDGET = 60_000  # segments per frame while the camera moves (llvmpipe: ~8 M segments/s)
LOD_PIXELS = 1.0  # cell of the level drawn while moving, in pixels
FULL_CELL_PIXELS = 0.5  # cell of a level drawn as full detail, in pixels (test_preview3d_full)
RAPID_SHADE = 0.45  # rapids are drawn faint: their colour this dark, opaque (drawn twice, the same)
ORBIT_DEG_PER_PX = 0.4
WHEEL_STEP = 1.0015  # zoom factor per 1/8 degree of wheel
GL_LINES, GL_LINE_STRIP = 0x0001, 0x0003
GL_FLOAT, GL_UNSIGNED_BYTE, GL_UNSIGNED_INT = 0x1406, 0x1401, 0x1405
GL_COLOR_BUFFER_BIT, GL_DEPTH_BUFFER_BIT = 0x4000, 0x0100
GL_DEPTH_TEST, GL_BLEND, GL_LEQUAL = 0x0B71, 0x0BE2, 0x0203
GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA = 0x0302, 0x0303
GL_RENDERER, GL_VERSION = 0x1F01, 0x1F02


def surface_format() -> QSurfaceFormat:
    fmt = QSurfaceFormat()
    fmt.setVersion(3, 3)
    fmt.setProfile(QSurfaceFormat.OpenGLContextProfile.CoreProfile)
    fmt.setDepthBufferSize(24)
    return fmt


def _rgba(hex_colour: str, shade: float = 1.0) -> list[float]:
    c = QColor(hex_colour)
    return [c.redF() * shade, c.greenF() * shade, c.blueF() * shade, 1.0]


class PathGLView(QOpenGLWidget):
    gl_failed = Signal(str)
    frame_drawn = Signal()

    def __init__(self, parent=None):
        super().__init__(parent)
        self.setFormat(surface_format())
        self.setMinimumSize(200, 150)
        self.camera = Camera()
        self.mesh: PathMesh | None = None
        self.measured: MeasuredPath | None = None
        self.done_vertex = -1
        self.lines = np.zeros((0, 6), np.float32)  # travel box, axes, tool, mark
        self.moving = False
        self.renderer = ""  # the GL_RENDERER and GL_VERSION strings, once started
        self.failure = ""
        self.drawn = ("none", 0)  # what the last frame drew: ("full" | "level", segments)
        self._pending = {"mesh": False, "levels": False, "lines": True}
        self._measured_sent = (-1, 0, 0)  # version, rows, capacity on the GPU
        self._level_buffers: list[QOpenGLBuffer] = []
        self._full = FullFrame()
        self._mesh_serial = 0
        self._refiner = QTimer(self, singleShot=True, interval=0, timeout=self._refine)
        self.direct_segments = SLICE_SEGMENTS  # up to this many, full detail in one frame
        self.full_cell_pixels = FULL_CELL_PIXELS  # 0: full detail draws every segment
        self.full_lines = 0  # the lines the last full picture drew
        self._gl = None
        self._settle = QTimer(self, singleShot=True, interval=SETTLE_MS, timeout=self._settled)
        self._press: tuple[QPointF, Qt.MouseButton] | None = None
        colours = group_colours()
        self._colours = [_rgba(c, shade=RAPID_SHADE if i == 0 else 1.0) for i, c in enumerate(colours)]
        self._colours += [[1.0, 1.0, 1.0, 1.0]] * (8 - len(self._colours))

    # -- what to draw -------------------------------------------------------------------

    def set_mesh(self, mesh: PathMesh | None, fit: bool = True) -> None:
        self.mesh = mesh
        self._mesh_serial += 1  # (an id() may come back for another mesh)
        self._full.forget()  # the pictures of the last model (their buffers go with them)
        self._pending["mesh"] = self._pending["levels"] = True
        if fit:
            self.fit()
        self.update()

    def levels_ready(self) -> None:
        """The mesh's levels of detail were built (off the GUI thread): send them."""
        self._pending["levels"] = True
        self.update()

    @property
    def levels_on_gpu(self) -> int:
        return len(self._level_buffers)

    def set_lines(self, rows: np.ndarray) -> None:
        self.lines = np.ascontiguousarray(rows, np.float32)
        self._pending["lines"] = True
        self.update()

    def set_done_vertex(self, vertex: int) -> None:
        """Every segment up to ``vertex`` is drawn finished (one uniform; O(1))."""
        if vertex != self.done_vertex:
            self.done_vertex = vertex
            self.update()

    def fit(self) -> None:
        if self.mesh is not None and self.mesh.segments:
            self.camera.fit(*self.mesh.bounds())
        self.update()

    def camera_moved(self) -> None:
        """Draw coarse until the camera has been still for SETTLE_MS."""
        self.moving = True
        self._settle.start()
        self.update()

    def _settled(self) -> None:
        self.moving = False
        self.update()

    # -- OpenGL -----------------------------------------------------------------------

    def initializeGL(self) -> None:  # noqa: N802 (Qt override)
        context = self.context()
        if context is None or not context.isValid():
            self._fail(self.tr("no OpenGL context could be created"))
            return
        f = self._gl = context.functions()
        self.renderer = f"{f.glGetString(GL_RENDERER)}, OpenGL {f.glGetString(GL_VERSION)}"
        address = context.getProcAddress(b"glDrawElements")
        if not address:
            self._fail(self.tr("the OpenGL driver has no glDrawElements"))
            return
        # PySide6's glDrawElements takes no buffer offset (only client memory, which a core
        # profile refuses): called through ctypes with a null offset into the bound buffer.
        self._draw_elements = _DRAW_ELEMENTS(address)
        try:
            self._programs = {
                "path": _program(shaders.PATH_VERTEX, shaders.FLAT_FRAGMENT),
                "measured": _program(shaders.MEASURED_VERTEX, shaders.SMOOTH_FRAGMENT),
                "lines": _program(shaders.LINES_VERTEX, shaders.SMOOTH_FRAGMENT),
            }
            self._vao = {name: _vao(self) for name in ("path", "measured", "lines")}
        except RuntimeError as exc:
            self._fail(str(exc))
            return
        self._buffers = {name: QOpenGLBuffer(QOpenGLBuffer.Type.VertexBuffer)
                         for name in ("points", "groups", "measured", "lines")}
        for buffer in self._buffers.values():
            buffer.create()
        self._buffers["measured"].setUsagePattern(QOpenGLBuffer.UsagePattern.DynamicDraw)
        self._pending = dict.fromkeys(self._pending, True)
        self._measured_sent = (-1, 0, 0)

    def _fail(self, reason: str) -> None:
        self.failure = reason
        QTimer.singleShot(0, lambda: self.gl_failed.emit(reason))

    def resizeGL(self, width: int, height: int) -> None:  # noqa: N802 (Qt override)
        self.camera.aspect = width / max(height, 1)

    def paintGL(self) -> None:  # noqa: N802 (Qt override)
        f = self._gl
        if f is None or self.failure:
            return
        self._upload()
        f.glClearColor(0.0, 0.0, 0.0, 1.0)
        f.glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT)
        _path_state(f)
        mvp = QMatrix4x4(*self.camera.matrix().ravel())
        self._draw_path(f, mvp)  # first: a full-detail picture is copied over the whole frame
        self._draw_lines(f, mvp)
        f.glEnable(GL_BLEND)  # the measured path's rapids are see-through
        f.glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA)
        f.glDisable(GL_DEPTH_TEST)  # the measured path is drawn over the programmed one
        self._draw_measured(f, mvp)
        self.frame_drawn.emit()

    def _draw_lines(self, f, mvp) -> None:
        if not len(self.lines):
            return
        program = self._programs["lines"]
        program.bind()
        program.setUniformValue("u_mvp", mvp)
        self._vao["lines"].bind()
        f.glDrawArrays(GL_LINES, 0, len(self.lines))
        self._vao["lines"].release()

    def _draw_path(self, f, mvp) -> None:
        mesh = self.mesh
        if mesh is None or not mesh.segments:
            self.drawn = ("none", 0)
            return
        self._bind_path(mvp)
        pixel = self.camera.pixel(self.height())
        moving = self._level(pixel * LOD_PIXELS, MOVING_BUDGET) if self.moving else None
        if moving is not None:
            self._draw_level(*moving)
        else:
            source = self._full_source(f)
            if source.total <= self.direct_segments:
                source.draw(0, source.total)
                self.drawn, self.full_lines = ("full", mesh.segments), source.total
            else:
                self._draw_full_picture(f, source)
        self._vao["path"].release()

    def _bind_path(self, mvp) -> None:
        program = self._programs["path"]
        program.bind()
        program.setUniformValue("u_mvp", mvp)
        program.setUniformValue1i("u_done", int(self.done_vertex))
        program.setUniformValueArray("u_colours", sum(self._colours, []), 8, 4)
        program.setUniformValue("u_done_colour", *_rgba(DONE_COLOUR))
        self._vao["path"].bind()

    def _full_source(self, f) -> FullSource:
        """What full detail draws at this zoom: the coarsest level whose cells are at most
        FULL_CELL_PIXELS of a pixel (it looks like every segment), else the whole strip."""
        mesh = self.mesh
        level = None
        if self.full_cell_pixels > 0 and len(self._level_buffers) == len(mesh.levels):
            level = mesh.pick_full(self.camera.pixel(self.height()), self.full_cell_pixels)
        if level is None:
            runs = [(0, mesh.segments)] if mesh.boxes is None else visible_runs(
                mesh.boxes, self.camera.project, mesh.segments)  # (boxes come with the levels)
            return FullSource.strip(f, runs, self.done_vertex)
        index = next(i for i, candidate in enumerate(mesh.levels) if candidate is level)
        self._level_buffers[index].bind()  # the path's VAO keeps it
        runs = visible_runs(level.boxes, self.camera.project, len(level.ends))
        return FullSource.spans(self._draw_elements, level, index, runs, self.done_vertex)

    def _full_key(self, source: FullSource):
        return self._mesh_serial, source.name, tuple(self.camera.matrix().ravel())

    def _draw_full_picture(self, f, source: FullSource) -> None:
        """The full picture when it is whole (with the newly finished segments drawn over
        it); until then a level of detail, while ``_refine`` draws it between frames."""
        full = self._full
        ratio = self.devicePixelRatioF()
        size = QSize(round(self.width() * ratio), round(self.height() * ratio))
        full.prepare(f, self._full_key(source), size, source.total, source.done)
        full.overdraw(source.draw, source.done)
        level = None if full.complete else self._level(self.camera.pixel(self.height()) * LOD_PIXELS,
                                                       MOVING_BUDGET)
        if level is None:
            full.blit()
            self.drawn = ("full", self.mesh.segments) if full.complete else ("partial", full.next)
            self.full_lines = source.total
        else:
            self._draw_level(*level)
        if not full.complete:
            self._refiner.start()

    def _refine(self) -> None:
        """One slice of the full picture, outside any frame (no window to compose each
        time); the widget repaints once it is whole."""
        full, mesh = self._full, self.mesh
        if self._gl is None or mesh is None or full.complete:
            return
        self.makeCurrent()
        f = self._gl
        self._bind_path(QMatrix4x4(*self.camera.matrix().ravel()))
        source = self._full_source(f)
        if full.key == self._full_key(source):  # else the next frame starts what is shown then
            _path_state(f)
            started = time.perf_counter()
            sliced = full.slice(source.draw)
            f.glFinish()  # the slice's own time
            full.tune(time.perf_counter() - started, sliced)
        self._vao["path"].release()
        self.doneCurrent()
        if full.key != self._full_key(source) or full.complete:
            self.update()
        else:
            self._refiner.start()

    def _level(self, pixel: float, budget: int) -> tuple[int, int] | None:
        """(level, segments) for this pixel size and budget; None without levels (or when the
        full model fits the budget)."""
        mesh = self.mesh
        if mesh.segments <= budget or len(self._level_buffers) != len(mesh.levels) or not mesh.levels:
            return None
        level = mesh.pick_level(pixel, budget)
        index = next(i for i, candidate in enumerate(mesh.levels) if candidate is level)
        return index, len(level.ends)

    def _draw_level(self, index: int, count: int) -> None:
        self._level_buffers[index].bind()  # the path's VAO keeps it
        self._draw_elements(GL_LINES, 2 * count, GL_UNSIGNED_INT, None)  # the whole level
        self.drawn = ("level", count)

    def _draw_measured(self, f, mvp) -> None:
        rows = len(self.measured) if self.measured is not None else 0
        if rows < 2:
            return
        program = self._programs["measured"]
        program.bind()
        program.setUniformValue("u_mvp", mvp)
        program.setUniformValue1f("u_tolerance", float(TOLERANCE_MM))
        program.setUniformValueArray("u_ramp", [float(v) for v in RAMP.ravel()], 3, 3)
        self._vao["measured"].bind()
        f.glDrawArrays(GL_LINE_STRIP, 0, rows)
        self._vao["measured"].release()

    # -- uploads (only what changed) ----------------------------------------------------

    def _upload(self) -> None:
        if self._pending["mesh"]:
            self._upload_mesh()
        if self._pending["levels"]:
            self._upload_levels()
        if self._pending["lines"]:
            self._pending["lines"] = False
            _fill(self._buffers["lines"], self.lines)
            self._vao["lines"].bind()
            self._attribute(self._programs["lines"], self._buffers["lines"], [(0, 3, 0), (1, 3, 12)], 24)
            self._vao["lines"].release()
        self._upload_measured()

    def _upload_mesh(self) -> None:
        self._pending["mesh"] = False
        mesh = self.mesh
        points = mesh.points if mesh is not None else np.zeros((0, 3), np.float32)
        groups = mesh.group if mesh is not None else np.zeros(0, np.uint8)
        _fill(self._buffers["points"], points)
        _fill(self._buffers["groups"], groups)
        self._vao["path"].bind()
        program = self._programs["path"]
        self._attribute(program, self._buffers["points"], [(0, 3, 0)], 12)
        self._buffers["groups"].bind()
        program.enableAttributeArray(1)
        program.setAttributeBuffer(1, GL_UNSIGNED_BYTE, 0, 1, 1)
        self._vao["path"].release()

    def _upload_levels(self) -> None:
        """One index buffer per level (PySide6 draws elements from offset 0 only)."""
        self._pending["levels"] = False
        for buffer in self._level_buffers:
            buffer.destroy()
        self._level_buffers = []
        for level in self.mesh.levels if self.mesh is not None else []:
            buffer = QOpenGLBuffer(QOpenGLBuffer.Type.IndexBuffer)
            buffer.create()
            _fill(buffer, level.pairs())
            self._level_buffers.append(buffer)

    def _upload_measured(self) -> None:
        path = self.measured
        if path is None:
            return
        version, sent, capacity = self._measured_sent
        buffer = self._buffers["measured"]
        if version != path.version or capacity != path.capacity or sent > len(path):
            buffer.bind()
            buffer.allocate(path.capacity * 16)
            sent = 0
            self._vao["measured"].bind()
            self._attribute(self._programs["measured"], buffer, [(0, 4, 0)], 16)
            self._vao["measured"].release()
        rows = path.rows()
        if len(rows) > sent:
            fresh = np.ascontiguousarray(rows[sent:])
            buffer.bind()
            buffer.write(sent * 16, fresh, fresh.nbytes)
        self._measured_sent = (path.version, len(rows), path.capacity)

    @staticmethod
    def _attribute(program, buffer, attributes, stride: int) -> None:
        """Point the bound VAO's float attributes (location, size, byte offset) at ``buffer``."""
        buffer.bind()
        for location, size, offset in attributes:
            program.enableAttributeArray(location)
            program.setAttributeBuffer(location, GL_FLOAT, offset, size, stride)

    # -- the mouse ----------------------------------------------------------------------

    def mousePressEvent(self, event) -> None:  # noqa: N802 (Qt override)
        self._press = (event.position(), event.button())

    def mouseReleaseEvent(self, event) -> None:  # noqa: N802 (Qt override)
        self._press = None

    def mouseMoveEvent(self, event) -> None:  # noqa: N802 (Qt override)
        if self._press is None:
            return
        last, button = self._press
        pos = event.position()
        dx, dy = pos.x() - last.x(), pos.y() - last.y()
        self._press = (pos, button)
        shifted = event.modifiers() & Qt.KeyboardModifier.ShiftModifier
        if button == Qt.MouseButton.LeftButton and not shifted:
            self.camera.orbit(-dx * ORBIT_DEG_PER_PX, dy * ORBIT_DEG_PER_PX)
        else:
            self.camera.pan(2 * dx / max(self.width(), 1), -2 * dy / max(self.height(), 1))
        self.camera_moved()

    def wheelEvent(self, event) -> None:  # noqa: N802 (Qt override)
        x, y = self.ndc(event.position())
        self.camera.zoom_at(WHEEL_STEP ** event.angleDelta().y(), x, y)
        self.camera_moved()

    def ndc(self, pos: QPointF) -> tuple[float, float]:
        """Widget pixels -> normalised device coordinates."""
        return 2 * pos.x() / max(self.width(), 1) - 1, 1 - 2 * pos.y() / max(self.height(), 1)


def _path_state(f) -> None:
    """Opaque lines with the depth test: a later line wins at equal depth, and drawing a
    line twice changes nothing (what lets a level stand for repeated segments)."""
    f.glEnable(GL_DEPTH_TEST)
    f.glDepthFunc(GL_LEQUAL)
    f.glDisable(GL_BLEND)


_DRAW_ELEMENTS = ctypes.CFUNCTYPE(None, ctypes.c_uint, ctypes.c_int, ctypes.c_uint, ctypes.c_void_p)


def _program(vertex: str, fragment: str) -> QOpenGLShaderProgram:
    program = QOpenGLShaderProgram()
    ok = program.addShaderFromSourceCode(QOpenGLShader.ShaderTypeBit.Vertex, vertex)
    ok = ok and program.addShaderFromSourceCode(QOpenGLShader.ShaderTypeBit.Fragment, fragment)
    if not (ok and program.link()):
        raise RuntimeError(program.log().strip() or "shader program failed")
    return program


def _vao(parent) -> QOpenGLVertexArrayObject:
    vao = QOpenGLVertexArrayObject(parent)
    if not vao.create():
        raise RuntimeError("vertex array object failed")
    return vao


def _fill(buffer: QOpenGLBuffer, array: np.ndarray) -> None:
    """Replace the buffer's contents with ``array``'s bytes."""
    data = np.ascontiguousarray(array)
    buffer.bind()
    if data.nbytes:
        buffer.allocate(data, data.nbytes)  # PySide6 reads the array's buffer: no copy
    else:
        buffer.allocate(4)
