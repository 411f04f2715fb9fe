"""Every file the window or the CLI reads for itself (settings, profile, tools, prefs,
layout) goes through one checked reader (issue 20): a FIFO never blocks, a link to
/dev/zero never fills memory, 100,000 ``[`` never reach the parser; a bad file is set
aside with a message and its default used. Every write is atomic: two writers and a
reader of the tool table never fail nor see an empty or half table."""

from __future__ import annotations

import json
import multiprocessing
import os
from pathlib import Path

import pytest

from app.atomic import set_aside
from app.gcode.reading import CONFIG_MAX_BYTES, SourceError, load_json, nesting_problem
from app.gcode.tools import Tool, load_tools, save_tools
from app.profile import MachineProfile, read_profile
from app.ui.settings.prefs import Prefs, load_prefs
from app.ui.settings.store import load_settings
from app.ui.window_state import load_window_state


def _readers():
    """(file name, reader, whether it gave its default) for each file the window reads."""
    return [
        ("settings.json", load_settings, lambda r: r.profile == MachineProfile() and r.problem),
        ("tools.json", load_tools, lambda r: r.tools == {} and r.problem),
        ("prefs.json", load_prefs, lambda r: r.prefs == Prefs() and r.problem),
        ("window.json", load_window_state, lambda r: r.geometry is None and r.problem),
        ("machine.toml", read_profile, lambda r: r.profile == MachineProfile() and r.problems),
    ]


BAD_FILES = {
    "fifo": lambda path: os.mkfifo(path),
    "dev_zero": lambda path: path.symlink_to("/dev/zero"),
    "folder": lambda path: path.mkdir(),
    "too_big": lambda path: path.write_bytes(b" " * (CONFIG_MAX_BYTES + 1)),
    "deep": lambda path: path.write_text("[" * 100_000),
    "deep_object": lambda path: path.write_text('{"a": ' * 100_000),
    "binary": lambda path: path.write_bytes(b"\x00\xff" * 100),
}


@pytest.mark.parametrize("kind", sorted(BAD_FILES))
@pytest.mark.parametrize(("name", "reader", "defaulted"), _readers(), ids=lambda v: getattr(v, "__name__", v))
def test_a_bad_file_never_blocks_nor_fills_memory(tmp_path, kind, name, reader, defaulted):
    path = tmp_path / name
    BAD_FILES[kind](path)
    result = reader(path)  # a FIFO would block here for ever; /dev/zero would fill the memory
    assert defaulted(result), (kind, name, result)
    problem = str(getattr(result, "problem", "") or " ".join(getattr(result, "problems", ())))
    assert name in problem


@pytest.mark.parametrize("name", ["settings.json", "tools.json", "prefs.json", "window.json"])
def test_a_damaged_file_is_set_aside_and_named(tmp_path, name):
    reader = {n: r for n, r, _ in _readers()}[name]
    path = tmp_path / name
    path.write_text("[" * 100_000)
    problem = str(reader(path).problem)
    assert not path.exists() and (tmp_path / f"{name}.damaged").read_text() == "[" * 100_000
    assert f"{name}.damaged" in problem
    path.write_text("{")  # a second damaged file does not overwrite the first one kept
    reader(path)
    assert (tmp_path / f"{name}.damaged-2").read_text() == "{"


def test_the_window_starts_with_every_file_bad(qtbot, tmp_path):
    from app.ui.main_window import MainWindow
    from app.ui.notifier import Notifier

    config = tmp_path / "config"
    config.mkdir()
    os.mkfifo(config / "tools.json")
    (config / "prefs.json").symlink_to("/dev/zero")
    (config / "settings.json").write_text("[" * 100_000)
    (config / "window.json").write_text('{"a": ' * 100_000)
    notifier = Notifier(show_boxes=False)
    window = MainWindow(config_dir=config, notifier=notifier)
    qtbot.addWidget(window)
    said = "\n".join(text for _, _, text in notifier.messages)
    for name in ("tools.json", "prefs.json", "settings.json", "window.json"):
        assert name in said and (config / f"{name}.damaged").exists()
    window.shutdown()


def test_json_nesting_is_checked_outside_strings(tmp_path):
    assert nesting_problem('{"a": "' + "[" * 80 + '"}') is None
    assert nesting_problem('["\\\\", ' + "[" * 70, 64) is not None
    path = tmp_path / "x.json"
    path.write_text('{"a": [1, 2, {"b": "]]]]"}]}')
    assert load_json(path) == {"a": [1, 2, {"b": "]]]]"}]}
    path.write_text("[" * 65 + "]" * 65)
    with pytest.raises(SourceError, match="nested more than 64 levels"):
        load_json(path)
    with pytest.raises(FileNotFoundError):
        load_json(tmp_path / "missing.json")


def test_set_aside_finds_a_free_name(tmp_path):
    path = tmp_path / "a.json"
    for n in range(3):
        path.write_text(str(n))
        set_aside(path)
    kept = [(tmp_path / f"a.json{s}").read_text() for s in (".damaged", ".damaged-2", ".damaged-3")]
    assert kept == ["0", "1", "2"]


# -- two windows saving the tool table at once ---------------------------------------

ROUNDS = 300


def _writer(path: str, number: int, ready, go) -> None:
    ready.set()
    go.wait()
    for n in range(ROUNDS):
        tools = {t: Tool(t, 1.0 + number, float(n), f"writer {number}") for t in range(1, 40)}
        save_tools(Path(path), tools)


def test_two_writers_and_a_reader_never_see_a_half_or_empty_table(tmp_path):
    path = tmp_path / "tools.json"
    save_tools(path, {1: Tool(1, 1.0, 0.0, "first")})
    context = multiprocessing.get_context("spawn")
    go = context.Event()
    readies = [context.Event() for _ in range(2)]
    writers = [context.Process(target=_writer, args=(str(path), n, readies[n], go)) for n in range(2)]
    for writer in writers:
        writer.start()
    for ready in readies:
        assert ready.wait(60)
    go.set()
    reads = 0
    while any(w.is_alive() for w in writers) or reads < 50:
        loaded = load_tools(path)
        assert loaded.problem == "" and loaded.tools, loaded.problem
        assert len({t.diameter for t in loaded.tools.values()}) == 1  # one writer's table, whole
        reads += 1
    for writer in writers:
        writer.join(60)
        assert writer.exitcode == 0  # neither writer failed
    assert not [p.name for p in tmp_path.iterdir() if p.name != "tools.json"]  # no temporary file left
    assert json.loads(path.read_text())["tools"][0]["comment"].startswith("writer")


def test_the_cli_reads_point_lists_and_contours_through_the_checked_reader(tmp_path, capsys):
    from app.gcode.features.cli import main as feature
    from app.gcode.pointlist.cli import main as import_points

    fifo = tmp_path / "points.xyz"
    os.mkfifo(fifo)
    assert import_points([str(fifo)]) == 1  # a FIFO would block here for ever
    assert "not a regular file" in capsys.readouterr().err
    args = ["profile", "--contour", "/dev/zero", "--side", "outside", "--tool-diameter", "3", "--depth", "1"]
    assert feature(args) == 2  # /dev/zero would fill the memory
    assert "not a regular file" in capsys.readouterr().err
