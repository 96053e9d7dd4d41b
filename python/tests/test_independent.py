"""Joint.evaluate against an independent NumPy/SciPy implementation of the model
(python/bench/reference_model.py: direct formulas, quadrature for F_3/2, brentq) to 1e-9."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

import pinjoint

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "bench"))
from reference_model import ReferenceJoint, ln_f32  # noqa: E402
from conftest import inside_film_bound  # noqa: E402

# The check values of F_3/2 in docs/model.md.
F32 = [(-3, 5.418377276511698), (0, 0.4300199936622599), (0.5, 0.19520360374379062), (1, 0.07566817739097503),
       (2, 0.006648177623587), (3, 2.639675542694661e-4), (4, 4.4391559585389115e-6)]


@pytest.mark.parametrize("t,value", F32)
def test_reference_f32_matches_model_notes(t, value):
    assert abs(np.exp(ln_f32(t)) / value - 1) < 1e-12


@pytest.mark.parametrize(
    "params",
    # The paper's model: the independent implementation is of its equations.
    [{"model.paper": True}, {"model.paper": True, "friction.boundary_friction_coefficient": 0.09, "lubricant.viscosity": 0.1, "surface.summit_height_std": 1.5e-6}],
)
def test_evaluate_agrees_with_the_independent_model_to_1e_9(params):
    rng = np.random.default_rng(2024)
    n = 40
    loads = np.exp(rng.uniform(np.log(10.0), np.log(1e6), n))
    speeds = rng.choice([-1, 1], n) * np.exp(rng.uniform(np.log(1e-8), np.log(1e4), n))
    speeds[:3] = 0.0
    p = pinjoint.Params(params)
    # The points the model answers (a film beyond the clearance is a ValueError: docs/conventions.md).
    keep = inside_film_bound(pinjoint.Joint(p), loads, speeds)
    assert keep.sum() >= 20, keep.sum()
    loads, speeds = loads[keep], speeds[keep]
    ours = pinjoint.Joint(p).evaluate(loads, speeds)
    ref = ReferenceJoint(p).evaluate(loads, speeds)
    # The paper's model (the independent implementation has no h_min extension).
    # The complete model's columns are 0 with model.paper (checked below), not in the reference.
    complete = ("clearance_torque", "journal_weight", "eccentricity_ratio", "grease_yield_torque")
    for k in ("clearance_torque", "journal_weight", "grease_yield_torque"):  # eccentricity_ratio is 1 - h/c
        assert np.all(ours[k] == 0.0), k
    for k in [c for c in pinjoint.RESULT_COLUMNS if c not in ("regime", "min_film_thickness", "min_lambda_ratio", "validity") + complete]:
        rel = np.abs(ours[k] - ref[k]) / np.maximum(np.abs(ref[k]), 1e-300)
        assert rel.max() < 1e-9, (k, rel.max(), loads[rel.argmax()], speeds[rel.argmax()])
    assert list(ours["regime"]) == list(ref["regime"])
    assert {"boundary", "full-film"} <= set(ours["regime"])
