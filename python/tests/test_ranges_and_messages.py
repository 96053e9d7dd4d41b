"""Issue 23 through the Python package: the declared box's corners answer inside the model's
invariants or raise ValueError naming the quantity (item 1); huge inputs give short messages
and the documented exception type (item 3); the load is a magnitude as the docstrings say
(item 4, docs/conventions.md)."""

from __future__ import annotations

import re

import numpy as np
import pytest

import pinjoint

MESSAGE_CHARS = 1000  # pinjoint_numfmt::MESSAGE_CHARS
T_MIN, T_MAX = 218.15, 673.15  # the declared temperature range (K; the paper's model from 238.15 K)


def invariants(p: pinjoint.Params, out: dict, load: float, slack: float) -> None:
    d = p.to_dict()
    mu_c = d["friction"]["boundary_friction_coefficient"]
    lub = d["lubricant"]
    r, rb = d["geometry"]["pin_radius"], d["geometry"]["bush_radius"]
    mu, pm = float(out["friction_coefficient"]), float(out["mean_pressure"])
    # The complete model adds the lubricant's torque in the clearance (zero with model.paper):
    # the contact's part of mu keeps the paper's bound.
    clearance = float(out["clearance_torque"])
    assert clearance >= 0.0
    # The journal's pressure-flow torque adds at most (c/2)·P, i.e. c/(2R) to mu.
    mu_max = mu_c + (lub["limiting_shear_stress"] + lub["limiting_shear_stress_slope"] * pm) / pm + (rb - r) / (2 * r)
    for k in pinjoint.RESULT_COLUMNS:
        if k not in ("regime", "validity"):  # the two named (string) columns
            assert np.isfinite(out[k]), (k, out)
    assert str(out["validity"]) in pinjoint.VALIDITIES, out["validity"]
    assert 0 <= mu <= (mu_max + clearance / (r * abs(load))) * (1 + slack) * (1 + 1e-12), (mu, mu_max, clearance)
    assert abs(float(out["torque"])) <= (mu_max * r * abs(load) + clearance) * (1 + slack) * (1 + 1e-12)
    for k in ("fluid_load_fraction", "asperity_load_fraction"):
        assert -slack <= float(out[k]) <= 1 + slack, out[k]
    h = float(out["film_thickness"])
    assert h > 0
    assert h <= 2 * (rb - r) * (1 + 1e-12) or float(out["fluid_load_fraction"]) < 0.01, (h, rb - r)


def ends(rng: str):
    """The ends of a declared range as param_table() writes it ("> 0", ">= 0", "in [a, b)",
    "in (a, b]", "in [a, b]"): the bounds it includes, points next to those it excludes."""
    if rng == "> 0":
        return [1e-300, 1e300]
    if rng == ">= 0":
        return [0.0, 1e300]
    m = re.fullmatch(r"in ([\[(])([^,]+), ([^\])]+)([\])])", rng)
    assert m, rng
    lo, hi = float(m.group(2)), float(m.group(3))
    eps = (hi - lo) * 1e-9
    return [lo if m.group(1) == "[" else lo + eps, hi if m.group(4) == "]" else hi - eps]


def corner_sets():
    """Each parameter at each end of its declared range, one at a time."""
    for row in pinjoint.param_table():
        if row["name"] in ("model.paper", "grease.enabled"):  # the two switches (bools)
            yield from ((row["name"], b) for b in (False, True))
            continue
        for v in ends(row["range"]):
            yield row["name"], v


def test_param_table_states_the_declared_ranges():
    rows = {r["name"]: r for r in pinjoint.param_table()}
    assert rows["lubricant.temperature"]["range"] == "in [218.15, 673.15]"
    assert rows["lubricant.viscosity"]["range"] == "in (0, 1000000000000]"
    assert all(ends(r["range"]) for r in rows.values())


