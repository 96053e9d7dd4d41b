"""examples/monte_carlo_dask.py on a 2-worker LocalCluster equals a serial run bit for bit."""

from __future__ import annotations

from pathlib import Path

from conftest import load_example

ROOT = Path(__file__).resolve().parents[2]


def test_dask_local_cluster_equals_serial_run(tmp_path, monkeypatch):
    # The worker processes (multiprocessing spawn, which hands them this sys.path) import the
    # example's task functions by name.
    monkeypatch.syspath_prepend(str(ROOT / "examples"))
    monkeypatch.setenv("PYTHONPATH", str(ROOT / "examples"))
    ex = load_example("monte_carlo_dask")
    small = ["--samples", "6", "--cycles", "2", "--samples-per-cycle", "200", "--map-loads", "6",
             "--map-speeds", "20", "--map-tasks", "3"]
    assert ex.main([*small, "--workers", "2", "--output", str(tmp_path / "dask")]) == 0
    assert ex.main([*small, "--serial", "--output", str(tmp_path / "serial")]) == 0
    for name in ("monte_carlo.csv", "operating_map.csv", "summary.txt"):
        a = (tmp_path / "dask" / name).read_bytes()
        b = (tmp_path / "serial" / name).read_bytes()
        assert a == b, name
    rows = (tmp_path / "dask" / "monte_carlo.csv").read_text().splitlines()
    assert len(rows) == 7 and rows[0].startswith("index,mu_c")
    # Every sample really differs, and its torques are positive and ordered.
    vals = [list(map(float, r.split(","))) for r in rows[1:]]
    assert len({v[1] for v in vals}) == 6
    assert all(0 < v[6] <= v[5] for v in vals)
    assert (tmp_path / "dask" / "torque_distribution.png").stat().st_size > 10_000
    assert len((tmp_path / "dask" / "operating_map.csv").read_text().splitlines()) == 1 + 6 * 20
