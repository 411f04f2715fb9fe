"""The Qt worker picks the GRBL driver for sim://grbl and drives the simulated GRBL
machine: capabilities and build info reach the window, a job runs to its end."""

from __future__ import annotations

from app.comm.worker import GRBL_PUMP_MS, PUMP_MS, SerialController, SerialWorker
from tests.comm.test_worker import on_gui


def test_worker_drives_the_grbl_simulator(qtbot):
    controller = SerialController(worker=SerialWorker())
    worker = controller.worker
    controller.start()
    try:
        info = on_gui(worker.machine_info_changed)
        caps_changed = on_gui(worker.capabilities_changed)
        with (qtbot.waitSignal(info, timeout=10000, check_params_cb=lambda i: bool(i.options)) as got_info,
              qtbot.waitSignal(caps_changed, timeout=10000) as caps):
            controller.connect_to("sim://grbl?speed=50")
        capabilities = caps.args[0]
        assert capabilities.driver == "grbl" and capabilities.overrides and not capabilities.sd_card
        assert got_info.args[0].flavour == "grbl" and got_info.args[0].planner_blocks == 15
        status = on_gui(worker.status_changed)
        with qtbot.waitSignal(on_gui(worker.command_finished), timeout=10000,
                              check_params_cb=lambda r: r.verb == "$X"):
            controller.send_command("$X")
        with qtbot.waitSignal(status, timeout=10000, check_params_cb=lambda s: s.state == "IDLE"):
            controller.send_command("STATUS")
        with qtbot.waitSignal(on_gui(worker.program_stopped), timeout=30000) as stop:
            controller.start_job(["G01 X1 Y1 F600", "G01 X2", "M06 T2", "G01 X3"])
        assert stop.args[0].tool == 2
        qtbot.waitUntil(lambda: worker._timer.interval() == GRBL_PUMP_MS)  # a job: its oks answered at once
        with qtbot.waitSignal(on_gui(worker.job_finished), timeout=60000) as finished:
            controller.resume()
        assert finished.args[0].completed
        qtbot.waitUntil(lambda: worker._timer.interval() == PUMP_MS)  # no job: fewer wake-ups
        with qtbot.waitSignal(status, timeout=10000, check_params_cb=lambda s: s.free == -1):
            controller.machine_call("set_feed_override", (150,))
    finally:
        assert controller.shutdown()
