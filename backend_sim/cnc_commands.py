"""Commands the CNC MCU carries out (``C <id> <VERB> [args]``), one handler per verb.

Each handler answers ``O <id> <VERB> [info]`` when the command has been carried out
(at once, or when the motion controller reports it: ``HOME`` on Homed, ``PAUSE`` on
Held, ``STOP`` on Stopped, ``JOG`` back in IDLE, ``SPINDLE`` when at speed) or ``E <id> <code> <text>``:
NOT_HOMED, SOFT_LIMIT, BUSY, COVER_OPEN, ALARM, BAD_ARGS, BAD_PARAM, BAD_SEQ,
UNKNOWN_VERB. ``PING``/``STATUS`` answer with ``S``. ``realtime`` carries out an ``R``
frame (HOLD, RESUME, STOP, RESET as the ``C`` verb does; JOG, JOGEND: the continuous
jog of ``continuous_jog``), answered at once with the state after it; an override
frame (FEED, SPINDLE, RAPID with a percentage) sets the controller's override, in any
state. Each handler keeps the status's ``why`` (``mcu.why``): a hold or stop
by a command is ``HOST`` (``PANEL`` for the main MCU's own ids: its buttons; an ``R``
frame may name its own reason), cleared by ``JOB``, ``HOME`` and a ``RESUME`` taken.
"""

from __future__ import annotations

from app.comm.frame import Command, Error, FrameError, Ok, RealtimeCommand, decimal
from backend_sim import value_ranges, work_systems
from backend_sim.motion import events as ev
from backend_sim.motion.dialect import DialectError, DialectParser
from backend_sim.motion.events import MotionError
from backend_sim.outgoing import encode_fit

AXES = "XYZ"
OWN_ID0 = 1_000_000_000  # ids of the main MCU's own commands (its panel, its SD job)
OFFSET_NAMES = ("OFFSET_X", "OFFSET_Y", "OFFSET_Z")  # GET: the work offset, machine mm
RUNNING = frozenset({"RUN", "HOLD", "HOMING", "JOG"})


class Refused(Exception):
    """A command refused with ``E <id> <code> <text>``."""

    def __init__(self, code: str, text: str = "") -> None:
        super().__init__(code, text)
        self.code, self.text = code, text


def realtime(mcu, frame: RealtimeCommand) -> None:
    """An ``R`` frame: act as its ``C`` verb at once; ``O <id> <VERB> <state>`` or ``E``."""
    cmd = Command(frame.id, frame.verb, frame.args)
    try:
        if frame.percent is not None:  # an override (FEED, SPINDLE, RAPID): any state
            mcu.mc.set_override(frame.verb, frame.percent)
            mcu.send_status()  # the new value shows in the status at once
        else:
            _REALTIME[frame.verb](mcu, cmd, frame.why or _source(cmd))
    except Refused as exc:
        mcu.send(Error(frame.id, exc.code, exc.text))
    except MotionError as exc:
        mcu.send(Error(frame.id, exc.code, exc.text))
    else:
        if frame.verb != "RESET":
            mcu.send(Ok(frame.id, frame.verb, mcu.status().state))


def _source(cmd: Command) -> str:
    return "PANEL" if cmd.id >= OWN_ID0 else "HOST"


def _hold_now(mcu, cmd: Command, why: str) -> None:
    if mcu.mc.state in ("RUN", "JOG", "HOMING") and mcu.mc.waiting is None:
        mcu.why = why
    _homing_stopped(mcu, cmd.verb)
    mcu.mc.feed_hold()


def _homing_stopped(mcu, verb: str) -> None:
    """A hold or stop ends a homing: its ``HOME`` is answered ``E NOT_HOMED`` now."""
    if mcu.mc.state != "HOMING":
        return
    for pending in [p for p in mcu.pending if p.verb == "HOME"]:
        mcu.pending.remove(pending)
        mcu.send(Error(pending.id, "NOT_HOMED", f"homing stopped by {verb}"))


