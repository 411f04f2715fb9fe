"""The CNC MCU's motion side: dialect parser, planner, servo loop and motor physics. No Qt.

Public API: ``DialectParser``, ``Move``, ``DialectError``, ``soft_limit_violation``
(``dialect``); ``MotionController`` (``controller``); the events ``Finished``, ``Alarm``,
``Homed``, ``StateChanged``, ``Held``, ``Stopped`` and ``MotionError`` (``events``).
"""

from backend_sim.motion.controller import MotionController
from backend_sim.motion.dialect import DialectError, DialectParser, Move, soft_limit_violation
from backend_sim.motion.events import Alarm, Finished, Held, Homed, MotionError, StateChanged, Stopped

__all__ = [
    "Alarm", "DialectError", "DialectParser", "Finished", "Held", "Homed", "MotionController",
    "MotionError", "Move", "StateChanged", "Stopped", "soft_limit_violation",
]
