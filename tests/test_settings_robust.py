"""Issue 14 point 9: bad settings and profiles never stop the window or the simulator;
each bad value is named (file, key, rule) and replaced by its default; writes are atomic."""

import os

import pytest

from app.atomic import write_atomic
from app.profile import Link, MachineProfile, ProfileError, check_value, load_profile, read_profile
from app.ui.settings.store import load_settings, save_settings
from app.ui.window_state import load_window_state, save_window_state

DEFAULT = MachineProfile()


def settings_file(tmp_path, text: str):
    path = tmp_path / "settings.json"
    path.write_text(text, encoding="utf-8")
    return path


@pytest.mark.parametrize("value,rule", [
    ("Infinity", "finite"), ("-Infinity", "finite"), ("NaN", "finite"), ('"8"', "text"), ("true", "true"),
    ("[1]", "not a number"), ("{}", "not a number"), ("null", "not a number"),
])
def test_bad_value_in_settings_is_named_and_replaced_by_the_default(tmp_path, value, rule):
    text = '{"version": 1, "profile": {"pid": {"kp": VALUE, "ki": 7}}}'.replace("VALUE", value)
    path = settings_file(tmp_path, text)
    loaded = load_settings(path)
    assert loaded.profile.pid.kp == DEFAULT.pid.kp and loaded.profile.pid.ki == 7  # the good value kept
    assert str(path) in loaded.problem and "kp" in loaded.problem and rule in loaded.problem
    assert path.read_text(encoding="utf-8") == text  # unchanged until the operator saves


def test_integer_field_refuses_a_fraction(tmp_path):
    path = settings_file(tmp_path, '{"version": 1, "profile": {"axis": {"encoder_ppr": 11.9}}}')
    loaded = load_settings(path)
    assert loaded.profile.axis.encoder_ppr == 11 and "whole number" in loaded.problem


@pytest.mark.parametrize("text", ["[" * 10_000 + "]" * 10_000, "[1, 2]", '"text"', "12", "",
                                  '{"version": 1, "profile": ' + "[" * 10_000 + "]" * 10_000 + "}",
                                  '{"version": 1, "profile": {"pid": ' + "[" * 5000 + "]" * 5000 + "}}",
                                  '{"version": 1, "profile": {"pid": 5}}'])
def test_structurally_wrong_settings_fall_back_to_defaults(tmp_path, text):
    path = settings_file(tmp_path, text)
    loaded = load_settings(path)
    assert loaded.profile == DEFAULT and loaded.problem and str(path) in loaded.problem


def test_contradicting_timers_are_refused_with_the_rule(tmp_path):
    path = settings_file(tmp_path, '{"version": 1, "profile": {"link": {"lost_s": 0.3, "heartbeat_s": 10}}}')
    loaded = load_settings(path)
    assert loaded.profile.link == Link()
    assert "heartbeat_s" in loaded.problem and "lost_s" in loaded.problem and "<" in loaded.problem


@pytest.mark.parametrize("suffix,text", [
    (".toml", "[pid]\nkp = inf\nki = 3\n"), (".toml", '[pid]\nkp = "8"\nki = 3\n'),
    (".toml", "[pid]\nkp = true\nki = 3\n"),
    (".json", '{"pid": {"kp": Infinity, "ki": 3}}'), (".json", '{"pid": {"kp": "8", "ki": 3}}'),
])
def test_profile_with_a_bad_value_loads_leniently_and_strictly_refuses(tmp_path, suffix, text):
    path = tmp_path / f"m{suffix}"
    path.write_text(text)
    read = read_profile(path)
    assert read.profile.pid.kp == DEFAULT.pid.kp and read.profile.pid.ki == 3
    assert len(read.problems) == 1 and str(path) in read.problems[0] and "kp" in read.problems[0]
    with pytest.raises(ProfileError, match="kp"):
        load_profile(path)


@pytest.mark.parametrize("text", ["[" * 10_000 + "]" * 10_000, "[1, 2]", "3"])
def test_profile_that_is_not_an_object(tmp_path, text):
    path = tmp_path / "m.json"
    path.write_text(text)
    read = read_profile(path)
    assert read.profile == DEFAULT and read.problems and str(path) in read.problems[0]


def test_simulator_starts_with_a_bad_profile(tmp_path, capsys):
    from backend_sim.__main__ import load_profile_for_sim

    path = tmp_path / "m.toml"
    path.write_text("[link]\nlost_s = 0.3\nheartbeat_s = 10\n[pid]\nkp = inf\n")
    profile = load_profile_for_sim(str(path))
    assert profile.link == Link() and profile.pid.kp == DEFAULT.pid.kp
    err = capsys.readouterr().err
    assert "kp" in err and "lost_s" in err and str(path) in err


