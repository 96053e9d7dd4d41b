"""The package's numbers equal the Rust library's, through the `pinjoint` CLI, bit for bit."""

from __future__ import annotations

import numpy as np
import pytest

import pinjoint
from conftest import inside_film_bound

# Loads from 1 N to 1e8 N and speeds from rest to 1e4 rad/s, both directions: every regime.
LOADS = np.array([1.0, 37.5, 1e3, 5e3, 2e4, 6e4, 2.5e5, 1e8])
SPEEDS = np.array([0.0, 1e-12, -1e-9, 1e-4, 0.05, -0.2, 1.0, 4.39, 6.0, -30.0, 100.0, 800.0, 1e4])


def grid(joint=None):
    """The (load, speed) pairs the model answers (a film beyond the diametral clearance is a
    ValueError, docs/conventions.md: 1 N from 1e-4 rad/s, 20 kN from about 500 rad/s)."""
    l, w = np.meshgrid(LOADS, SPEEDS, indexing="ij")
    l, w = l.ravel(), w.ravel()
    keep = inside_film_bound(joint or pinjoint.Joint(), l, w)
    assert keep.sum() > 60, keep.sum()
    return l[keep], w[keep]


def assert_same(ours, ref, columns=pinjoint.RESULT_COLUMNS):
    for c in columns:
        a, b = np.asarray(ours[c]), np.asarray(ref[c])
        if a.dtype.kind == "f":
            # Bit for bit: same float64 values, not merely close.
            assert np.array_equal(a.view(np.int64), b.astype(np.float64).view(np.int64)), (c, a, b)
        else:
            assert list(a) == list(b), c


def test_every_regime_equals_the_cli_sweep_bit_for_bit(sweep):
    l, w = grid()
    ours = pinjoint.Joint().evaluate(l, w)
    ref = sweep(l, w)
    assert set(ours["regime"]) == {"boundary", "mixed", "full-film"}
    assert_same(ours, ref)
    assert np.array_equal(ours["load"], l) and np.array_equal(ours["speed"], w)


def test_parallel_path_equals_the_cli(sweep):
    # Above the serial threshold: rayon chunks; still bit for bit and in order.
    rng = np.random.default_rng(7)
    l = np.exp(rng.uniform(np.log(1e3), np.log(1e5), 9000))
    w = rng.choice([-1, 1], 9000) * np.exp(rng.uniform(np.log(1e-4), np.log(1e3), 9000))
    keep = inside_film_bound(pinjoint.Joint(), l, w)
    l, w = l[keep], w[keep]
    assert_same(pinjoint.Joint().evaluate(l, w), sweep(l, w))


def test_parameter_file_dict_and_params_agree_with_the_cli(sweep, tmp_path):
    toml = tmp_path / "joint.toml"
    toml.write_text(
        "[friction]\nboundary_friction_coefficient = 0.1\n[lubricant]\nviscosity = 0.05\n"
        "[surface]\nbush_rms_roughness = 2e-6\n"
    )
    l, w = grid(pinjoint.Joint(str(toml)))
    ref = sweep(l, w, "--params", str(toml))
    from_path = pinjoint.Joint(str(toml)).evaluate(l, w)
    from_dict = pinjoint.Joint(
        {"friction": {"boundary_friction_coefficient": 0.1}, "lubricant.viscosity": 0.05, "surface.bush_rms_roughness": 2e-6}
    ).evaluate(l, w)
    assert_same(from_path, ref)
    assert_same(from_dict, ref)


@pytest.mark.parametrize("level", ["table", "boundary", "auto"])
def test_fidelity_levels_equal_the_cli_inside_the_envelope(sweep, level):
    rng = np.random.default_rng(3)
    l = rng.uniform(5e3, 6e4, 300)
    w = rng.uniform(0.05, 10.0, 300) * rng.choice([-1, 1], 300)
    env = (5e3, 6e4, 0.01, 10.0)
    joint = pinjoint.Joint(fidelity=level, tolerance=1e-3, envelope=env)
    ours = joint.evaluate(l, w)
    ref = sweep(l, w, "--fidelity", level, "--tolerance", "1e-3", "--envelope-load", "5000:60000", "--envelope-speed", "0.01:10")
    assert_same(ours, ref)
    assert joint.fallbacks == 0
    # Outside the envelope: the complete solve, as at full.
    out = joint.evaluate([1e3, 2e4], [1.0, 100.0])
    full = pinjoint.Joint().evaluate([1e3, 2e4], [1.0, 100.0])
    assert_same(out, full)
    assert joint.fallbacks == 2


def test_cycle_equals_the_cli_cycle_csv_bit_for_bit(cycle_cli):
    ref = cycle_cli("--frequency", "1", "--amplitude", "40", "--load", "20000", "--cycles", "2", "--samples-per-cycle", "400")
    ours = pinjoint.simulate_cycle(1.0, np.radians(40.0), 20e3, cycles=2, samples_per_cycle=400)
    assert list(ours) == list(pinjoint.CYCLE_COLUMNS) == list(ref)
    for c in pinjoint.CYCLE_COLUMNS[:-1]:
        assert np.array_equal(ours[c].view(np.int64), ref[c].view(np.int64)), c
    assert np.array_equal(ours["stuck"], ref["stuck"] == 1)
    assert ours["stuck"].any() and not ours["stuck"].all()


def test_cycle_with_a_rig_file_and_overrides_equals_the_cli(cycle_cli, tmp_path):
    toml = tmp_path / "rig.toml"
    toml.write_text("[friction]\nboundary_friction_coefficient = 0.11\n[rig]\ninertia = 0.08\nmethod = \"dop853\"\n")
    ref = cycle_cli(
        "--params", str(toml), "--frequency", "0.3", "--amplitude", "30", "--load", "40000", "--cycles", "1",
        "--samples-per-cycle", "300", "--formulation", "regularised",
    )
    ours = pinjoint.simulate_cycle(
        0.3, np.radians(30.0), 40e3, cycles=1, samples_per_cycle=300, params=toml, formulation="regularised"
    )
    for c in pinjoint.CYCLE_COLUMNS[:-1]:
        assert np.array_equal(ours[c].view(np.int64), ref[c].view(np.int64)), c


def test_cycle_at_table_fidelity_equals_the_cli(cycle_cli):
    ref = cycle_cli("--frequency", "1", "--amplitude", "40", "--load", "20000", "--cycles", "1", "--samples-per-cycle", "200",
                    "--fidelity", "table", "--tolerance", "1e-4")
    ours = pinjoint.simulate_cycle(1.0, np.radians(40.0), 20e3, cycles=1, samples_per_cycle=200, fidelity="table")
    for c in pinjoint.CYCLE_COLUMNS[:-1]:
        assert np.array_equal(ours[c].view(np.int64), ref[c].view(np.int64)), c
