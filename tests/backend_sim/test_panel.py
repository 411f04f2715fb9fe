"""The front panel: OLED text read back through the font, buttons, LED, resets; no host."""

from __future__ import annotations

import numpy as np

from backend_sim import oled
from backend_sim.font5x7 import GLYPHS

PROGRAM = ["G00 Z5", "G00 X5 Y5", "G01 Z4 F600", "G01 X9", "G00 Z5"]


def test_font_covers_printable_ascii_with_distinct_glyphs():
    assert set(GLYPHS) == {chr(c) for c in range(0x20, 0x7F)}
    assert len(set(GLYPHS.values())) == len(GLYPHS)
    assert all(len(g) == 5 and max(g) < 0x80 for g in GLYPHS.values())


def test_render_and_read_back_every_character():
    printable = "".join(chr(c) for c in range(0x21, 0x7F))
    rows = [printable[i:i + 21] for i in range(0, len(printable), 21)]
    fb = oled.render(rows)
    assert fb.shape == (64, 128) and fb.dtype == np.bool_
    assert oled.read_text(fb)[: len(rows)] == rows


def test_inverted_row_reads_back():
    fb = oled.render(["TITLE", oled.INVERT + " Run SD file"])
    assert fb[8:16, 126:].all()
    assert oled.read_text(fb)[:2] == ["TITLE", " Run SD file"]


def test_status_page_shows_state_position_gains_and_link(sim):
    sim.run_for(0.1)
    text = sim.panel.oled_text()
    assert text[0].startswith("IDLE")
    assert text[1].split() == ["X", "0.000"] and text[3].split() == ["Z", "-20.000"]
    assert text[4] == "S0 P8 I20 D0.05"
    assert text[5] == "HOST -- UART OK"


def press(sim, *buttons):
    for button in buttons:
        sim.panel.press(button)
        sim.run_for(0.05)


def test_standalone_home_then_run_an_sd_file_to_the_end(sim, tmp_path):
    (tmp_path / "sd" / "a.nc").write_text("G00 Z5\n")
    (tmp_path / "sd" / "part.nc").write_text("\n".join(PROGRAM) + "\n")
    press(sim, "OK")
    assert sim.panel.oled_text()[:6] == ["MENU", " Run SD file", " Pause", " Resume", " Stop", " Home"]
    press(sim, "DOWN", "DOWN", "DOWN", "DOWN", "OK")
    assert sim.run_until(lambda: sim.panel.oled_text()[7] == "HOME ok", 60)
    assert sim.cnc.mc.homed
    press(sim, "OK", "OK")
    assert sim.panel.oled_text()[:3] == ["SD FILES", " a.nc", " part.nc"]
    assert not sim.panel.oled_framebuffer()[16:24, 126:].all()
    press(sim, "DOWN")
    assert sim.panel.oled_framebuffer()[16:24, 126:].all()
    press(sim, "OK")
    assert sim.run_until(lambda: "SD part.nc" in sim.panel.oled_text()[6], 5)
    assert sim.panel.oled_text()[0].split()[:2] == ["RUN", "HS"]
    assert sim.run_until(lambda: sim.main.sd_job is None, 60)
    assert [line for _, line in sim.exec_log] == PROGRAM
    text = sim.panel.oled_text()
    assert text[7] == "SD part.nc done"
    assert abs(float(text[1].split()[1]) - 9.0) <= 0.01
    assert abs(float(text[3].split()[1]) - 5.0) <= 0.01


def test_panel_pause_and_resume_a_running_sd_job(sim, tmp_path):
    (tmp_path / "sd" / "long.nc").write_text("G01 X60 F600\nG01 X0\n")
    press(sim, "OK", "DOWN", "DOWN", "DOWN", "DOWN", "OK")
    assert sim.run_until(lambda: sim.panel.oled_text()[7] == "HOME ok", 60)
    press(sim, "OK", "OK", "OK")
    assert sim.run_until(lambda: sim.cnc.mc.state == "RUN", 2)
    press(sim, "OK", "DOWN", "OK")
    assert sim.run_until(lambda: sim.panel.oled_text()[7] == "PAUSE ok", 5)
    assert sim.cnc.mc.state == "HOLD"
    press(sim, "OK", "DOWN", "DOWN", "OK")
    assert sim.run_until(lambda: sim.main.sd_job is None, 60)
    assert len(sim.exec_log) == 2


def test_exit_goes_back_and_empty_card(sim):
    press(sim, "OK", "OK")
    assert sim.panel.oled_text()[:2] == ["SD FILES", " (empty)"]
    press(sim, "OK", "EXIT")
    assert sim.panel.oled_text()[0] == "MENU"
    press(sim, "EXIT")
    assert sim.panel.oled_text()[0].startswith("IDLE")


def test_run_without_homing_shows_the_refusal(sim, tmp_path):
    (tmp_path / "sd" / "part.nc").write_text("G00 Z5\n")
    press(sim, "OK", "OK", "OK")
    assert sim.run_until(lambda: sim.panel.oled_text()[7] == "NOT_HOMED", 1)
    assert sim.main.sd_job is None


def test_reset_buttons(sim, host):
    boot = sim.cnc.boot_id
    sim.panel.press("RESET")
    sim.run_for(0.1)
    assert sim.cnc.boot_id != boot and not sim.cnc.mc.homed
    sim.panel.press("MRESET")
    assert not sim.main.host_connected
    sim.run_for(0.1)
    assert sim.panel.oled_text()[5] == "HOST -- UART OK"


def test_led_heartbeat_without_alert(sim):
    states = []
    for _ in range(8):
        sim.run_for(0.25)
        states.append((sim.panel.led, sim.panel.buzzer))
    assert {led for led, _ in states} == {True, False}
    assert not any(buzz for _, buzz in states)


def test_sd_run_holds_at_program_stops_ok_continues_exit_stops(sim, tmp_path):
    stops = ["M03 S3000", "G00 Z5", "G00 X5 Y5", "M00", "G01 X9 F600", "M06 T2", "G01 X5", "M05"]
    (tmp_path / "sd" / "stops.nc").write_text("\n".join(stops) + "\n")
    press(sim, "OK", "DOWN", "DOWN", "DOWN", "DOWN", "OK")
    assert sim.run_until(lambda: sim.panel.oled_text()[7] == "HOME ok", 60)
    press(sim, "OK", "OK", "OK")  # menu, Run SD file, the only file
    assert sim.run_until(lambda: sim.panel.oled_text()[0] == "PROGRAM STOP", 30)
    text = sim.panel.oled_text()
    assert text[1] == "line 3: M00" and text[4:6] == ["OK   continue", "EXIT stop job"]
    assert [seq for seq, _ in sim.exec_log] == [0, 1, 2]
    press(sim, "OK")
    assert sim.run_until(lambda: sim.panel.oled_text()[0] == "TOOL CHANGE", 30)
    assert sim.panel.oled_text()[1:3] == ["line 5: M06 T2", "fit tool T2"]
    assert sim.cnc.status().rpm < 3000 and "P" not in sim.cnc.flags()
    press(sim, "EXIT")
    assert sim.run_until(lambda: sim.main.sd_job is None, 10)
    assert [seq for seq, _ in sim.exec_log] == [0, 1, 2, 3, 4]


def test_oled_shows_the_measured_spindle_speed(sim, host):
    cid = host.command("SPINDLE 3000")
    host.wait(lambda f: f.KIND == "O" and f.id == cid)
    sim.run_for(1.5)  # the main MCU's UART ping brings the CNC MCU's reading
    rpm = int(sim.panel.oled_text()[4].split()[0][1:])
    assert 2500 < rpm <= 3750
