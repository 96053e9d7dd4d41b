"""Bad operating points and parameters: ValueError naming the quantity, value, unit, index."""

from __future__ import annotations

import numpy as np
import pytest

import pinjoint

J = pinjoint.Joint()


@pytest.mark.parametrize(
    "load,speed,text",
    [
        (np.nan, 1.0, "load = NaN N"),
        (np.inf, 1.0, "load = inf N"),
        (0.0, 1.0, "load = 0.0 N"),
        (2e4, np.nan, "speed = NaN rad/s"),
        (2e4, -np.inf, "speed = -inf rad/s"),
        (1e308, 1.0, "load = 1e308 N is beyond the asperity model's capacity"),
    ],
)
def test_bad_point_is_a_value_error_with_value_and_unit(load, speed, text):
    with pytest.raises(ValueError) as e:
        J.evaluate(load, speed)
    assert text in str(e.value)


def test_negative_load_follows_the_library():
    # The library's rule decides (today: load must be > 0); the package adds nothing.
    import subprocess  # noqa: F401  (the CLI rejects it before the library sees it)
    try:
        got = J.evaluate(-2e4, 1.0)
    except ValueError as e:
        assert "load = -20000.0 N" in str(e)
    else:  # a library that takes |load|
        assert got["torque"] == J.evaluate(2e4, 1.0)["torque"]


def test_the_index_of_the_first_bad_point_in_c_order_is_named():
    loads = np.full((3, 4), 2e4)
    loads[2, 1] = -1.0
    loads[1, 3] = np.nan
    with pytest.raises(ValueError, match=r"^at index \(1, 3\): load = NaN N"):
        J.evaluate(loads, 1.0)
    # Also on the parallel path (many chunks): the lowest index, whatever the scheduling.
    big = np.full(50_000, 2e4)
    big[[49_000, 31_234, 40_000]] = 0.0
    with pytest.raises(ValueError, match=r"^at index 31234: load = 0.0 N"):
        J.evaluate(big, 0.5)


def test_negative_speed_is_its_magnitude():
    a, b = J.evaluate(2e4, -3.0), J.evaluate(2e4, 3.0)
    for k in pinjoint.RESULT_COLUMNS:
        assert a[k] == b[k], k


def test_parameter_errors_name_key_value_and_unit(tmp_path):
    with pytest.raises(ValueError, match=r"materials\.pin_elastic_modulus = -5 Pa is out of range"):
        pinjoint.Params({"materials.pin_elastic_modulus": -5})
    with pytest.raises(ValueError, match=r"lubricant\.viscosity = NaN|lubricant\.viscosity = nan"):
        pinjoint.Joint({"lubricant": {"viscosity": float("nan")}})
    with pytest.raises(ValueError, match=r"unknown parameter `geometry\.pin_radiuss`"):
        pinjoint.Params({"geometry.pin_radiuss": 0.02})
    with pytest.raises(ValueError, match=r"unknown parameter section `geometryy`"):
        pinjoint.Params({"geometryy": {"pin_radius": 0.02}})
    with pytest.raises(ValueError, match="geometry.bush_radius"):
        pinjoint.Params({"geometry.bush_radius": 0.028})
    with pytest.raises(TypeError, match="geometry.pin_radius"):
        pinjoint.Params({"geometry.pin_radius": "big"})
    with pytest.raises(TypeError, match="bool"):
        pinjoint.Params({"geometry.pin_radius": True})
    bad = tmp_path / "bad.toml"
    bad.write_text("[materials]\nbush_poisson_ratio = 0.5\n")
    with pytest.raises(ValueError, match=r"bad\.toml: parameter materials\.bush_poisson_ratio = 0\.5"):
        pinjoint.Joint(str(bad))
    with pytest.raises(OSError, match="missing.toml"):
        pinjoint.Params.from_toml(tmp_path / "missing.toml")


def test_fidelity_and_tolerance_errors():
    with pytest.raises(ValueError, match="fidelity"):
        pinjoint.Joint(fidelity="fast")
    with pytest.raises(ValueError, match="tolerance"):
        pinjoint.Joint(fidelity="table", tolerance=-1.0)
    with pytest.raises(ValueError, match="load"):
        pinjoint.Joint(fidelity="table", envelope=(6e4, 5e3, 0.01, 10.0))


def test_cycle_errors_name_parameter_value_and_unit():
    with pytest.raises(ValueError, match=r"rig\.frequency = -1 Hz|frequency"):
        pinjoint.simulate_cycle(-1.0, 0.7, 2e4, cycles=1, samples_per_cycle=50)
    with pytest.raises(ValueError, match=r"load = 0\.0 N"):
        pinjoint.simulate_cycle(1.0, 0.7, 0.0, cycles=1, samples_per_cycle=50)
    with pytest.raises(ValueError, match="rig.inertia"):
        pinjoint.simulate_cycle(1.0, 0.7, 2e4, cycles=1, samples_per_cycle=50, inertia=-1.0)
    with pytest.raises(ValueError, match=r"unknown parameter `rig\.intertia`"):
        pinjoint.simulate_cycle(1.0, 0.7, 2e4, cycles=1, samples_per_cycle=50, intertia=1.0)
    with pytest.raises(ValueError, match="cycles = 0"):
        pinjoint.simulate_cycle(1.0, 0.7, 2e4, cycles=0)
    with pytest.raises(ValueError, match="samples_per_cycle = 4"):
        pinjoint.simulate_cycle(1.0, 0.7, 2e4, cycles=1, samples_per_cycle=4)


def test_params_round_trip_and_defaults():
    p = pinjoint.default_params()
    assert p == pinjoint.Params() and hash(p) == hash(pinjoint.Params())
    assert p["friction.boundary_friction_coefficient"] == 0.12
    assert pinjoint.Params.from_toml_str(p.to_toml()) == p
    q = p.with_values({"friction.boundary_friction_coefficient": 0.1})
    assert q != p and q["friction.boundary_friction_coefficient"] == 0.1
    assert pinjoint.Params(q.to_dict()) == q
    assert len(pinjoint.param_table()) == len(p) == len(pinjoint.Params.keys())
    names = {r["name"] for r in pinjoint.param_table()}
    assert names == set(pinjoint.Params.keys())
