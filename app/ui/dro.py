"""The DRO's link to the machine: reads the six work systems on connect, follows every
answer that changes them, shows each status, and sends the operator's requests once
the state table allows them (``work_offsets``, ``zero``, ``go_to``).

After the active system changes (``SET WCS``, or a row of the active system), the
work offset is read again (``GET OFFSET_X..Z``) so the preflight (``app/ui/preflight.py``)
checks the program with the offset the machine now uses.
"""

from __future__ import annotations

from PySide6.QtCore import QObject

from app.ui.dro_panel import DroPanel
from app.ui.preflight import OFFSET_NAMES
from app.ui.session_binder import JOB
from app.ui.work_offsets import AXES, WorkSystems


def relative(systems) -> tuple:
    """What a program sees of ``systems``: the active one and each row less the active
    row (``None``, programs read without the machine's systems: G54 and no offsets)."""
    if systems is None:
        return 1, tuple((0.0, 0.0, 0.0) for _ in range(6))
    active, rows = systems
    return active, tuple(tuple(round(a - b, 6) for a, b in zip(rows[n], rows[active], strict=True))
                         for n in sorted(rows))


class Dro(QObject):
    def __init__(self, window, panel: DroPanel) -> None:
        super().__init__(window)
        self.w, self.panel = window, panel
        self.systems = WorkSystems()
        self.work: tuple[float, float, float] | None = None
        self._travel_offset: list[float] | None = None  # what the previews' travel box uses
        worker = window.link.worker
        worker.connected.connect(self.read_all)
        worker.command_finished.connect(self.on_command)
        worker.status_changed.connect(self.on_status)
        panel.select_requested.connect(self.select)
        panel.row_edited.connect(self.edit_row)
        panel.zero_requested.connect(window.operator.zero)
        panel.move_requested.connect(self.move_to)
        panel.refused.connect(self._say)

    def read_all(self, url: str = "") -> None:
        self.systems = WorkSystems()
        self.w.link.call("send_command", "GET WCS")
        self.show()

    def on_status(self, event) -> None:
        self.work = tuple(event.position)
        self.show()

    def on_command(self, result) -> None:
        first_answer = self.systems.supported is None
        if not self.systems.take(result.verb, tuple(result.args), result.info, result.ok, result.code):
            return
        name = result.args[0] if result.args else ""
        if first_answer and self.systems.supported:
            for query in WorkSystems.row_queries():
                self.w.link.call("send_command", query)
        active_row = name.startswith(f"G{self.systems.active}_")
        changed = result.verb == "SET" and result.ok and (name == "WCS" or active_row)
        if changed or (name == "WCS" and not result.ok):  # a new offset, or a machine with one only
            for offset in OFFSET_NAMES:
                self.w.link.call("send_command", f"GET {offset}")
        self._programs_follow()
        self._travel_follows()
        self.show()

    def _travel_follows(self) -> None:
        """The previews draw the travel box around the active system's work zero."""
        offset = self.systems.offset()
        if None in offset or offset == self._travel_offset:
            return
        self._travel_offset = offset
        travel = self.w.profile.travel
        self.w.preview.set_travel((travel.x_max, travel.y_max), offset[:2])
        self.w.preview3d.set_travel((travel.x_max, travel.y_max, travel.z_max), offset)

    def _programs_follow(self) -> None:
        """Programs are read with the machine's systems; the open one again when they
        place its G54-G59 differently from when it was read."""
        systems = self.systems.for_programs()
        if systems is None or relative(systems) == relative(self.w.loader.systems):
            self.w.loader.systems = systems if systems is not None else self.w.loader.systems
            return
        self.w.loader.systems = systems
        loaded = self.w.loaded
        if loaded is not None and not self.w.loader.busy and self.w.binder.state not in JOB:
            self.w.open_file(loaded.path)

    def show(self) -> None:
        live = getattr(self.w, "live_state", None)
        tracker = live.tracker if live is not None else None
        g92 = tracker.view.g92 if tracker is not None else ""  # in force in the running job
        self.panel.show_state(self.systems, self.work, g92)

    def select(self, system: int) -> None:
        self._send(WorkSystems.select(system))

    def edit_row(self, system: int, axis: str, value: float) -> None:
        self._send(WorkSystems.set_row(system, axis, value))

    def _send(self, command: str) -> None:
        """A change of the work offsets, if the table allows it now; if not (or until the
        machine answers) the panel shows what the machine has."""
        if self.w.operator.allowed("work_offsets"):
            self.w.link.call("send_command", command)
        self.show()

    def move_to(self, target: dict) -> None:
        if not self.w.operator.allowed("go_to"):
            return
        top = self.w.profile.travel.limits()[AXES.index("Z")][1]
        try:
            text = self.systems.move_to(target, top)
        except ValueError:
            self._say(self.tr("The work offset is not known yet: connect to the machine first."))
            return
        self.w.operator.run_lines(text, self.tr("Go to"))

    def _say(self, text: str) -> None:
        self.w.status.showMessage(text, 10000)
        self.w.console.add_log("warning", text)
