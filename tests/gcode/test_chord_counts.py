"""``chord_counts`` is sure of most arcs without an arctangent: its counts are still
those of the exact rule (``sweep`` and ``segments``, as ``chord_points`` draws them), at
every edge of that rule."""

import numpy as np
import pytest

from app.gcode.arcs import _one_chord, chord_counts, chord_points, in_plane, segments, sweep
from app.gcode.ops import PLANE_AXES


def exact_counts(start, end, center, axes, turn, tolerance):
    s, c, e, _ = in_plane(axes, start, center, end)
    r = np.maximum(np.hypot(*(s - c).T), np.hypot(*(e - c).T))
    return segments(r, sweep(s, e, c, turn), tolerance)


def hostile_arcs(n: int, seed: int, tolerance: float):
    """Arcs on every edge: sweeps at and around 0, a quarter, a half and a whole turn;
    middles that stray exactly the tolerance (and a hair either side); radii from 1e-9
    to 1e4; zero radii; ends off the circle (spirals); both ways round, extra turns; all
    three planes; helices."""
    rng = np.random.default_rng(seed)
    radius = 10.0 ** rng.uniform(-9, 4, n)
    edges = np.array([0.0, 1e-13, 1e-9, 1e-6, np.pi / 2, np.pi, 2 * np.pi - 1e-9, 2 * np.pi])
    angle = np.where(rng.random(n) < 0.4, rng.choice(edges, n) * (1 + rng.normal(0, 1e-12, n)),
                     rng.uniform(0, 2 * np.pi, n))
    at_edge = rng.random(n) < 0.3  # the tolerance is the middle's distance from the chord
    sagitta = radius * (1 - np.cos(np.minimum(angle, np.pi / 2) / 2))
    radius = np.where(at_edge & (sagitta > 0), tolerance / np.maximum(1 - np.cos(angle / 2), 1e-300)
                      * (1 + rng.choice([-1e-15, 0.0, 1e-15, 1e-9], n)), radius)
    radius[rng.random(n) < 0.02] = 0.0
    start_angle = rng.uniform(-np.pi, np.pi, n)
    turn = rng.choice([1, -1, 2, -2, 3], n, p=[0.45, 0.45, 0.04, 0.04, 0.02])
    signed = np.where(turn > 0, angle, -angle)
    center = rng.uniform(-200, 200, (n, 3))
    spiral = 1 + np.where(rng.random(n) < 0.2, rng.normal(0, 1e-3, n), 0.0)
    plane = rng.choice(3, n, p=[0.8, 0.1, 0.1])
    axes = np.take(PLANE_AXES, plane, axis=0)
    start, end = center.copy(), center.copy()
    idx = np.arange(n)
    for points, theta, r in ((start, start_angle, radius), (end, start_angle + signed, radius * spiral)):
        points[idx, axes[:, 0]] += r * np.cos(theta)
        points[idx, axes[:, 1]] += r * np.sin(theta)
    end[idx, axes[:, 2]] += rng.choice([0.0, 1.0], n)  # helices
    return start, end, center, axes, turn


@pytest.mark.parametrize("tolerance", [0.79, 0.138, 0.01, 1e-6])
@pytest.mark.parametrize("seed", [1, 2, 3])
def test_the_counts_are_the_exact_rule_s_at_every_edge(tolerance, seed):
    arcs = hostile_arcs(200_000, seed, tolerance)
    exact = exact_counts(*arcs, tolerance)
    np.testing.assert_array_equal(chord_counts(*arcs, tolerance), exact)
    start, end, center, axes, turn = arcs
    s, c, e, _ = in_plane(axes, start, center, end)
    sure = _one_chord(s, e, c, turn, tolerance)
    assert sure.sum() > 1000 and (exact[sure] == 1).all()  # the quick way is taken, and right
    assert ((exact == 1) & ~sure).any() and (exact > 1).any()  # and so is the exact one


def test_the_counts_are_the_points_chord_points_draws():
    arcs = hostile_arcs(20_000, 7, 0.05)
    few = exact_counts(*arcs, 0.05) <= 64  # (arcs of 1e4 mm at a whole turn have 10^5 chords)
    start, end, center, axes, turn = (column[few] for column in arcs)
    _, owner = chord_points(start, end, center, axes, turn, 0.05)
    np.testing.assert_array_equal(np.bincount(owner, minlength=len(start)),
                                  chord_counts(start, end, center, axes, turn, 0.05))
