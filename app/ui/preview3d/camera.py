"""The 3-D view's camera: an orthographic orbit around a target point (no Qt).

Z is up, as on the machine. ``yaw`` turns the view about Z (0: from the front, the
operator's side, looking along +Y; 90: from the right, looking along -X), ``pitch``
raises it (90: from above, X to the right and Y up as in the 2-D view). ``half_height``
is half the height of the view in millimetres, so a pixel is
``2 * half_height / height`` millimetres wherever it is: the level of detail is
sized to that. Screen positions are in normalised device coordinates (-1..1, y up).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

PRESETS = {  # name: (yaw, pitch) in degrees
    "top": (0.0, 90.0),
    "front": (0.0, 0.0),
    "side": (90.0, 0.0),
    "isometric": (45.0, math.degrees(math.atan(1 / math.sqrt(2)))),
}
FIT_MARGIN = 1.08
MIN_HALF_HEIGHT = 0.05  # mm
MAX_HALF_HEIGHT = 5_000.0


@dataclass
class Camera:
    target: np.ndarray = field(default_factory=lambda: np.zeros(3))
    yaw: float = PRESETS["isometric"][0]
    pitch: float = PRESETS["isometric"][1]
    half_height: float = 100.0
    aspect: float = 1.0  # width / height
    depth: float = 1_000.0  # half the depth range, mm (set by fit)

    def rotation(self) -> np.ndarray:
        """World -> camera axes (rows: right, up, towards the viewer)."""
        yaw, tilt = math.radians(self.yaw), math.radians(90.0 - self.pitch)
        cz, sz = math.cos(yaw), math.sin(yaw)
        rz = np.array([[cz, sz, 0.0], [-sz, cz, 0.0], [0.0, 0.0, 1.0]])
        cx, sx = math.cos(-tilt), math.sin(-tilt)
        rx = np.array([[1.0, 0.0, 0.0], [0.0, cx, -sx], [0.0, sx, cx]])
        return rx @ rz

    def matrix(self) -> np.ndarray:
        """World -> clip space, 4x4 (row-major; transpose for OpenGL's column order)."""
        view = np.eye(4)
        rot = self.rotation()
        view[:3, :3] = rot
        view[:3, 3] = -rot @ self.target
        half_w = self.half_height * self.aspect
        proj = np.diag([1 / half_w, 1 / self.half_height, -1 / self.depth, 1.0])
        return proj @ view

    def pixel(self, height_px: float) -> float:
        """Millimetres per pixel of a view ``height_px`` pixels high."""
        return 2 * self.half_height / max(height_px, 1.0)

    def project(self, points: np.ndarray) -> np.ndarray:
        """(n, 3) world points -> (n, 3) normalised device coordinates."""
        m = self.matrix()
        return np.asarray(points, float) @ m[:3, :3].T + m[:3, 3]

    def on_screen(self, ndc_x: float, ndc_y: float) -> np.ndarray:
        """The world point at this screen position in the plane through the target."""
        right, up, _ = self.rotation()
        return self.target + right * ndc_x * self.half_height * self.aspect + up * ndc_y * self.half_height

    # -- what the operator does ----------------------------------------------------------

    def preset(self, name: str) -> None:
        self.yaw, self.pitch = PRESETS[name]

    def orbit(self, d_yaw: float, d_pitch: float) -> None:
        self.yaw = (self.yaw + d_yaw) % 360.0
        self.pitch = min(90.0, max(-90.0, self.pitch + d_pitch))

    def pan(self, d_ndc_x: float, d_ndc_y: float) -> None:
        """Move the picture by this much of the screen (the world follows the cursor)."""
        self.target = self.on_screen(-d_ndc_x, -d_ndc_y)

    def zoom_at(self, factor: float, ndc_x: float, ndc_y: float) -> None:
        """Zoom by ``factor`` (> 1: closer) keeping the point under the cursor still."""
        fixed = self.on_screen(ndc_x, ndc_y)
        new_half = min(MAX_HALF_HEIGHT, max(MIN_HALF_HEIGHT, self.half_height / factor))
        self.target = fixed + (self.target - fixed) * (new_half / self.half_height)
        self.half_height = new_half

    def fit(self, low, high) -> None:
        """Show the box ``low``..``high`` whole from the current direction."""
        low, high = np.asarray(low, float), np.asarray(high, float)
        corners = np.array([[x, y, z] for x in (low[0], high[0]) for y in (low[1], high[1])
                            for z in (low[2], high[2])])
        rot = self.rotation()
        local = corners @ rot.T
        lo, hi = local.min(axis=0), local.max(axis=0)
        centre = (lo + hi) / 2
        self.target = rot.T @ centre
        size = np.maximum(hi - lo, 1e-3)
        self.half_height = max(size[1] / 2, size[0] / 2 / max(self.aspect, 1e-6), 1.0) * FIT_MARGIN
        self.depth = max(float(np.linalg.norm(high - low)), 10.0) * 2

    def look_at(self, point, half_height: float) -> None:
        """Centre ``point`` at ``half_height`` millimetres (for jumping to a place)."""
        self.target = np.asarray(point, float).copy()
        self.half_height = min(MAX_HALF_HEIGHT, max(MIN_HALF_HEIGHT, half_height))
