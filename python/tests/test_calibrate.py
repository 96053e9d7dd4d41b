"""pinjoint.calibrate: mu_c recovered from rig records made by simulate_cycle, the result
equal to `pinjoint calibrate --json` on the same records (bit for bit), bad records rejected."""

from __future__ import annotations

import json
import pickle
import subprocess

import numpy as np
import pytest

import pinjoint

MU = 0.105
LOADS = (20e3, 40e3)


@pytest.fixture(scope="module")
def records():
    """Two rig records (0.3 Hz, +-40 deg, 3 strokes; breakaway peaks at every reversal, the
    rig's inertia and servo) at two loads, made with mu_c = 0.105, with 0.05 N*m of torque
    noise (without any, the fitted mu_c and J carry only the rig integrator's error, 3e-9 and
    3e-6 relative, and their intervals, 1e-9 wide, need not cover that)."""
    params = pinjoint.Params({pinjoint.MU_C: MU})
    rng = np.random.default_rng(1)
    out = []
    for load in LOADS:
        c = pinjoint.simulate_cycle(0.3, np.radians(40.0), load, cycles=3, samples_per_cycle=1000, params=params)
        torque = c["torque"] + 0.05 * rng.standard_normal(len(c["torque"]))
        out.append({"name": f"P{load:g}", "time": c["time"], "angle": c["angle"], "torque": torque, "load": load})
    return out


@pytest.fixture(scope="module")
def fitted(records):
    return pinjoint.calibrate(records)


def write_csv(path, rec):
    """The record as a CSV the CLI reads: every value in Python's repr (round-trips exactly)."""
    with open(path, "w") as f:
        f.write("time,angle,torque,load\n")
        for t, a, q in zip(rec["time"], rec["angle"], rec["torque"]):
            f.write(f"{float(t)!r},{float(a)!r},{float(q)!r},{float(rec['load'])!r}\n")


def test_mu_c_recovered_within_interval(fitted):
    est = fitted["parameters"][pinjoint.MU_C]
    lo, hi = est["ci95"]
    assert lo <= MU <= hi, est
    assert abs(est["value"] - MU) < 1e-3, est
    assert 0 < est["standard_error"] < 1e-3
    # The calibrated parameter set: mu_c replaced, everything else the defaults.
    assert fitted.params[pinjoint.MU_C] == est["value"]
    assert fitted.params.with_values({pinjoint.MU_C: 0.12}) == pinjoint.Params()
    assert fitted["points_used"] + fitted["points_excluded"] == sum(len(r["time"]) for r in fitted["series"])
    # Excluded windows are reported per record, each with its reason.
    assert [x["record"] for x in fitted["excluded"]] == ["P20000", "P40000"]
    for x in fitted["excluded"]:
        assert x["windows"] and {w["reason"] for w in x["windows"]} <= {"low speed", "settling after reversal"}
        assert sum(w["samples"] for w in x["windows"]) == x["low_speed"] + x["settling"]


def test_equals_cli_json(fitted, records, cli, tmp_path):
    paths = []
    for r in records:
        p = tmp_path / f"{r['name']}.csv"
        write_csv(p, r)
        paths.append(p)
    args = [str(cli), "calibrate", "--output", str(tmp_path / "out"), "--json"]
    for p in paths:
        args += ["--input", str(p)]
    run = subprocess.run(args, check=True, capture_output=True, text=True)
    cli_json = json.loads(run.stdout)
    ours = json.loads(fitted.to_json())
    assert ours == cli_json  # the floats parse back to the same doubles: bit for bit
    for key in cli_json:
        assert fitted[key] == cli_json[key], key
    assert pinjoint.Params.from_toml(tmp_path / "out" / "calibrated.toml") == fitted.params


def test_inertia_fitted_unless_given(fitted, records):
    # No inertia and no rig.inertia in params: J is fitted with mu_c and T0, with its interval
    # (the records' rig has J = 0.05 kg*m^2), and reported as fitted.
    assert fitted["inertia_fitted"] is True
    j = fitted["inertia_estimate"]
    assert j["ci95"][0] <= 0.05 <= j["ci95"][1], j
    assert fitted["inertia"] == j["value"]
    assert "rig.inertia" in fitted["correlation_keys"]
    given = pinjoint.calibrate(records, inertia=0.05, resamples=0)
    assert given["inertia_fitted"] is False and "inertia_estimate" not in given and given["inertia"] == 0.05
    assert "rig.inertia" not in given["correlation_keys"]