def _resume_now(mcu, cmd: Command, why: str) -> None:
    _resume(mcu, cmd)


def _stop_now(mcu, cmd: Command, why: str) -> None:
    if mcu.job.open or mcu.mc.state != "IDLE":
        mcu.why = why
    _homing_stopped(mcu, cmd.verb)
    mcu.stop_job()


def _reset_now(mcu, cmd: Command, why: str) -> None:
    _reset(mcu, cmd)
    mcu.recent.start(cmd.id)  # the reset's own id outlives it: a copy right behind is a repeat
    mcu.recent.record(cmd.id, encode_fit(Ok(cmd.id, "RESET", "")))


def _jog_keep(mcu, cmd: Command, why: str) -> None:
    """``R JOG <dirs> <feed>``: start or keep alive a continuous jog."""
    mcu.jogging.keep(cmd.args[0], decimal(cmd.args[1], "jog feed"))


def _jog_end(mcu, cmd: Command, why: str) -> None:
    mcu.jogging.end()


_REALTIME = {"HOLD": _hold_now, "RESUME": _resume_now, "STOP": _stop_now, "RESET": _reset_now,
             "JOG": _jog_keep, "JOGEND": _jog_end}


def dispatch(mcu, cmd: Command) -> None:
    handler = HANDLERS.get(cmd.verb)
    try:
        if handler is None:
            raise Refused("UNKNOWN_VERB", cmd.verb)
        info = handler(mcu, cmd)
    except Refused as exc:
        mcu.send(Error(cmd.id, exc.code, exc.text))
    except MotionError as exc:
        mcu.send(Error(cmd.id, exc.code, exc.text))
    except ValueError as exc:
        mcu.send(Error(cmd.id, "BAD_ARGS", str(exc)))
    else:
        if info is not None:
            mcu.send(Ok(cmd.id, cmd.verb, info))


# ---------------------------------------------------------------------- checks


def _not_running(mcu) -> None:
    if mcu.job.open or mcu.mc.state in RUNNING:
        raise Refused("BUSY", f"machine is {mcu.mc.state}" + (" with a job open" if mcu.job.open else ""))


def _cover_closed(mcu) -> None:
    if mcu.cover_open:
        raise Refused("COVER_OPEN", "close the cover first")


def _homed(mcu) -> None:
    if not mcu.mc.homed:
        raise Refused("NOT_HOMED", "home first")


def _number(text: str, what: str) -> float:
    """The strict number grammar of docs/protocol.md (no ``1_0``, ``1e3``, ``inf``, ``nan``)."""
    try:
        return decimal(text, what)
    except FrameError as exc:
        raise Refused("BAD_ARGS", str(exc)) from None


def _args(cmd: Command, low: int, high: int) -> tuple[str, ...]:
    if not low <= len(cmd.args) <= high:
        raise Refused("BAD_ARGS", f"{cmd.verb} takes {low}..{high} arguments")
    return cmd.args


# ---------------------------------------------------------------------- handlers


def _status(mcu, cmd: Command) -> None:
    mcu.send_status()


def _home(mcu, cmd: Command) -> None:
    (mode,) = _args(cmd, 0, 1) or ("NORMAL",)
    if mode not in ("NORMAL", "RECOVER"):
        raise Refused("BAD_ARGS", f"HOME {mode}: NORMAL or RECOVER")
    _cover_closed(mcu)
    if mcu.mc.state != "ALARM":
        _not_running(mcu)
    mcu.job.close()
    mcu.mc.home(mode)
    mcu.why = ""
    mcu.await_event(cmd.id, "HOME", ev.Homed, mode)


