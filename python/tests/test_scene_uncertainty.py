"""pinjoint.scenes and examples/scene_uncertainty.py: the free-fall scene on PreslidingBatch
against an independent scalar loop, the lock margin against eq. 11 at rest, the sampling of
a calibration's covariance, and the uncertainty study reproducible from its seed and equal on
a 2-worker LocalCluster and locally, file for file."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import pinjoint
from pinjoint import scenes

from conftest import load_example

ROOT = Path(__file__).resolve().parents[2]
MU = pinjoint.MU_C


def scalar_free_fall(scene, mu_c):
    """The scene's equations for one leg, in plain Python floats with a pinjoint.Presliding
    trunnion joint (written independently of pinjoint.scenes): the host's inertia on each pin
    J / trunnion_joints, each commit with the step h."""
    s = scene
    joint = pinjoint.Presliding(pinjoint.Params({MU: mu_c}), angle=s.up_angle, host_inertia=s.inertia / s.trunnion_joints)
    phi, w, a, energy = s.up_angle, 0.0, 0.0, 0.0
    for k in range(int(round(s.end_time / s.step))):
        ax = s.cg_distance * (a * math.cos(phi) - w * w * math.sin(phi))
        ay = s.cg_distance * (a * math.sin(phi) + w * w * math.cos(phi))
        load = s.trunnion_load_share * math.hypot(s.leg_mass * ax, s.leg_mass * ay + s.leg_mass * s.gravity)
        tf = s.trunnion_joints * joint.torque(phi, w, load)
        joint.commit(phi, w, load, step=s.step)
        total = -s.leg_mass * s.gravity * s.cg_distance * math.sin(phi) - s.damper_linear * w - s.damper_quadratic * w * abs(w)
        total += (-s.lock_spring_torque if phi < s.lock_spring_angle else 0.0) + tf
        a = total / s.inertia
        w_new = w + s.step * a
        phi_new = phi + s.step * w_new
        if phi_new <= 0:
            energy += tf * phi
            return k * s.step + s.step * phi / (phi - phi_new), abs(w_new), energy
        energy += -tf * (phi_new - phi)
        phi, w = phi_new, w_new
    return math.inf, math.nan, energy


def test_the_scene_equals_an_independent_scalar_loop():
    scene = scenes.FreeFall(end_time=2.5)
    mu = np.array([0.09, 0.12, 0.15])
    out = scenes.free_fall(3, scene, per_joint={MU: mu})
    for i, m in enumerate(mu):
        t, w, e = scalar_free_fall(scene, float(m))
        # NumPy's and the math module's sin/cos may differ in the last bit: compare to 1e-9.
        assert out["time_to_lock"][i] == pytest.approx(t, rel=1e-9)
        assert out["speed_at_lock"][i] == pytest.approx(w, rel=1e-9)
        assert out["friction_energy"][i] == pytest.approx(e, rel=1e-7)
    assert out["locked"].all()
    # The friction slows the fall: more friction, a later lock and more energy dissipated.
    assert np.all(np.diff(out["time_to_lock"]) > 0) and np.all(np.diff(out["friction_energy"]) > 0)


def test_not_locked_by_the_end_time_is_inf():
    out = scenes.free_fall(2, scenes.FreeFall(end_time=0.5))
    assert np.all(np.isinf(out["time_to_lock"])) and np.all(np.isnan(out["speed_at_lock"])) and not out["locked"].any()


@pytest.mark.skipif("grease.yield_stress" in pinjoint.Params.keys(), reason="with a grease model the breakaway adds its yield torque")
def test_lock_margin_is_eq_11_at_rest():
    # At rest mu = mu_c exactly (docs/model.md, limits): T_break = mu_c R P.
    mu = np.array([0.08, 0.12, 0.16])
    scene = scenes.FreeFall(end_time=0.01)
    out = scenes.free_fall(3, scene, per_joint={MU: mu})
    r = pinjoint.default_params()["geometry.pin_radius"]
    want = scene.lock_link_torque / (scene.lock_link_pivots * mu * r * scene.lock_link_load) - 1
    assert np.allclose(out["lock_margin"], want, rtol=1e-14)


def test_a_calibrations_covariance_is_sampled():
    fit = {
        "parameters": {MU: {"value": 0.11, "standard_error": 0.004}, "lubricant.viscosity": {"value": 0.012, "standard_error": 0.001}},
        "correlation_keys": ["lubricant.viscosity", MU, "torque_offset"],
        "correlation": [[1.0, -0.6, 0.1], [-0.6, 1.0, 0.0], [0.1, 0.0, 1.0]],
    }
    s = scenes.sample_parameters(20000, 4, calibration=fit)
    assert list(s) == [MU, "lubricant.viscosity"]
    x = np.stack([s[MU], s["lubricant.viscosity"]])
    n = x.shape[1]
    assert abs(x[0].mean() - 0.11) < 5 * 0.004 / math.sqrt(n)
    assert abs(x[1].mean() - 0.012) < 5 * 0.001 / math.sqrt(n)
    assert x[0].std() == pytest.approx(0.004, rel=0.03) and x[1].std() == pytest.approx(0.001, rel=0.03)
    assert np.corrcoef(x)[0, 1] == pytest.approx(-0.6, abs=0.03)
    again = scenes.sample_parameters(20000, 4, calibration=fit)
    assert all(np.array_equal(s[k], again[k]) for k in s)
    # A distribution by name for any key, on top.
    d = scenes.sample_parameters(5000, 1, distributions={"geometry.bush_length": "uniform:0.05,0.06", MU: ("normal", 0.12, 0.01)})
    assert d["geometry.bush_length"].min() >= 0.05 and d["geometry.bush_length"].max() < 0.06
    with pytest.raises(ValueError, match="not a parameter key"):
        scenes.sample_parameters(3, 1, distributions={"nope.key": "normal:1,1"})
    with pytest.raises(ValueError, match="is not KEY=KIND:A,B"):
        scenes.parse_distribution("friction.boundary_friction_coefficient=gamma:1,2")


def test_the_study_is_reproducible_and_equal_on_a_local_cluster(tmp_path, monkeypatch):
    monkeypatch.syspath_prepend(str(ROOT / "examples"))
    monkeypatch.setenv("PYTHONPATH", str(ROOT / "examples"))
    ex = load_example("scene_uncertainty")
    small = ["--samples", "200", "--chunk", "50", "--end-time", "2.5", "--temperature-c", "-20", "--seed", "7"]
    assert ex.main([*small, "--output", str(tmp_path / "a")]) == 0
    assert ex.main([*small, "--no-figure", "--output", str(tmp_path / "b")]) == 0
    assert ex.main([*small, "--no-figure", "--workers", "2", "--output", str(tmp_path / "dask")]) == 0
    for name in ("samples.csv", "summary.txt"):
        a = (tmp_path / "a" / name).read_bytes()
        assert a == (tmp_path / "b" / name).read_bytes(), name
        assert a == (tmp_path / "dask" / name).read_bytes(), name
    rows = (tmp_path / "a" / "samples.csv").read_text().splitlines()
    # The sampled keys (mu_c and the grease's scatter), then the scene's answers.
    assert len(rows) == 201 and rows[0].startswith("index,friction.boundary_friction_coefficient,") and ",time_to_lock" in rows[0]
    assert (tmp_path / "a" / "scene_uncertainty.png").stat().st_size > 10_000
    summary = (tmp_path / "a" / "summary.txt").read_text()
    assert "Locked by the end time: 100.00 %" in summary
    # Another seed, other samples.
    assert ex.main([*small[:-1], "8", "--no-figure", "--output", str(tmp_path / "c")]) == 0
    assert (tmp_path / "c" / "samples.csv").read_bytes() != (tmp_path / "a" / "samples.csv").read_bytes()


def test_a_real_fit_drives_the_example(tmp_path):
    truth = pinjoint.Params({MU: 0.105})
    rec = pinjoint.simulate_cycle(0.3, np.radians(40), 20e3, cycles=3, samples_per_cycle=1000, params=truth)
    fit = pinjoint.calibrate([dict(rec, load=20e3)])
    s = scenes.sample_parameters(4000, 2, calibration=fit)
    est = fit["parameters"][MU]
    assert list(s) == [MU]
    assert abs(s[MU].mean() - est["value"]) < 5 * est["standard_error"] / math.sqrt(4000)
    assert s[MU].std() == pytest.approx(est["standard_error"], rel=0.05)
    path = tmp_path / "fit.json"
    path.write_text(fit.to_json())
    ex = load_example("scene_uncertainty")
    assert ex.main(["--calibration", str(path), "--samples", "40", "--end-time", "2", "--temperature-c", "20", "--no-figure", "--output", str(tmp_path / "o")]) == 0
    rows = (tmp_path / "o" / "samples.csv").read_text().splitlines()
    mu = np.array([float(r.split(",")[1]) for r in rows[1:]])
    assert np.all(np.abs(mu - est["value"]) < 6 * est["standard_error"])
