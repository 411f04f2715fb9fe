"""The machine profile: defaults of DESIGN.md, overrides, and clear errors."""

import pytest

from app.profile import MachineProfile, ProfileError, load_profile


def test_defaults_match_the_design():
    p = MachineProfile()
    assert p.axis.counts_per_rev == 1980
    assert p.axis.mm_per_count == pytest.approx(8 / 1980)
    assert p.axis.max_speed_mm_s == pytest.approx(130 * 8 / 60)
    assert p.travel.limits() == ((0, 150), (0, 150), (0, 30))
    assert p.travel.work_offset() == (0, 0, 20)


def test_shipped_profile_equals_the_defaults():
    assert load_profile("resources/machine.toml") == MachineProfile()


def test_override_from_toml_and_json(tmp_path):
    toml = tmp_path / "m.toml"
    toml.write_text("[axis]\nlead_mm = 4\n[pid]\nkp = 2.5\n")
    p = load_profile(toml)
    assert (p.axis.lead_mm, p.pid.kp) == (4.0, 2.5)
    js = tmp_path / "m.json"
    js.write_text('{"travel": {"x_max": 200}}')
    assert load_profile(js).travel.x_max == 200


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("[axis]\nlead_mm = -1\n", r"\[axis\]: lead_mm = -1 is out of range 0.5..50"),
        ("[axis]\nlead = 4\n", "unknown setting 'lead'"),
        ("[wheels]\nn = 4\n", "unknown section 'wheels'"),
        ("[axis]\nlead_mm = 'x'\n", "is not a number"),
        ("[axis\n", "not valid TOML"),
    ],
)
def test_bad_profiles_name_file_key_and_range(tmp_path, text, message):
    path = tmp_path / "bad.toml"
    path.write_text(text)
    with pytest.raises(ProfileError, match=message):
        load_profile(path)