def _job(mcu, cmd: Command) -> str:
    count, *kind = _args(cmd, 1, 2)
    if not count.isdigit() or int(count) < 1:
        raise Refused("BAD_ARGS", f"JOB {count}: a line count >= 1")
    if kind not in ([], ["MDI"]):
        raise Refused("BAD_ARGS", f"JOB {count} {kind[0]}: the only second word is MDI")
    if not mcu.check_mode:
        _cover_closed(mcu)
    _not_running(mcu)
    _alarm_free(mcu)
    if not mcu.check_mode:
        _homed(mcu)
    mcu.reset_parser()
    mcu.why = ""
    mcu.job.start(int(count))
    mcu.job_mdi = bool(kind)
    mcu.lines.clear()
    mcu.send_status()  # before the O: no status of the last job may follow it
    return count


def _alarm_free(mcu) -> None:
    if mcu.mc.state == "ALARM":
        raise Refused("ALARM", "clear the alarm: HOME RECOVER or RESET")


def _pause(mcu, cmd: Command) -> str | None:
    if mcu.mc.state not in ("RUN", "JOG", "HOMING"):
        return mcu.mc.state
    if mcu.mc.waiting is None:  # at a program stop the hold stays the program's
        mcu.why = _source(cmd)
    moving_job = mcu.mc.state == "RUN"
    _homing_stopped(mcu, "PAUSE")
    mcu.mc.feed_hold()  # a jog is cancelled, homing stops: answered once stopped
    mcu.await_event(cmd.id, "PAUSE", ev.Held if moving_job else ev.Stopped)
    return None


def _resume(mcu, cmd: Command) -> str:
    if cmd.args:
        return _resume_from(mcu, cmd)
    _cover_closed(mcu)
    _alarm_free(mcu)
    if mcu.mc.parked is not None:
        raise Refused("BUSY", "a jog runs at the program stop: resume once it has ended")
    mcu.mc.resume()
    mcu.why = ""
    return ""


def _resume_from(mcu, cmd: Command) -> str:
    if len(cmd.args) != 2 or cmd.args[0] != "FROM" or not cmd.args[1].isdigit():
        raise Refused("BAD_ARGS", "RESUME FROM <seq>")
    seq = int(cmd.args[1])
    if not mcu.job.open:
        raise Refused("BAD_SEQ", "no job open (new boot or job ended): re-home and restart")
    if seq != mcu.job.acc + 1:
        raise Refused("BAD_SEQ", f"next line is {mcu.job.acc + 1}, not {seq}")
    _cover_closed(mcu)
    mcu.job.expected = seq
    mcu.job.bad_stretch = False
    mcu.mc.resume(release_stop=False)
    return f"FROM {seq}"


def _stop(mcu, cmd: Command) -> None:
    mcu.await_event(cmd.id, "STOP", ev.Stopped)
    _stop_now(mcu, cmd, _source(cmd))


def _reset(mcu, cmd: Command) -> None:
    mcu.send(Ok(cmd.id, "RESET", ""))
    mcu.reset()


def _in_range(value: float, check) -> float:
    problem = check(value)
    if problem:
        raise Refused("BAD_VALUE", problem)
    return value


def _jog(mcu, cmd: Command) -> None:
    axis, dist, feed = _args(cmd, 3, 3)
    if axis not in AXES:
        raise Refused("BAD_ARGS", f"axis {axis}: X, Y or Z")
    distance = _in_range(_number(dist, "distance"), value_ranges.distance_problem)
    rate = _in_range(_number(feed, "feed"), value_ranges.feed_problem)
    _cover_closed(mcu)
    if mcu.job.open and not mcu.mc.at_stop():
        raise Refused("BUSY", "a job is open")
    _alarm_free(mcu)
    mcu.mc.jog(axis, distance, rate)
    mcu.await_event(cmd.id, "JOG", ev.StateChanged, f"{axis} {dist}")


