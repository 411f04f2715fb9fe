"""The custom commands' file (app/ui/settings/commands.py)."""

from __future__ import annotations

import json

from app.ui.settings.commands import CustomCommand, load_commands, save_commands


def test_saved_commands_read_back(tmp_path):
    path = tmp_path / "commands.json"
    commands = (CustomCommand("Park", gcode="G00 Z10\nG00 X0 Y0", confirm=True),
                CustomCommand("Surface", file=str(tmp_path / "surface.ngc")))
    save_commands(path, commands)
    loaded = load_commands(path)
    assert loaded.commands == commands and loaded.problem == ""


def test_a_missing_file_gives_none_and_a_damaged_one_is_set_aside(tmp_path):
    path = tmp_path / "commands.json"
    assert load_commands(path).commands == ()
    path.write_text("{not json")
    loaded = load_commands(path)
    assert loaded.commands == () and "commands.json" in loaded.problem
    assert not path.exists() and any(p.name.startswith("commands.json") for p in tmp_path.iterdir())


def test_a_bad_entry_is_named_and_left_out(tmp_path):
    path = tmp_path / "commands.json"
    rows = [{"name": "ok", "gcode": "G00 Z5"}, {"name": "", "gcode": "G00 Z5"},
            {"name": "both", "gcode": "G00 Z5", "file": "a.ngc"}, {"name": "x", "gcode": 5},
            {"name": "y", "gcode": "M05", "confirm": "yes"}, "text"]
    path.write_text(json.dumps({"version": 1, "commands": rows}))
    loaded = load_commands(path)
    assert [c.name for c in loaded.commands] == ["ok"]
    for number in (2, 3, 4, 5, 6):
        assert f"command {number}:" in loaded.problem, loaded.problem
    assert "not both" in loaded.problem and "confirm must be true or false" in loaded.problem