def test_long_records_are_block_averaged_to_the_sample_budget(records):
    n = sum(len(r["time"]) for r in records)
    avg = pinjoint.calibrate(records, max_samples=n // 2, resamples=0)
    assert avg["block_length"] == 2 and avg["samples_read"] == n
    assert sum(len(s["time"]) for s in avg["series"]) <= n // 2 + len(records)
    assert abs(avg["parameters"][pinjoint.MU_C]["value"] - MU) < 1e-3
    with pytest.raises(ValueError, match="max_samples"):
        pinjoint.calibrate(records, max_samples=10)


def test_result_pickles_and_forms(fitted, records):
    again = pickle.loads(pickle.dumps(fitted))
    assert again.params == fitted.params and again["parameters"] == fitted["parameters"]
    # One record alone, an object with attributes, a scalar load as an array: same fit.
    class Rec:
        pass

    r = Rec()
    for k, v in records[0].items():
        setattr(r, k, v)
    a = pinjoint.calibrate(records[0], resamples=0)
    b = pinjoint.calibrate([r], resamples=0)
    c = pinjoint.calibrate([dict(records[0], load=np.full(len(records[0]["time"]), LOADS[0]))], resamples=0)
    assert a.to_json() == b.to_json() == c.to_json()


def short(rec, **changes):
    return dict(rec, **changes)


@pytest.mark.parametrize(
    "change, words",
    [
        (lambda r: short(r, torque=np.where(np.arange(len(r["time"])) == 7, np.nan, r["torque"])), ["torque", "nan", "N.m", "index 7"]),
        (lambda r: short(r, load=-5.0), ["load = -5.0 N", "index 0"]),
        (lambda r: short(r, angle=np.degrees(r["angle"])), ["angle", "rad", "degrees"]),
        (lambda r: short(r, time=r["time"][::-1].copy()), ["time", "index 1"]),
        (lambda r: {k: (v[:5] if isinstance(v, np.ndarray) else v) for k, v in r.items()}, ["5 samples", "too short"]),
        (lambda r: short(r, angle=np.zeros_like(r["angle"])), ["no motion"]),
        (lambda r: {k: v for k, v in r.items() if k != "torque"}, ["torque", "N.m"]),
        (lambda r: {k: v for k, v in r.items() if k != "angle"}, ["angle", "angular_velocity"]),
        (lambda r: short(r, torque=r["torque"][:-1]), ["torque", "values but time has"]),
    ],
)
def test_bad_records_are_value_errors(records, change, words):
    with pytest.raises(ValueError) as e:
        pinjoint.calibrate([change(records[0])], resamples=0)
    text = str(e.value)
    for w in words:
        assert w.lower() in text.lower(), (w, text)
    assert len(text) < 400, text


def test_bad_options_are_value_errors(records):
    with pytest.raises(ValueError, match="model = 'rig'"):
        pinjoint.calibrate(records, model="rig")
    with pytest.raises(ValueError, match="always fitted"):
        pinjoint.calibrate(records, fit=("lubricant.viscosity",))
    with pytest.raises(ValueError, match="no_such"):
        pinjoint.calibrate(records, fit=(pinjoint.MU_C, "lubricant.no_such"), resamples=0)
    with pytest.raises(ValueError, match="no records"):
        pinjoint.calibrate([])
    with pytest.raises(TypeError):
        pinjoint.calibrate(records, resamples=1.5)


def test_options_map_to_cli_flags(records, cli, tmp_path):
    """params as a TOML file with a [rig] inertia (as --params), and the exclusion and offset
    options as --speed-fraction, --settle-time, --no-offset: the same JSON as the CLI."""
    toml = tmp_path / "start.toml"
    toml.write_text(f"[friction]\nboundary_friction_coefficient = 0.1\n\n[rig]\ninertia = 0.07\n")
    csv_path = tmp_path / "r.csv"
    write_csv(csv_path, records[1])
    ours = pinjoint.calibrate([records[1]], params=toml, speed_fraction=0.4, settle_time=0.2, fit_offset=False)
    assert ours["inertia"] == 0.07 and "torque_offset" not in ours
    run = subprocess.run(
        [str(cli), "calibrate", "--input", str(csv_path), "--params", str(toml), "--speed-fraction", "0.4",
         "--settle-time", "0.2", "--no-offset", "--output", str(tmp_path / "out"), "--json"],
        check=True, capture_output=True, text=True,
    )
    assert json.loads(ours.to_json()) == json.loads(run.stdout)
    # A changed option changes the fit (the comparison above can fail).
    other = pinjoint.calibrate([records[1]], params=toml, speed_fraction=0.4, settle_time=0.2, fit_offset=False, inertia=0.0)
    assert other["parameters"] != ours["parameters"]


@pytest.fixture(scope="module")
def cold_records():
    """Rig records at 233.15 and 293.15 K (outside the stick-slip band of about -25 to 5 C that the
    grease's supply layer gives the rig at 20 kN, where the quasi-static fit does not hold) (0.5 Hz, +-40 deg, 3 cycles, 20 kN) made with the
    grease's yield activation temperature 25 % above its default, 0.05 N*m of torque noise;
    each carries its temperature."""
    truth = {pinjoint.MU_C: MU, "grease.yield_activation": 1.25 * pinjoint.Params()["grease.yield_activation"]}
    rng = np.random.default_rng(2)
    out = []
    for t in (233.15, 293.15):
        p = pinjoint.Params(dict(truth, **{"lubricant.temperature": t}))
        c = pinjoint.simulate_cycle(0.5, np.radians(40.0), 20e3, cycles=3, samples_per_cycle=600, params=p)
        torque = c["torque"] + 0.05 * rng.standard_normal(len(c["torque"]))
        out.append({"name": f"T{t:g}", "time": c["time"], "angle": c["angle"], "torque": torque, "load": 20e3, "temperature": t})
    return out


def test_temperature_per_record_equals_cli(cold_records, cli, tmp_path):
    """temperature= (one per record) is --temperature per --input: the same JSON, bit for bit;
    a temperature column in the record gives the same fit; 2 temperatures fit what is named."""
    keys = (pinjoint.MU_C, "grease.yield_activation")
    bare = [{k: v for k, v in r.items() if k != "temperature"} for r in cold_records]
    ours = pinjoint.calibrate(bare, fit=keys, temperature=[233.15, 293.15], resamples=0)
    assert ours["temperatures"] == [233.15, 293.15]
    assert "grease.yield_activation" in ours["parameters"]
    column = pinjoint.calibrate(cold_records, fit=keys, resamples=0)
    assert column.to_json() == ours.to_json()
    args = [str(cli), "calibrate", "--fit", "grease.yield_activation", "--output", str(tmp_path / "out"), "--json"]
    for r in cold_records:
        p = tmp_path / f"{r['name']}.csv"
        write_csv(p, r)
        args += ["--input", str(p), "--temperature", repr(r["temperature"])]
    run = subprocess.run(args, check=True, capture_output=True, text=True)
    cli_json = json.loads(run.stdout)
    # The CLI's bootstrap default differs from resamples=0: compare without it.
    again = pinjoint.calibrate(bare, fit=keys, temperature=[233.15, 293.15])
    assert json.loads(again.to_json()) == cli_json
    assert pinjoint.Params.from_toml(tmp_path / "out" / "calibrated.toml") == again.params
    # Without the temperatures the records are taken at the parameters' 20 C: another fit.
    plain = pinjoint.calibrate(bare, resamples=0)
    assert plain["temperatures"] == [] and plain["rms_residual"] > ours["rms_residual"]
    # Two temperatures and nothing named: mu_c only, and the warning says why.
    default = pinjoint.calibrate(cold_records, resamples=0)
    assert list(default["parameters"]) == [pinjoint.MU_C]
    assert any("2 temperatures" in w and "3 or more" in w for w in default["warnings"]), default["warnings"]


@pytest.mark.parametrize(
    "temperature, words",
    [
        (20.0, ["temperature = 20", "kelvin?", "293.15 K"]),
        (-5.0, ["temperature = -5", "> 0 K", "kelvin?"]),
        (float("nan"), ["temperature = nan", "finite"]),
        ([293.15, 293.15, 293.15], ["3 temperature values for 2 records"]),
        (200.0, ["temperature = 200", "lubricant.temperature"]),
    ],
)
def test_bad_temperatures_are_value_errors(cold_records, temperature, words):
    bare = [{k: v for k, v in r.items() if k != "temperature"} for r in cold_records]
    with pytest.raises(ValueError) as e:
        pinjoint.calibrate(bare, temperature=temperature, resamples=0)
    text = str(e.value)
    for w in words:
        assert w.lower() in text.lower(), (w, text)


def test_temperature_column_and_argument_must_agree(cold_records):
    with pytest.raises(ValueError, match="disagrees with temperature=300"):
        pinjoint.calibrate(cold_records, temperature=300.0, resamples=0)
    with pytest.raises(ValueError, match="kelvin"):
        pinjoint.calibrate([dict(cold_records[0], temperature=20.0)], resamples=0)