@pytest.mark.parametrize("fidelity", ["full", "auto"])
def test_declared_corners_answer_inside_the_invariants_or_raise_a_named_value_error(fidelity):
    answered = tried = 0
    for name, v in corner_sets():
        try:
            p = pinjoint.Params({name: v})
        except ValueError as e:
            assert len(str(e)) <= MESSAGE_CHARS and " = " in str(e), str(e)
            continue
        for load, speed in ((2e4, 0.2), (-6e4, -1.0), (1.0, 1.0)):
            tried += 1
            try:
                j = pinjoint.Joint(p, fidelity=fidelity, tolerance=1e-3) if fidelity != "full" else pinjoint.Joint(p)
                out = j.evaluate(load, speed)
            except ValueError as e:
                assert len(str(e)) <= MESSAGE_CHARS and " = " in str(e), str(e)
                continue
            invariants(p, out, load, 1e-12 if fidelity == "full" else 1e-3)
            answered += 1
    assert answered * 2 > tried, (answered, tried)


@pytest.mark.parametrize("t", [T_MIN, T_MAX, 0.5 * (T_MIN + T_MAX)])
def test_the_temperature_range_is_closed_and_answers(t):
    p = pinjoint.Params({"lubricant.temperature": t})
    invariants(p, pinjoint.Joint(p).evaluate(2e4, 0.2), 2e4, 1e-12)


def test_the_reported_cold_point_is_refused_naming_the_temperature():
    with pytest.raises(ValueError, match=r"lubricant\.temperature = 145(\.0)? K.*\[218\.15, 673\.15\]"):
        pinjoint.Params({"lubricant.temperature": 145.0})


def test_a_film_beyond_the_clearance_is_a_value_error_naming_it():
    with pytest.raises(ValueError, match=r"film_thickness = .* diametral clearance"):
        pinjoint.Joint({"model.paper": True}).evaluate(1.0, 1.0)
    # The complete model (default) answers it: the journal bearing carries the light load.
    assert float(pinjoint.Joint().evaluate(1.0, 1.0)["torque"]) > 0.0


def test_huge_toml_gives_a_short_value_error(tmp_path):
    junk = "x" * 10_000_000
    path = tmp_path / "junk.toml"
    path.write_text(junk + "\n")
    for call in (lambda: pinjoint.Params.from_toml(path), lambda: pinjoint.Params.from_toml_str(junk),
                 lambda: pinjoint.Params.from_toml_str("[geometry]\n" + junk + " = 1.0\n"),
                 lambda: pinjoint.Params.from_toml_str('[geometry]\npin_radius = "' + junk + '"\n')):
        with pytest.raises(ValueError) as e:
            call()
        assert len(str(e.value)) <= MESSAGE_CHARS, len(str(e.value))
        assert "line " in str(e.value)


@pytest.mark.parametrize("value", [10**400, -(10**400), 2**1024])
def test_an_int_beyond_float_is_a_value_error_naming_the_key(value):
    with pytest.raises(ValueError) as e:
        pinjoint.Params({"geometry.pin_radius": value})
    m = str(e.value)
    assert "geometry.pin_radius" in m and "digits" in m and len(m) <= MESSAGE_CHARS, m


def test_huge_keys_and_values_are_cut():
    big = "k" * 1_000_000
    for call, kind in ((lambda: pinjoint.Params({"geometry." + big: 1.0}), ValueError),
                       (lambda: pinjoint.Params({big: 1.0}), ValueError),
                       (lambda: pinjoint.Params({"geometry.pin_radius": big}), TypeError),
                       (lambda: pinjoint.Joint(fidelity=big), ValueError),
                       (lambda: pinjoint.simulate_cycle(1.0, 0.5, 2e4, cycles=big), TypeError)):
        with pytest.raises(kind) as e:
            call()
        assert len(str(e.value)) <= MESSAGE_CHARS, (kind, len(str(e.value)))


def test_the_load_is_a_magnitude_as_the_docstrings_say():
    assert "a negative value is taken as |load|" in pinjoint.Joint.evaluate.__doc__
    assert "a negative value is taken as |P|" in pinjoint.simulate_cycle.__doc__
    j = pinjoint.Joint()
    a, b = j.evaluate(2e4, 0.3), j.evaluate(-2e4, 0.3)
    for k in pinjoint.RESULT_COLUMNS:
        assert a[k] == b[k], k
    with pytest.raises(ValueError, match="load = 0"):
        j.evaluate(0.0, 0.3)
    c = pinjoint.simulate_cycle(1.0, 0.3, 2e4, cycles=1, samples_per_cycle=16)
    d = pinjoint.simulate_cycle(1.0, 0.3, -2e4, cycles=1, samples_per_cycle=16)
    assert np.array_equal(c["torque"], d["torque"])
