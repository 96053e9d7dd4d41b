"""`pinjoint sweep --output X.parquet` read back with pyarrow: the CSV's columns in its order,
every number bit for bit the CSV's (the CSV prints the shortest text that reads back as the
double), regime and validity as text; `--input X.parquet` answers as the CSV input does; bad
Parquet inputs are errors naming the column or row."""

from __future__ import annotations

import csv
import subprocess

import numpy as np
import pytest

pq = pytest.importorskip("pyarrow.parquet")
pa = pytest.importorskip("pyarrow")


def run(cli, *args, ok=True):
    r = subprocess.run([str(cli), *map(str, args)], capture_output=True, text=True, timeout=300)
    if ok:
        assert r.returncode == 0, r.stderr
    return r


def points(tmp_path, seed, n, temperature=False, label=False):
    rng = np.random.default_rng(seed)
    load = 1e3 * 10 ** rng.uniform(0.5, 2.0, n) * np.where(rng.uniform(size=n) < 0.1, -1, 1)
    speed = np.where(rng.uniform(size=n) < 0.1, 0.0, rng.choice([-1, 1], n) * 10 ** rng.uniform(-5, 1.5, n))
    cols = {"load": load, "speed": speed}
    if temperature:
        cols["temperature"] = rng.choice([243.15, 293.15, 313.15], n)
    path = tmp_path / f"pts{seed}.csv"
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        head = (["id"] if label else []) + list(cols)
        w.writerow(head)
        for i in range(n):
            w.writerow(([f"case,{i}"] if label else []) + [repr(float(cols[k][i])) for k in cols])
    return path, cols


def read_csv_text(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:]


@pytest.mark.parametrize("seed,fidelity,temperature,label", [(1, "full", False, True), (2, "boundary", True, False), (3, "table", False, False), (4, "auto", True, True)])
def test_parquet_is_the_csv_bit_for_bit(cli, tmp_path, seed, fidelity, temperature, label):
    src, _ = points(tmp_path, seed, 300, temperature, label)
    out_csv, out_pq = tmp_path / "out.csv", tmp_path / "out.parquet"
    run(cli, "sweep", "--input", src, "--output", out_csv, "--fidelity", fidelity)
    run(cli, "sweep", "--input", src, "--output", out_pq, "--fidelity", fidelity)
    head, rows = read_csv_text(out_csv)
    t = pq.read_table(out_pq)
    assert t.column_names == head
    assert t.num_rows == len(rows)
    for k, name in enumerate(head):
        col = t.column(name)
        if name in ("regime", "validity", "id"):
            assert pa.types.is_string(col.type) or pa.types.is_dictionary(col.type), (name, col.type)
            assert [str(v) for v in col.to_pylist()] == [r[k] for r in rows], name
        else:
            assert col.type == pa.float64(), (name, col.type)
            got = col.to_numpy()
            want = np.array([float(r[k]) for r in rows])
            assert np.array_equal(got.view(np.uint64), want.view(np.uint64)), name


def test_parquet_input_answers_as_the_csv_input(cli, tmp_path):
    src, cols = points(tmp_path, 7, 500, temperature=True)
    table = pa.table({"speed": cols["speed"], "other": np.arange(500), "load": cols["load"], "temperature": cols["temperature"]})
    pin = tmp_path / "in.parquet"
    pq.write_table(table, pin, row_group_size=128)
    a, b = tmp_path / "a.csv", tmp_path / "b.csv"
    run(cli, "sweep", "--input", src, "--output", a)
    run(cli, "sweep", "--input", pin, "--output", b)
    # The same rows; the input columns' text as given in the CSV, the same doubles.
    ha, ra = read_csv_text(a)
    hb, rb = read_csv_text(b)
    assert ha == hb and len(ra) == len(rb) == 500
    for x, y in zip(ra, rb):
        assert [float(v) for v in x[:3]] == [float(v) for v in y[:3]]
        assert x[3:] == y[3:]
    # Parquet in, Parquet out, at a fidelity level (the envelope from the file's own ranges).
    c, d = tmp_path / "c.parquet", tmp_path / "d.parquet"
    run(cli, "sweep", "--input", src, "--output", c, "--fidelity", "table")
    run(cli, "sweep", "--input", pin, "--output", d, "--fidelity", "table")
    assert pq.read_table(c).equals(pq.read_table(d))


def test_many_rows_stream_in_row_groups(cli, tmp_path):
    n = 200_000
    src = tmp_path / "big.csv"
    k = np.arange(n)
    with open(src, "w") as f:
        f.write("load,speed\n")
        f.writelines(f"{5e3 + (i % 977) * 50.0!r},{1e-3 * (1 + i % 1013)!r}\n" for i in range(n))
    out = tmp_path / "big.parquet"
    run(cli, "sweep", "--input", src, "--output", out, "--fidelity", "boundary")
    meta = pq.ParquetFile(out).metadata
    assert meta.num_rows == n
    assert meta.num_row_groups >= 3  # streamed in bounded row groups
    t = pq.read_table(out, columns=["load", "speed"])
    assert np.array_equal(t.column("load").to_numpy(), 5e3 + (k % 977) * 50.0)


def test_bad_parquet_inputs_name_the_column_or_row(cli, tmp_path):
    p = tmp_path / "no_speed.parquet"
    pq.write_table(pa.table({"load": [1e4, 2e4]}), p)
    r = run(cli, "sweep", "--input", p, ok=False)
    assert r.returncode != 0 and "speed" in r.stderr and "panick" not in r.stderr
    p = tmp_path / "null.parquet"
    pq.write_table(pa.table({"load": [1e4, None, 3e4], "speed": [1.0, 1.0, 1.0]}), p)
    r = run(cli, "sweep", "--input", p, ok=False)
    assert r.returncode != 0 and "row 2" in r.stderr and "load" in r.stderr
    p = tmp_path / "text.parquet"
    pq.write_table(pa.table({"load": ["a", "b"], "speed": [1.0, 1.0]}), p)
    r = run(cli, "sweep", "--input", p, ok=False)
    assert r.returncode != 0 and "load" in r.stderr
    p = tmp_path / "zero.parquet"
    pq.write_table(pa.table({"load": [1e4, 0.0], "speed": [1.0, 1.0]}), p)
    r = run(cli, "sweep", "--input", p, ok=False)
    assert r.returncode != 0 and "load = 0 N" in r.stderr
    p = tmp_path / "garbage.parquet"
    p.write_bytes(b"load,speed\n1,2\n")
    r = run(cli, "sweep", "--input", p, ok=False)
    assert r.returncode != 0 and "Parquet" in r.stderr and "panick" not in r.stderr


def test_map_writes_parquet(cli, tmp_path):
    run(cli, "map", "--loads", 3, "--speeds", 4, "--output", tmp_path / "csv")
    run(cli, "map", "--loads", 3, "--speeds", 4, "--output", tmp_path / "pq", "--format", "parquet")
    head, rows = read_csv_text(tmp_path / "csv" / "map.csv")
    t = pq.read_table(tmp_path / "pq" / "map.parquet")
    assert t.column_names == head
    for k, name in enumerate(head):
        if name in ("regime", "validity"):
            assert t.column(name).to_pylist() == [r[k] for r in rows]
        else:
            want = np.array([float(r[k]) for r in rows])
            assert np.array_equal(t.column(name).to_numpy().view(np.uint64), want.view(np.uint64)), name
