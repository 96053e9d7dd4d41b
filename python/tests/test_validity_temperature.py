"""The `validity` field of the results and `Joint.at_temperature`: the envelope at each of its
boundaries and on both sides, over random points; a moved joint bit for bit a fresh one at
that temperature (full and a table level); bad temperatures refused by name."""

from __future__ import annotations

import math

import numpy as np
import pytest

import pinjoint

# The envelope as docs/validity.md states it (not read from the package).
LOAD = (5e3, 60e3)
U_MAX = 2.0 * math.pi * 1.0 * math.radians(40.0) * 0.028
TEMP = (288.15, 298.15)
COLD = 273.15
# The model's assumptions (docs/validity.md, "Past the model's assumptions"): the load at which
# the Hertz half-width of eq. 6 reaches the pin radius, pi E' B R^2/(8 R') for Table 1, and the
# default grease's upper service temperature (MIL-PRF-23827 Type I, +121 C).
E_EFF = 2.0 / ((1 - 0.28**2) / 205e9 + (1 - 0.34**2) / 117e9)
R_RED = 0.028 * 0.028025 / 0.000025
LOAD_EDGE = math.pi * E_EFF * 0.0594 * 0.028**2 / (8 * R_RED)
T_MAX = 394.15


def expected(load, speed, t, paper=False):
    """The envelope's name; below 0 C known-wrong for the paper's model only (the complete
    model, the default, is an extrapolation there); past the model's assumptions outside."""
    u = np.abs(speed) * 0.028
    load = np.abs(load)
    ok = (load >= LOAD[0]) & (load <= LOAD[1]) & (u <= U_MAX) & (t >= TEMP[0]) & (t <= TEMP[1])
    out = np.where(ok, "checked", "extrapolation").astype(object)
    if paper:
        out[np.broadcast_to(t < COLD, out.shape)] = "known-wrong"
    out[np.broadcast_to((load > LOAD_EDGE) | (t > T_MAX), out.shape)] = "outside"
    return out


def joint_at(t, **kw):
    return pinjoint.Joint(pinjoint.Params({"lubricant.temperature": t}), **kw)


def test_every_boundary_and_both_sides():
    w_max = U_MAX / 0.028
    cases = [
        (5e3, 1.0, 293.15, "checked"),
        (np.nextafter(5e3, 0), 1.0, 293.15, "extrapolation"),
        (60e3, -1.0, 293.15, "checked"),
        (np.nextafter(60e3, 1e9), -1.0, 293.15, "extrapolation"),
        (20e3, 0.0, 293.15, "checked"),
        (20e3, w_max * (1 - 1e-12), 293.15, "checked"),
        (20e3, w_max * (1 + 1e-12), 293.15, "extrapolation"),
        (20e3, 0.5, 288.15, "checked"),
        (20e3, 0.5, np.nextafter(288.15, 0), "extrapolation"),
        (20e3, 0.5, 298.15, "checked"),
        (20e3, 0.5, np.nextafter(298.15, 1e9), "extrapolation"),
        (20e3, 0.5, 273.15, "extrapolation"),
        (20e3, 0.5, np.nextafter(273.15, 0), "extrapolation"),
    ]
    base = pinjoint.Joint()
    for load, w, t, want in cases:
        for j in (joint_at(t), base.at_temperature(t)):
            assert str(j.evaluate(load, w)["validity"]) == want, (load, w, t)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_random_points_and_temperatures(seed):
    rng = np.random.default_rng(seed)
    base = pinjoint.Joint()
    # Inside the declared temperature range and the film-clearance bound (docs/conventions.md);
    # loads and temperatures on both sides of the model's assumptions (outside above 96.7 kN
    # and 394.15 K).
    for t in np.concatenate([rng.uniform(250.0, 400.0, 4), [293.15, 272.0, 394.15, 394.16]]):
        load = np.exp(rng.uniform(np.log(5e3), np.log(2e5), 300))
        speed = np.exp(rng.uniform(np.log(1e-4), np.log(3.0), 300)) * rng.choice([-1.0, 1.0], 300)
        moved = base.at_temperature(float(t))
        fresh = joint_at(float(t))
        a, b = moved.evaluate(load, speed), fresh.evaluate(load, speed)
        assert list(a) == list(b)
        for k in a:
            if a[k].dtype.kind == "f":
                assert np.array_equal(a[k].view(np.uint64), b[k].view(np.uint64)), (t, k)
            else:
                assert np.array_equal(a[k], b[k]), (t, k)
        assert np.array_equal(a["validity"], expected(load, speed, t))
        assert moved.params == fresh.params
        base = moved  # the next temperature is reached from this one


def test_table_level_moves_with_the_temperature():
    # An envelope whose table margins stay inside the film bound at 250 K.
    env = (10e3, 60e3, 0.01, 1.0)
    j = pinjoint.Joint(fidelity="table", tolerance=1e-3, envelope=env)
    rng = np.random.default_rng(7)
    load = rng.uniform(10e3, 60e3, 200)
    speed = np.exp(rng.uniform(np.log(0.01), np.log(1.0), 200))
    for t in (250.0, 320.0):
        moved = j.at_temperature(t)
        fresh = joint_at(t, fidelity="table", tolerance=1e-3, envelope=env)
        assert moved.level == fresh.level and moved.error_bound == fresh.error_bound
        a, b = moved.evaluate(load, speed), fresh.evaluate(load, speed)
        assert np.array_equal(a["friction_coefficient"], b["friction_coefficient"])
        full = joint_at(t).evaluate(load, speed)["friction_coefficient"]
        assert np.max(np.abs(a["friction_coefficient"] / full - 1.0)) <= 1e-3


@pytest.mark.parametrize("bad", [0.0, -1.0, float("nan"), float("inf"), -float("inf"), 138.15, 673.16])
def test_bad_temperatures_are_refused_by_name(bad):
    with pytest.raises(ValueError, match="lubricant.temperature"):
        pinjoint.Joint().at_temperature(bad)


def test_cold_soak_is_known_wrong_and_low_only_for_the_paper_model():
    paper = {"model.paper": True}
    warm = pinjoint.Joint(paper).evaluate(20e3, 0.21)
    cold = pinjoint.Joint(paper).at_temperature(238.15).evaluate(20e3, 0.21)  # -35 C, the paper model's floor
    assert str(warm["validity"]) == "checked" and str(cold["validity"]) == "known-wrong"
    assert float(cold["friction_coefficient"]) < 0.6 * float(warm["friction_coefficient"])  # 0.062 against 0.119
    # The complete model (default): an extrapolation, and stiffer, down to -55 C.
    warm = pinjoint.Joint().evaluate(20e3, 0.21)
    for t in (238.15, 218.15):
        cold = pinjoint.Joint().at_temperature(t).evaluate(20e3, 0.21)
        assert str(cold["validity"]) == "extrapolation"
        assert float(cold["friction_coefficient"]) > float(warm["friction_coefficient"])
    assert pinjoint.VALIDITIES == ["checked", "extrapolation", "known-wrong", "outside"]
