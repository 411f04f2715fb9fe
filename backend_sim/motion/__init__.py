"""The CNC MCU's motion side: dialect parser, planner, servo loop and motor physics. No Qt.

Public API (the CNC MCU protocol layer uses it; see each module's docstring):

- ``dialect``: ``DialectParser``, ``Move``, ``DialectError``, ``soft_limit_violation``.
- ``controller``: ``MotionController(profile, mode="planner"|"simple")``.
- ``events``: ``Finished``, ``Alarm``, ``Homed``, ``StateChanged``, ``Held``, ``Stopped``
  and the ``MotionError`` that commands raise when refused.
- ``accuracy`` (tests and benchmarks only): run device lines and measure contour error.

Layout: ``motor`` (JGA25-370 + L298N + screw, exact ZOH discretisation), ``spindle``
(RS775, gate-time rpm), ``geometry`` (lines, arcs, helices by path length), ``planner``
(look-ahead, junction deviation, S-curve by moving average of path length),
``fastpath`` (the planner's tick inlined into the servo loop), ``simple`` (the original
firmware: Bresenham, chords, stop at every end), ``servo`` (generated 1 kHz loop: PID,
feed-forward, motor, encoders, switches), ``homing``, ``controller``/``controller_ops``.
"""

from backend_sim.motion.controller import MotionController
from backend_sim.motion.dialect import DialectError, DialectParser, Move, soft_limit_violation
from backend_sim.motion.events import Alarm, Finished, Held, Homed, MotionError, StateChanged, Stopped

__all__ = [
    "Alarm", "DialectError", "DialectParser", "Finished", "Held", "Homed", "MotionController",
    "MotionError", "Move", "StateChanged", "Stopped", "soft_limit_violation",
]
