#!/usr/bin/env python3
"""Writes the hand-made seeds of fuzz/regressions/ (the byte layouts are read by
fuzz/src/checks.rs). Run from the fuzz directory: python3 make_seeds.py"""
import math
import struct
from pathlib import Path

TYPICAL = 7  # selector byte: keep the parameter's default


def u16(v):
    return list(struct.pack("<H", v))


def log2_code(x, scale):
    """The u16 code of checks.rs's `2^((u16 - 32768)/scale)`."""
    return u16(int(round(32768 + math.log2(x) * scale)))


def core(params=None, load=20e3, omega=0.2, guess=None):
    b = []
    params = params or {}
    for i in range(21):
        b += params.get(i, [TYPICAL])
    if isinstance(load, list):
        b += load
    else:
        b += [0] + log2_code(load / 20e3, 1024)
    if isinstance(omega, list):
        b += omega
    else:
        b += [0 if omega >= 0 else 1, 0] + log2_code(abs(omega), 1024)
    b += [0] if guess is None else [1] + list(struct.pack("<d", guess))
    return bytes(b)


def fmi_setup(k=0, logging=0):
    return [0, k, 34, 0, 1, 2, 2, logging, 1, k, 1, 0, 7, 7, 0, 2, k, 4, k]


def step(k=0):  # doStep at the host's time, 1 ms
    return [13, k, 2, 2, 128, 0]


def set_real(k, vr_index, special):  # one value of SPECIAL at variables[vr_index]
    return [8, k, 1, 2, vr_index, 5, special, 3]


def set_reals(k, pairs):  # [(variable index, float)] as raw bits
    b = [8, k, len(pairs)]
    for idx, _ in pairs:
        b += [2, idx]
    for _, v in pairs:
        b += [4] + list(struct.pack("<d", v))
    return b + [3]


# Parameters the core accepts but for which it returns a negative film (fuzz/README.md):
# asperity_density, asperity_radius, summit_height_std, viscosity (table indices 20, 21, 22, 26).
SPARSE = [(20, 2.79296875e7), (21, 1.328125e-8), (22, 1.8331541852530975e-6), (26, 6.593932009391239e-5)]

out = Path(__file__).parent / "regressions"
seeds = {
    "core/seed-default-20kN-0.2rads": core(),
    "core/seed-60kN-80rads-warm": core(load=60e3, omega=-80.0, guess=3.0),
    "core/seed-at-rest": core(omega=[0, 2, 0]),
    "core/seed-poisson-at-bound-and-nan-viscosity": core(params={4: [6, 1, 0], 13: [5, 4]}),
    "core/seed-load-1e9-speed-1e6": core(load=1e9, omega=1e6),
    "fmi_calls/seed-init-step": bytes(fmi_setup() + step() * 3),
    "fmi_calls/seed-bad-inputs": bytes(fmi_setup() + set_real(0, 2, 4) + set_real(0, 2, 2) + set_real(0, 1, 5)
                                       + set_real(0, 2, 15) + step() + set_real(0, 1, 16) + step()),
    "fmi_calls/seed-state-serialize-deserialize": bytes(fmi_setup() + step() + [18, 0, 1, 21, 0, 1, 1, 23, 0, 1, 0, 5, 2, 1]
                                                        + [19, 0, 2] + step()),
    # Regressions of the FMU fix: before it, these returned fmi2OK with film_thickness < 0.
    "fmi_calls/regression-negative-film-at-initialization": bytes([0, 0, 34, 0, 1, 2, 2, 0, 1, 0, 1, 0, 7, 7, 0]
                                                                  + set_reals(0, SPARSE) + [2, 0, 4, 0, 12, 0, 1, 2, 5]),
    "fmi_calls/regression-1e9-newton-at-rest": bytes(fmi_setup() + step() + set_real(0, 2, 15) + set_real(0, 1, 0) + step()
                                                     + [11, 0, 1, 2, 5]),
    "fmi_calls/seed-two-instances-reset": bytes(fmi_setup(0) + fmi_setup(1) + step(0) + step(1) + [6, 0, 7, 0]
                                                + [18, 1, 3, 30, 1, 3, 2] + step(0)),
}
for name, data in seeds.items():
    p = out / name
    p.parent.mkdir(parents=True, exist_ok=True)
    p.write_bytes(data)
    print(p, len(data))