@pytest.mark.parametrize("text,message", [("1_0", "not a number"), ("inf", "not a number"),
                                          ("nan", "not a number"), ("11.9", "whole number"),
                                          ("1e3", "not a number")])
def test_dialog_text_is_read_with_the_strict_grammar(text, message):
    section = DEFAULT.axis if message == "whole number" else DEFAULT.pid
    key = "encoder_ppr" if message == "whole number" else "kp"
    with pytest.raises(ProfileError, match=message):
        check_value(section, key, text, "PID", text=True)


# ---------------------------------------------------------------------- atomic writes


def test_write_atomic_replaces_whole_or_not_at_all(tmp_path, monkeypatch):
    path = tmp_path / "s.json"
    write_atomic(path, "old")

    def crash(*args):
        raise OSError("disk full")

    monkeypatch.setattr(os, "replace", crash)
    with pytest.raises(OSError):
        write_atomic(path, "new")
    monkeypatch.undo()
    assert path.read_text() == "old"
    assert [p.name for p in tmp_path.iterdir()] == ["s.json"], "no temporary file left"


def test_save_settings_is_atomic(tmp_path, monkeypatch):
    path = tmp_path / "settings.json"
    save_settings(path, DEFAULT)
    before = path.read_bytes()
    monkeypatch.setattr(os, "replace", lambda *a: (_ for _ in ()).throw(OSError("crash")))
    with pytest.raises(OSError):
        save_settings(path, MachineProfile(pid=DEFAULT.pid.__class__(kp=1.0)))
    assert path.read_bytes() == before


# ---------------------------------------------------------------------- window state


def test_window_state_round_trip(tmp_path):
    path = tmp_path / "window.json"
    save_window_state(path, b"\x01geometry", b"\x00state\xff")
    loaded = load_window_state(path)
    assert (loaded.geometry, loaded.state, loaded.problem) == (b"\x01geometry", b"\x00state\xff", "")


@pytest.mark.parametrize("text", ["{", "[]", '{"geometry": 5}', '{"state": "not base64 !!"}', "[" * 10_000])
def test_corrupt_window_state_is_ignored_and_kept_aside(tmp_path, text):
    path = tmp_path / "window.json"
    path.write_text(text)
    loaded = load_window_state(path)
    assert loaded.geometry is None and loaded.state is None and "window" in loaded.problem
    assert not path.exists() and (tmp_path / "window.json.damaged").read_text() == text


@pytest.mark.parametrize("text", ["", "[1, 2]", "{\"version\": 7}", "[" * 10_000 + "]" * 10_000, "\ud800",
                                  "{\"recent_files\": [1], \"dark\": 1}"])
def test_damaged_prefs_give_the_defaults_and_are_set_aside_whole(tmp_path, text):
    """A file that is no preferences is kept as prefs.json.damaged, byte for byte (a bad
    value in a good file is only named: that file stays)."""
    from app.ui.settings.prefs import Prefs, load_prefs

    path = tmp_path / "prefs.json"
    path.write_text(text, encoding="utf-8", errors="surrogatepass")
    before = path.read_bytes()
    loaded = load_prefs(path)
    assert loaded.prefs == Prefs() and "prefs.json" in loaded.problem
    kept = path if path.exists() else tmp_path / "prefs.json.damaged"
    assert kept.read_bytes() == before
    assert path.exists() == ("recent_files" in text)


def test_prefs_round_trip_atomically_and_keep_eight_recent_files(tmp_path):
    from app.ui.settings.prefs import Prefs, load_prefs, save_prefs

    prefs = Prefs()
    for n in range(10):
        prefs = prefs.with_recent(f"/f{n}.ngc")
    prefs = prefs.with_recent("/f3.ngc")
    save_prefs(tmp_path / "prefs.json", Prefs(prefs.recent_files, True))
    loaded = load_prefs(tmp_path / "prefs.json")
    assert loaded.problem == "" and loaded.prefs.dark is True
    assert loaded.prefs.recent_files == ("/f3.ngc", "/f9.ngc", "/f8.ngc", "/f7.ngc", "/f6.ngc", "/f5.ngc",
                                         "/f4.ngc", "/f2.ngc")
    assert [p.name for p in tmp_path.iterdir()] == ["prefs.json"]  # no temporary file left