def _spindle(mcu, cmd: Command) -> str | None:
    (value,) = _args(cmd, 1, 1)
    if value == "OFF":
        mcu.mc.spindle_off()  # always allowed: whatever moves or holds, the spindle stops now
        return "OFF"
    line = f"M03 S{_in_range(_number(value, 'rpm'), value_ranges.rpm_problem):g}"
    _cover_closed(mcu)
    if mcu.job.open:
        raise Refused("BUSY", "a job is open: use M03/M05 in the program")
    _alarm_free(mcu)
    try:
        move = DialectParser(mcu.offset, tuple(mcu.mc.commanded_mm)).parse(-1, line)
    except DialectError as exc:
        raise Refused(exc.code, exc.text) from None
    mcu.mc.enqueue(move)
    mcu.await_event(cmd.id, "SPINDLE", ev.StateChanged, value)
    return None


def _set(mcu, cmd: Command) -> str:
    name, value = _args(cmd, 2, 2)
    try:
        number = value_ranges.set_value(name, value)
    except ValueError as exc:
        raise Refused("BAD_ARGS", str(exc)) from None
    if number is None:
        number = _number(value, name)
    elif value_ranges.choice_problem(name, value):
        raise Refused("BAD_PARAM", value_ranges.choice_problem(name, value))
    if work_systems.owns(name):
        work_systems.set_(mcu, name, number, Refused, _not_running)
    elif name == "CHECK":
        if mcu.job.open:
            raise Refused("BUSY", "a job is open")
        mcu.check_mode = bool(number)
    elif not _param(mcu.stops.set, name, number):
        _param(mcu.mc.set_param, name, number)
    return f"{name} {value}"


def _get(mcu, cmd: Command) -> str:
    (name,) = _args(cmd, 1, 1)
    value = mcu.stops.get(name)
    if name in OFFSET_NAMES:
        value = mcu.offset[OFFSET_NAMES.index(name)]
    elif work_systems.owns(name):
        value = work_systems.get(mcu, name)
    elif value is None:
        value = int(mcu.check_mode) if name == "CHECK" else _param(mcu.mc.get_param, name)
    return f"{name} {value:g}"


def _param(call, *args):
    try:
        return call(*args)
    except ValueError as exc:
        raise Refused("BAD_PARAM", str(exc)) from None


def _zero(mcu, cmd: Command) -> str:
    axes = "".join(cmd.args) or AXES
    if not axes or any(a not in AXES for a in axes):
        raise Refused("BAD_ARGS", f"ZERO {axes}: axes among X Y Z")
    _homed(mcu)
    position = mcu.mc.commanded_mm
    offset = tuple(position[k] if AXES[k] in axes else mcu.offset[k] for k in range(3))
    if mcu.job.open and mcu.mc.at_stop() and mcu.mc.state != "JOG":
        _zero_at_stop(mcu, offset)
    else:
        _not_running(mcu)
        work_systems.write_active(mcu, offset)
    return " ".join(f"{a}{o:.3f}" for a, o in zip(AXES, mcu.offset, strict=True))


def _zero_at_stop(mcu, offset) -> None:
    """``ZERO`` at a program stop: the rest of the job keeps its work coordinates
    (the parser and the queued moves shift with the offset; the parser keeps its modes)."""
    parser, old = mcu.parser, mcu.offset
    work_systems.write_active(mcu, offset)
    delta = tuple(n - o for n, o in zip(mcu.offset, old, strict=True))
    parser.offset = tuple(mcu.offset)
    parser.position = tuple(p + d for p, d in zip(parser.position, delta, strict=True))
    mcu.parser = parser
    mcu.mc.shift_stop(delta)


HANDLERS = {
    "PING": _status,
    "STATUS": _status,
    "HOME": _home,
    "JOB": _job,
    "PAUSE": _pause,
    "RESUME": _resume,
    "STOP": _stop,
    "RESET": _reset,
    "JOG": _jog,
    "SPINDLE": _spindle,
    "SET": _set,
    "GET": _get,
    "ZERO": _zero,
}

__all__ = ["HANDLERS", "Refused", "dispatch"]
