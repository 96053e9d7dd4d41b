"""Issue 37 item 5 through the Python package: past the model's assumptions (the Hertz
half-width of eq. 6 beyond the pin radius, a temperature above
grease.upper_service_temperature) the validity is "outside", never "extrapolation"; the
answer is continuous across each edge; `Joint.load_edge` is the declared load capacity; the
package agrees with the command line."""

from __future__ import annotations

import json
import math
import subprocess

import numpy as np

import pinjoint

# Table 1, independently of the package: E', R' and the load at which a = R.
E_EFF = 2.0 / ((1 - 0.28**2) / 205e9 + (1 - 0.34**2) / 117e9)
R_RED = 0.028 * 0.028025 / 0.000025
LOAD_EDGE = math.pi * E_EFF * 0.0594 * 0.028**2 / (8 * R_RED)


def half_width(load, r_red=R_RED, e_eff=E_EFF, b=0.0594):
    return np.sqrt(8 * np.abs(load) * r_red / (math.pi * e_eff * b))


def test_the_declared_capacity_is_the_load_edge():
    j = pinjoint.Joint()
    assert abs(j.load_edge / LOAD_EDGE - 1) < 1e-12
    assert abs(half_width(j.load_edge) / 0.028 - 1) < 1e-12
    assert j.capacity > 1e3 * j.load_edge  # the refusal: the asperity model's limit
    assert pinjoint.VALIDITIES == ["checked", "extrapolation", "known-wrong", "outside"]


def test_past_each_edge_is_outside_and_inside_is_unchanged():
    rng = np.random.default_rng(37)
    load = np.concatenate([np.exp(rng.uniform(np.log(1e3), np.log(1e7), 400)), [LOAD_EDGE, np.nextafter(LOAD_EDGE, 1e9)]])
    speed = np.exp(rng.uniform(np.log(1e-3), np.log(30.0), load.size)) * rng.choice([-1.0, 1.0], load.size)
    for paper in (False, True):
        base = pinjoint.Joint({"model.paper": paper})
        for t in (250.0, 293.15, 394.15, np.nextafter(394.15, 1e9), 450.0, 673.15):
            if paper and t < 238.15:
                continue
            out = base.at_temperature(float(t)).evaluate(load, speed, errors="nan")
            v = out["validity"]
            # Away from the edge by more than rounding, the half-width decides by itself.
            past = (half_width(load) > 0.028 * (1 + 1e-9)) | (t > 394.15)
            inside = (half_width(load) < 0.028 * (1 - 1e-9)) & (t <= 394.15)
            answered = v != "refused"
            assert np.all(v[past & answered] == "outside"), (paper, t)
            assert not np.any(v[inside] == "outside"), (paper, t)
            # On the edge itself: inside; one ulp beyond: outside.
            j = base.at_temperature(float(t))
            on = j.evaluate([j.load_edge, np.nextafter(j.load_edge, 1e9)], 0.5)["validity"]
            assert (on[0] == "outside") == (t > 394.15) and on[1] == "outside", (paper, t, on)
            assert np.all(np.isfinite(out["torque"][past & answered]))
            # Only the flag: a point just past the load edge is the one just inside.
            edge = base.at_temperature(float(t)).evaluate([LOAD_EDGE * (1 - 1e-9), LOAD_EDGE * (1 + 1e-9)], 0.5)
            assert abs(edge["torque"][1] / edge["torque"][0] - 1) < 1e-6
            assert edge["validity"][1] == "outside" and (edge["validity"][0] != "outside" or t > 394.15)


def test_the_upper_service_temperature_is_a_parameter():
    j = pinjoint.Joint({"grease.upper_service_temperature": 330.0})
    assert str(j.at_temperature(330.0).evaluate(20e3, 1.0)["validity"]) == "extrapolation"
    assert str(j.at_temperature(330.5).evaluate(20e3, 1.0)["validity"]) == "outside"
    a = j.at_temperature(330.0 - 1e-6).evaluate(20e3, 1.0)["torque"]
    b = j.at_temperature(330.0 + 1e-6).evaluate(20e3, 1.0)["torque"]
    assert abs(float(b) / float(a) - 1) < 1e-6


def test_the_package_agrees_with_the_command_line(cli):
    j = pinjoint.Joint()
    for load, t in [(20e3, 400.0), (2e5, 293.15), (LOAD_EDGE, 293.15), (60e3, 394.15)]:
        o = subprocess.run([str(cli), "point", f"--load={load!r}", "--speed=0.5", f"--temperature={t!r}", "--json"],
                           check=True, capture_output=True, text=True)
        m = json.loads(o.stdout)
        out = j.at_temperature(t).evaluate(load, 0.5)
        assert m["validity"] == str(out["validity"]), (load, t)
        assert m["torque"] == float(out["torque"]), (load, t)
