"""What each tied number of the manual is: page → {ID: Python expression} (tied_numbers.py).

The expressions run against the built project (check_docs.py --run; --update-numbers
rewrites the pages from them):

- point(N=|kN=, w=|rpm=, C=20, paper=False, p={dotted key: value}) → the JSON object of
  `pinjoint point --json` (keys: torque, friction_coefficient, film_thickness, journal_weight,
  clearance_torque, grease_yield_torque, inlet_viscosity, ...), at C °C, with the parameter
  overrides `p` in a parameter file;
- sweep([(load N, speed rad/s, C °C), ...], p=...) → the rows of `pinjoint sweep`;
- param("grease.yield_stress") → a default of `pinjoint params`;
- lib("journal.ld1.S.0.1") → a number of `target/release/examples/doc_numbers`;
- code(path, regex) → a constant of the source (group 1, a Rust constant expression: literals,
  arithmetic, PI and the file's other `const NAME: f64`); const(path, NAME) → `const NAME: f64`;
- column(path, name) → a column of a CSV file of the repository (a test fixture);
- the functions of HELPERS below, and math's.

A value is a string (the quoted number must equal it to the rounding of its quoted digits)
or Spec(expr, rel=...) for an explicit relative tolerance. Inputs of an operating point are
written as the page writes them (kN=20, w=3, C=-20): the page's untagged numbers of the same
paragraph that are literals of these expressions are its inputs.
"""
import re

from tied_numbers import Spec

C0 = "273.15"  # K at 0 °C, for the code's kelvin constants


def X(expr):
    """A number quoted as the value itself: a parameter's default, a constant of the code."""
    return Spec(expr, exact=True)


def warming_steps(b):
    """Over 12 loads (10 N–1 MN) × 12 speeds (1e-3–200 rad/s), log-spaced, from 20 to 120 °C
    in steps of 2.5 K: how many steps raise the torque, and the steepest rise (ratio, load,
    speed)."""
    geo = lambda lo, hi, n: [lo * (hi / lo) ** (i / (n - 1)) for i in range(n)]
    loads, speeds = geo(10.0, 1e6, 12), geo(1e-3, 200.0, 12)
    temps = [20.0 + 2.5 * k for k in range(41)]
    out = b.sweep([(load, w, c) for load in loads for w in speeds for c in temps])
    up, worst = 0, (0.0, 0.0, 0.0)
    for i in range(len(loads) * len(speeds)):
        seq = out[41 * i: 41 * (i + 1)]
        for a, c in zip(seq, seq[1:]):
            if c["torque"] > a["torque"]:
                up += 1
                worst = max(worst, (c["torque"] / a["torque"], a["load"], a["speed"]))
    return {"grid": len(loads) * len(speeds), "steps": len(loads) * len(speeds) * 40, "up": up,
            "ratio": worst[0], "load": worst[1], "speed": worst[2], "from": temps[0], "to": temps[-1], "step": 2.5}


def rig_worst(b):
    """The largest relative torque difference complete/paper over the paper's room on
    tests/one_answer.rs's grid through its corners (5 temperatures 15–25 °C × 13 loads
    5–60 kN × 21 speeds up to 4.386 rad/s): (difference, load, speed, °C)."""
    rows = []
    for c in (15.0, 17.5, 20.0, 22.5, 25.0):
        for k in range(13):
            load = 5e3 * 12.0 ** (k / 12.0)
            for m in range(21):
                rows.append((load, 0.0 if m == 0 else 4.386 * 1e-4 ** (1.0 - m / 20.0), c))
    full, paper = b.sweep(rows), b.sweep(rows, p={"model.paper": True})
    worst = max((abs(a["torque"] / p["torque"] - 1.0), a["load"], a["speed"], r[2]) for a, p, r in zip(full, paper, rows))
    return worst


def cooling_steps(b):
    """Over warming_steps' 144 loads and speeds, from 20 down to −55 °C in steps of 2.5 K: how
    many steps lower the torque as it cools."""
    geo = lambda lo, hi, n: [lo * (hi / lo) ** (i / (n - 1)) for i in range(n)]
    loads, speeds = geo(10.0, 1e6, 12), geo(1e-3, 200.0, 12)
    temps = [20.0 - 2.5 * k for k in range(31)]
    out = b.sweep([(load, w, c) for load in loads for w in speeds for c in temps])
    down = 0
    for i in range(len(loads) * len(speeds)):
        seq = out[31 * i: 31 * (i + 1)]
        down += sum(1 for a, c in zip(seq, seq[1:]) if c["torque"] < a["torque"])
    return {"grid": len(loads) * len(speeds), "steps": len(loads) * len(speeds) * 30, "down": down,
            "from": temps[0], "to": temps[-1], "step": 2.5}


def monotone_in_load(b, w_lo, w_hi, c_lo, c_hi, n_lo, kn_hi):
    """On a grid of 12 speeds (w_lo–w_hi rad/s) × 12 temperatures (c_lo–c_hi °C), 201 loads
    log-spaced n_lo N–kn_hi kN each, the default grease: the largest relative fall of the
    torque and rise of the film between neighbouring loads, and whether each lay inside the
    journal ↔ line-contact transition (0 < w < 1 at either neighbour)."""
    speeds = [w_lo * (w_hi / w_lo) ** (i / 11) for i in range(12)]
    temps = [c_lo + (c_hi - c_lo) * i / 11 for i in range(12)]
    loads = [n_lo * (kn_hi * 1e3 / n_lo) ** (k / 200) for k in range(201)]
    out = b.sweep([(load, w, c) for w in speeds for c in temps for load in loads])
    fall, rise, outside = 0.0, 0.0, 0.0
    for i in range(len(speeds) * len(temps)):
        seq = out[201 * i: 201 * (i + 1)]
        for a, c in zip(seq, seq[1:]):
            f = max(0.0, 1.0 - c["torque"] / a["torque"])
            r = max(0.0, c["film_thickness"] / a["film_thickness"] - 1.0)
            inside = 0.0 < a["journal_weight"] < 1.0 or 0.0 < c["journal_weight"] < 1.0
            fall, rise = max(fall, f), max(rise, r)
            if not inside:
                outside = max(outside, f, r)
    return {"torque": fall, "film": rise, "outside": outside, "speeds": len(speeds), "temps": len(temps), "loads": len(loads)}


def rb_high(b, c_um, lam):
    """Raimondi & Boyd's L/D = 1 rows at ε 0.8 and 0.9 (tests/one_answer.rs's table) on a rigid
    wide-clearance bearing (c = c_um µm, B = 2R, the base oil alone) at 0.3–100 rad/s: the
    largest relative deviation of μ·R/c from their (R/c)f (%) where w = 1 and λ ≥ lam."""
    text = (b.root / "tests/one_answer.rs").read_text(encoding="utf-8")
    m = re.search(r"const RAIMONDI_BOYD_HIGH: \[\(f64, f64, f64\); \d+\] = \[(.*?)\];", text, re.S)
    rows = [tuple(float(x) for x in r) for r in re.findall(r"\(([\d.]+), ([\d.]+), ([\d.]+)\)", m.group(1))]
    r = b.param("geometry.pin_radius")
    c, eta, length = c_um * 1e-6, b.param("lubricant.viscosity"), 2 * r
    p = {"grease.enabled": False, "geometry.bush_length": length, "geometry.bush_radius": r + c}
    worst, checked = 0.0, 0
    for eps, s, f in rows:
        for w in (0.3, 1.0, 3.0, 10.0, 30.0, 100.0):
            load = eta * w / (2 * 3.141592653589793 * s) * (r / c) ** 2 * 2 * r * length
            op = b.point(N=load, w=w, p=p)
            if op["journal_weight"] >= 1.0 and op["lambda_ratio"] >= lam:
                checked += 1
                worst = max(worst, abs(op["friction_coefficient"] * r / c / f - 1))
    if checked == 0:
        raise RuntimeError("no rigid full-film point")
    return {"worst_pc": 100 * worst, "eps_lo": min(e for e, _, _ in rows), "eps_hi": max(e for e, _, _ in rows)}


def rb_through_joint(b):
    """Raimondi & Boyd's L/D = 1 rows (tests/complete.rs's table) through the whole joint: the
    base oil alone, B = 2R, the load that gives their S at 3, 30 and 150 rad/s; the largest
    relative deviation of μ·R/c from their (R/c)f (%) where the joint is in full film (w = 1,
    λ ≥ 3), and the smallest and largest ε of the rows."""
    text = (b.root / "tests/complete.rs").read_text(encoding="utf-8")
    m = re.search(r"const RAIMONDI_BOYD_LD1: \[\(f64, f64, f64\); \d+\] = \[(.*?)\];", text, re.S)
    rows = [tuple(float(x) for x in r) for r in re.findall(r"\(([\d.]+), ([\d.]+), ([\d.]+)\)", m.group(1))]
    r, rb = b.param("geometry.pin_radius"), b.param("geometry.bush_radius")
    c, eta, length = rb - r, b.param("lubricant.viscosity"), 2 * b.param("geometry.pin_radius")
    p = {"grease.enabled": False, "geometry.bush_length": length}
    worst = 0.0
    for eps, s, f in rows:
        for w in (3.0, 30.0, 150.0):
            load = eta * w / (2 * 3.141592653589793 * s) * (r / c) ** 2 * 2 * r * length
            op = b.point(N=load, w=w, p=p)
            if op["journal_weight"] >= 1.0 and op["lambda_ratio"] >= 3.0:
                worst = max(worst, abs(op["friction_coefficient"] * r / c / f - 1))
    return {"worst_pc": 100 * worst, "eps_lo": min(e for e, _, _ in rows), "eps_hi": max(e for e, _, _ in rows)}


def ns_extra(b):
    return {"warming_steps": lambda: warming_steps(b), "rig_worst": lambda: rig_worst(b),
            "rb_through_joint": lambda: rb_through_joint(b), "cooling_steps": lambda: cooling_steps(b),
            "monotone_in_load": lambda *a: monotone_in_load(b, *a), "rb_high": lambda *a: rb_high(b, *a)}


def _sensitivity():
    """μ at 20 kN, 3 rad/s ('hi') and 200 N, 1 rad/s ('lo') for supply layers and exponents."""
    out = {}
    cases = [("off", {"grease.supply_layer_inverse": 0}), ("l5e3", {"grease.supply_layer_inverse": 5e3}),
             ("l2e4", {"grease.supply_layer_inverse": 2e4}), ("l8e4", {"grease.supply_layer_inverse": 8e4}),
             ("m05", {"grease.supply_exponent": 0.5}), ("m2", {"grease.supply_exponent": 2})]
    for mk, over in cases:
        for c in [20, 0, -20, -40, -55]:
            for side, (load, w) in {"hi": ("kN=20", 3), "lo": ("N=200", 1)}.items():
                out[f"sens.{mk}.{c}.{side}"] = f"point({load}, w={w}, C={c}, p={over!r})['friction_coefficient']"
    out["sens.l5e3.um"] = X("1e6/5e3")
    hi = lambda over: f"point(kN=20, w=3, C=20, p={over!r})['friction_coefficient']"
    lo = lambda over: f"point(N=200, w=1, C=20, p={over!r})['friction_coefficient']"
    layers = [{"grease.supply_layer_inverse": x} for x in (0, 5e3, 2e4, 8e4)] + [{"grease.supply_exponent": m} for m in (0.5, 2)]
    # the largest spread of μ at 20 kN, 3 rad/s, 20 °C over the table's layers (%), an upper bound
    out["sens.room_pc"] = Spec("100*(max(" + ", ".join(hi(o) for o in layers) + ")/min(" + ", ".join(hi(o) for o in layers) + ") - 1)", upper=True)
    out["sens.room_lo_pc"] = f"100*({lo(layers[3])}/{lo(layers[2])} - 1)"
    out["sens.l8e4.um"] = X("1e6/8e4")
    return out


def _supply_table():
    """20 kN, 3 rad/s against temperature: η_b, the supply layer h_oil (µm), the film, torque, μ."""
    out = {}
    for c in [20, 0, -20, -30, -40, -55]:
        pt = f"point(kN=20, w=3, C={c})"
        eta = f"{pt}['inlet_viscosity']"
        out[f"sup.{c}.eta"] = f"{eta}*1e3" if c > -40 else eta
        out[f"sup.{c}.hoil"] = (f"1e6/param('grease.supply_layer_inverse')*(point(kN=20, w=3, C=20)['inlet_viscosity']"
                                f"/{eta})**param('grease.supply_exponent')")
        out[f"sup.{c}.h"] = f"1e6*{pt}['film_thickness']"
        out[f"sup.{c}.fluid"] = f"100*{pt}['fluid_load_fraction']"
        out[f"sup.{c}.T"] = f"{pt}['torque']"
        out[f"sup.{c}.mu"] = f"{pt}['friction_coefficient']"
    return out


def _petroff(load, w, c=20):
    # Petroff's torque 2π η_b |ω| R³ B / c of the default joint at `load`, `w`, `c` °C.
    return (f"2*pi*point({load}, w={w}, C={c})['inlet_viscosity']*{w}*param('geometry.pin_radius')**3"
            f"*param('geometry.bush_length')/(param('geometry.bush_radius')-param('geometry.pin_radius'))")


T_REF = f"param('lubricant.reference_temperature') - {C0}"
BREAKAWAY_20KN = "param('friction.boundary_friction_coefficient')*param('geometry.pin_radius')*20e3"

COLD_DAY = {
    "cold_soak": X(f"const('src/validity.rs', 'COLD_SOAK') - {C0}"),
    "t_ref": X(T_REF),
    "ld": "param('geometry.bush_length')/(2*param('geometry.pin_radius'))",
    "xi0": X("const('src/composite.rs', 'XI_0')"),
    "xi1": X("const('src/composite.rs', 'XI_1')"),
    "xi_ratio": X("const('src/composite.rs', 'XI_1')/const('src/composite.rs', 'XI_0')"),
    # Moes' rigid-elastic crossing M = 1.18 as the elasticity ratio (4/3π)M²
    "xi_moes": "4/(3*pi)*1.18**2",
    "mono.speeds": X("monotone_in_load(0.01, 100, -55, 120, 50, 200)['speeds']"),
    "mono.temps": X("monotone_in_load(0.01, 100, -55, 120, 50, 200)['temps']"),
    "mono.loads": X("monotone_in_load(0.01, 100, -55, 120, 50, 200)['loads']"),
    "mono.torque": "monotone_in_load(0.01, 100, -55, 120, 50, 200)['torque']",
    "mono.film": "monotone_in_load(0.01, 100, -55, 120, 50, 200)['film']",
    # the largest change in the wrong direction between neighbouring loads outside the transition
    "mono.outside": X("monotone_in_load(0.01, 100, -55, 120, 50, 200)['outside']"),
    "rb_high.tol": X("100*code('tests/one_answer.rs', r'assert!\\(rel\\(fv, f\\) <= ([\\d.]+)')"),
    "rb_high.eps_lo": X("rb_high(100, 3)['eps_lo']"),
    "rb_high.eps_hi": X("rb_high(100, 3)['eps_hi']"),
    "rb_high.worst": Spec("rb_high(100, 3)['worst_pc']", upper=True),
    # the grease against the base oil, 20 °C to -54 °C
    "eta_ratio_m54": "lib('base_oil.viscosity.-54')/lib('base_oil.viscosity.20')",
    "k_ratio_m54": "exp(param('grease.consistency_activation')*(1/(273.15+(-54)) - 1/(273.15+20)))",
    "ty_ratio_m54": "lib('grease.yield_stress_ratio.-54')",
    "oil_activation": Spec("lib('grease.oil_activation.-54')", sig=3),
    "share.25": "lib('grease.apparent_viscosity.25.25')/lib('base_oil.viscosity.25')",
    "share.m54": "lib('grease.apparent_viscosity.25.-54')/lib('base_oil.viscosity.-54')",
    "app_visc_m54_k": Spec("lib('grease.apparent_viscosity.25.-54.k_with_oil')", sig=3),
    "app_visc_m54_both": Spec("lib('grease.apparent_viscosity.25.-54.both_with_oil')", sig=3),
    # the supply layer
    "layer_inverse": X("param('grease.supply_layer_inverse')"),
    "layer_um": X("1e6/param('grease.supply_layer_inverse')"),
    "gamma_s": X("param('starvation.exponent')"),
    "requote_tol": X("code('tests/one_answer.rs', r'prop_assert!\\(rel\\(y, x\\) <= ([\\de.-]+)')"),
    "cold_day_C": X(f"code('tests/complete.rs', r'fn the_cold_day_is_stiffer_than_the_room.*?let cold = Joint::new\\(&at\\(([\\d.]+)\\)\\)') - {C0}"),
    **_supply_table(),
    "rig_w": X("max(point(kN=k, w=4.386, C=c)['journal_weight'] for k in (5, 20, 60) for c in (15, 20, 25))"),
    "supply_exponent": X("param('grease.supply_exponent')"),
    "yield_stress": X("param('grease.yield_stress')"),
    "consistency": X("param('grease.consistency')"),
    "flow_index": X("param('grease.flow_index')"),
    "yield_activation": X("param('grease.yield_activation')"),
    "consistency_activation": X("param('grease.consistency_activation')"),
    "app_visc_m54": "lib('grease.apparent_viscosity.25.-54')",
    "rb_joint.eps_lo": X("rb_through_joint()['eps_lo']"),
    "rb_joint.eps_hi": X("rb_through_joint()['eps_hi']"),
    "rb_joint.worst": Spec("rb_through_joint()['worst_pc']", upper=True),
    **_sensitivity(),
    # What it gives
    "g200w1.T": "point(N=200, w=1)['torque']",
    "g200w1.mu": "point(N=200, w=1)['friction_coefficient']",
    "g200w1.w": "point(N=200, w=1)['journal_weight']",
    "g200w1.h": "1e6*point(N=200, w=1)['film_thickness']",
    "g200w1.pT": "point(N=200, w=1, paper=True)['torque']",
    "g200w1.pmu": "point(N=200, w=1, paper=True)['friction_coefficient']",
    "g200w3.T": "point(N=200, w=3)['torque']",
    "g200w3.mu": "point(N=200, w=3)['friction_coefficient']",
    "g200w3.pT": "point(N=200, w=3, paper=True)['torque']",
    "g100w1.T": "point(N=100, w=1)['torque']",
    "g100w1.pT": "point(N=100, w=1, paper=True)['torque']",
    "g23k.T": "point(kN=23, w=173)['torque']",
    "g23k.petroff": _petroff("kN=23", 173),
    "g23k.pT": "point(kN=23, w=173, paper=True)['torque']",
    "g20k.T": "point(kN=20, w=3)['torque']",
    "g20k.mu": "point(kN=20, w=3)['friction_coefficient']",
    "g20k.pT": "point(kN=20, w=3, paper=True)['torque']",
    "g20k.pmu": "point(kN=20, w=3, paper=True)['friction_coefficient']",
    "g20km20.T": "point(kN=20, w=3, C=-20)['torque']",
    "g20km20.mu": "point(kN=20, w=3, C=-20)['friction_coefficient']",
    "g20km20.pT": "point(kN=20, w=3, C=-20, paper=True)['torque']",
    "g20km20.pmu": "point(kN=20, w=3, C=-20, paper=True)['friction_coefficient']",
    "g20km55.T": "point(kN=20, w=3, C=-55)['torque']",
    "g20km55.mu": "point(kN=20, w=3, C=-55)['friction_coefficient']",
    "paper_min": X(f"const('src/params.rs', 'PAPER_MIN_TEMPERATURE') - {C0}"),
    "g200m20.T": "point(N=200, w=1, C=-20)['torque']",
    "g200m20.mu": "point(N=200, w=1, C=-20)['friction_coefficient']",
    # The grease's yield torque at rest, 20 kN
    "yield.20": "point(kN=20, w=0, C=20)['grease_yield_torque']",
    "yield.m20": "point(kN=20, w=0, C=-20)['grease_yield_torque']",
    "yield.m54": "point(kN=20, w=0, C=-54)['grease_yield_torque']",
    "yield.20.pc": f"100*point(kN=20, w=0, C=20)['grease_yield_torque']/({BREAKAWAY_20KN})",
    "yield.m20.pc": f"100*point(kN=20, w=0, C=-20)['grease_yield_torque']/({BREAKAWAY_20KN})",
    "yield.m54.pc": f"100*point(kN=20, w=0, C=-54)['grease_yield_torque']/({BREAKAWAY_20KN})",
    "breakaway": BREAKAWAY_20KN,
    # Properties checked
    "service_load_min": X("const('src/validity.rs', 'SERVICE_LOAD_MIN')"),
    "service_load_max_MN": X("code('tests/complete.rs', r'log_uniform\\(SERVICE_LOAD_MIN, ([\\de.]+)\\)')/1e6"),
    "service_speed_max": X("const('src/validity.rs', 'SERVICE_SPEED_MAX')"),
    "service_t_min": X(f"const('src/validity.rs', 'SERVICE_TEMPERATURE_MIN') - {C0}"),
    "service_t_max": X(f"const('src/validity.rs', 'SERVICE_TEMPERATURE_MAX') - {C0}"),
    "warm.grid": X("warming_steps()['grid']"),
    "warm.from": X("warming_steps()['from']"),
    "warm.to": X("warming_steps()['to']"),
    "warm.up": X("warming_steps()['up']"),
    "warm.steps": X("warming_steps()['steps']"),
    "warm.step": X("warming_steps()['step']"),
    "warm.ratio": "warming_steps()['ratio']",
    "warm.load_kN": "warming_steps()['load']/1e3",
    "warm.speed": "warming_steps()['speed']",
    "rig.load_lo_kN": X("code('src/validity.rs', r'pub const LOAD: Range = Range \\{.*?lo: ([^,]+),')/1e3"),
    "rig.load_hi_kN": X("code('src/validity.rs', r'pub const LOAD: Range = Range \\{.*?hi: ([^,]+),')/1e3"),
    "rig.w_max": X("code('tests/one_answer.rs', r'fn the_papers_room_stays_the_papers\\(.*?omega in 0\\.0f64\\.\\.([\\d.]+)')"),
    "rig.t_lo": X(f"code('tests/one_answer.rs', r'fn the_papers_room_stays_the_papers\\(.*?t in ([\\d.]+)f64') - {C0}"),
    "rig.t_hi": X(f"code('tests/one_answer.rs', r'fn the_papers_room_stays_the_papers\\(.*?t in [\\d.]+f64\\.\\.([\\d.]+)\\)') - {C0}"),
    "rig.tolerance_pc": X("100*code('tests/one_answer.rs', r'fn the_papers_room_on_a_grid_through_its_corners.*?assert!\\(worst.0 <= ([\\d.]+)')"),
    "rig.worst_pc": "100*rig_worst()[0]",
    "rig.worst_load_kN": "rig_worst()[1]/1e3",
    "rig.worst_speed": "rig_worst()[2]",
    "rig.worst_C": "rig_worst()[3]",
    "rig.worst_paper_T": "point(N=rig_worst()[1], w=rig_worst()[2], C=rig_worst()[3], paper=True)['torque']",
    "rig.worst_clearance": "point(N=rig_worst()[1], w=rig_worst()[2], C=rig_worst()[3])['clearance_torque']",
    # the earlier grease (K 18 Pa·s^n, τ_y 200 Pa at 20 °C, 4100 K and 3000 K) at the room's worst point
    "rig.old_pc": "100*(point(kN=5, w=4.386, C=15, p={'grease.consistency': 18, 'grease.yield_stress': 200, "
                  "'grease.consistency_activation': 4100, 'grease.yield_activation': 3000})['torque']"
                  "/point(kN=5, w=4.386, C=15, paper=True)['torque'] - 1)",
    "cool.grid": X("cooling_steps()['grid']"),
    "cool.from": X("cooling_steps()['from']"),
    "cool.to": X("cooling_steps()['to']"),
    "cool.down": X("cooling_steps()['down']"),
    "cool.steps": X("cooling_steps()['steps']"),
    "cool.step": X("cooling_steps()['step']"),
    # The paper's model
    "fixture.rows": X("len(column('tests/fixtures/paper_model_main.csv', 'load'))"),
    "fixture.load_lo": X("min(column('tests/fixtures/paper_model_main.csv', 'load'))"),
    "fixture.load_hi_MN": X("max(column('tests/fixtures/paper_model_main.csv', 'load'))/1e6"),
    "fixture.speed_hi": X("max(column('tests/fixtures/paper_model_main.csv', 'speed'))"),
    "fixture.t_lo": X(f"min(column('tests/fixtures/paper_model_main.csv', 'temperature')) - {C0}"),
    "fixture.t_hi": X(f"max(column('tests/fixtures/paper_model_main.csv', 'temperature')) - {C0}"),
}

def _range(name, end):
    return f"code('src/validity.rs', r'pub const {name}: Range = Range \\{{.*?{end}: ([^,]+),')"


VALIDITY = {
    "load_lo_kN": X(_range("LOAD", "lo") + "/1e3"),
    "load_hi_kN": X(_range("LOAD", "hi") + "/1e3"),
    "u_lo": X(_range("SLIDING_SPEED", "lo")),
    "u_hi": _range("SLIDING_SPEED", "hi"),
    "w_max": "const('src/validity.rs', 'MAX_RIG_ANGULAR_SPEED')",
    "pin_mm": X("1e3*const('src/validity.rs', 'PAPER_PIN_RADIUS')"),
    "t_lo_K": X(_range("TEMPERATURE", "lo")),
    "t_hi_K": X(_range("TEMPERATURE", "hi")),
    "t_lo": X(_range("TEMPERATURE", "lo") + f" - {C0}"),
    "t_hi": X(_range("TEMPERATURE", "hi") + f" - {C0}"),
    "t_mid": X(f"({_range('TEMPERATURE', 'lo')} + {_range('TEMPERATURE', 'hi')})/2 - {C0}"),
    "t_half": X(f"({_range('TEMPERATURE', 'hi')} - {_range('TEMPERATURE', 'lo')})/2"),
    "f_lo": X(_range("FREQUENCY", "lo")),
    "f_hi": X(_range("FREQUENCY", "hi")),
    "amp_deg": f"degrees(({_range('STROKE_AMPLITUDE', 'lo')} + {_range('STROKE_AMPLITUDE', 'hi')})/2)",
    "amp_tol": f"({_range('STROKE_AMPLITUDE', 'hi')} - {_range('STROKE_AMPLITUDE', 'lo')})/({_range('STROKE_AMPLITUDE', 'hi')} + {_range('STROKE_AMPLITUDE', 'lo')})",
    "cold_soak": COLD_DAY["cold_soak"],
    "cold_soak_K": X("const('src/validity.rs', 'COLD_SOAK')"),
    "w12": "radians(12)",
    "mu12.20": "point(kN=20, w=radians(12), C=20, paper=True)['friction_coefficient']",
    "paper_min": COLD_DAY["paper_min"],
    "paper_min_K": X("const('src/params.rs', 'PAPER_MIN_TEMPERATURE')"),
    "t_min_K": X("const('src/params.rs', 'MIN_TEMPERATURE')"),
    "t_max_K": X("const('src/params.rs', 'MAX_TEMPERATURE')"),
    "vr_pinjoint": X("code('modelDescription/PinJoint.xml', r'name=\"validity\" valueReference=\"(\\d+)\"')"),
    "vr_rig": X("code('modelDescription/PinJointRig.xml', r'name=\"validity\" valueReference=\"(\\d+)\"')"),
    "rpm_max": "const('src/validity.rs', 'MAX_RIG_ANGULAR_SPEED')*60/(2*pi)",
    "max_temperatures": X("code('crates/cli/src/commands/sweep/mod.rs', r'const MAX_TEMPERATURES: usize = (\\d+);')"),
    # past the model's assumptions
    "capacity": "lib('joint.capacity')",
    "t_min_C": X(f"const('src/params.rs', 'MIN_TEMPERATURE') - {C0}"),
    "t_max_C": X(f"const('src/params.rs', 'MAX_TEMPERATURE') - {C0}"),
    "edge_deg": "degrees(1)",
    "a_over_R_60": "point(kN=60, w=1)['contact_half_width']/param('geometry.pin_radius')",
    "a_at_capacity": "point(kN=60, w=1)['contact_half_width']*sqrt(lib('joint.capacity')/60e3)",
    "class_gap": X(f"abs(-54 - (const('src/params.rs', 'MIN_TEMPERATURE') - {C0}))"),
}

RB_EPS = ["0.1", "0.2", "0.4", "0.6", "0.8", "0.9", "0.97"]


def _rb(table, eps, col):
    """Raimondi & Boyd's value in the tests of src/journal/table.rs (col 1 S, 2 φ°, 3 (R/c)f)."""
    cols = ",\\s*".join(["([\\d.]+)" if i == col else "[\\d.]+" for i in (1, 2, 3)])
    return f"code('src/journal/table.rs', r'const {table}:.*?\\({re.escape(eps)},\\s*{cols}\\)')"


def _rb_worst(table, name, rows, col):
    """The largest deviation of the model from Raimondi & Boyd over `rows` (S, (R/c)f: %; φ: °)."""
    key = {1: "S", 2: "phi_deg", 3: "f"}[col]
    terms = [f"lib('journal.{name}.{key}.{e}')" for e in rows]
    refs = [_rb(table, e, col) for e in rows]
    if col == 2:
        return "max(" + ", ".join(f"abs({t} - {r})" for t, r in zip(terms, refs)) + ")"
    return "100*max(" + ", ".join(f"abs({t}/{r} - 1)" for t, r in zip(terms, refs)) + ")"


GCM_PER_NM = "1e5/9.80665"  # g·cm per N·m (1 gf·cm = 9.80665e-5 N·m)

JOURNAL_BEARING = {
    "nodes": X("code('src/journal/table.rs', r'pub const NODES: usize = (\\d+);')"),
    "eps_first": "1/(1 + exp(const('src/journal/table.rs', 'LOGIT_END')))",
    "eps_last": "1/(1 + exp(-const('src/journal/table.rs', 'LOGIT_END')))",
    "grid_theta": X("code('src/journal/reynolds.rs', r'const TABLE: Grid = Grid \\{ n_theta: (\\d+)')"),
    "grid_zeta": X("code('src/journal/reynolds.rs', r'const TABLE: Grid = Grid \\{[^}]*n_zeta: (\\d+)')"),
    "ld_min_inv": X("1/const('src/journal/table.rs', 'LD_MIN')"),
    "ld_max": X("const('src/journal/table.rs', 'LD_MAX')"),
    "ld_max_gap": "100*abs(lib('journal.ld_max.S.0.1')/lib('journal.long.S.0.1') - 1)",
    **{f"rb.{k}.{e}": _rb("RB_LD1", e, c) for e in RB_EPS for k, c in (("S", 1), ("phi", 2), ("f", 3))},
    **{f"m.S.{e}": f"lib('journal.ld1.S.{e}')" for e in RB_EPS},
    **{f"m.phi.{e}": f"lib('journal.ld1.phi_deg.{e}')" for e in RB_EPS},
    **{f"m.f.{e}": f"lib('journal.ld1.f.{e}')" for e in RB_EPS},
    "rb1.S": _rb_worst("RB_LD1", "ld1", RB_EPS, 1),
    "rb1.phi": _rb_worst("RB_LD1", "ld1", RB_EPS, 2),
    "rb1.f": _rb_worst("RB_LD1", "ld1", RB_EPS, 3),
    "rb24.S": f"max({_rb_worst('RB_LD_HALF', 'ld_half', RB_EPS[:6], 1)}, {_rb_worst('RB_LD_QUARTER', 'ld_quarter', RB_EPS[:6], 1)})",
    "rb24.phi": f"max({_rb_worst('RB_LD_HALF', 'ld_half', RB_EPS[:6], 2)}, {_rb_worst('RB_LD_QUARTER', 'ld_quarter', RB_EPS[:6], 2)})",
    "rb24.f": f"max({_rb_worst('RB_LD_HALF', 'ld_half', RB_EPS[:6], 3)}, {_rb_worst('RB_LD_QUARTER', 'ld_quarter', RB_EPS[:6], 3)})",
    "long.S": "lib('journal.long.S.0.1')",
    "long.phi": "lib('journal.long.phi_deg.0.1')",
    "grid_conv": X("100*code('src/journal/table.rs', r'assert!\\(\\(s1.sommerfeld / s4.sommerfeld - 1.0\\).abs\\(\\) < ([\\d.]+)')"),
    "gauss_nodes": X("code('src/clearance/integrals.rs', r'const GAUSS12: \\[\\(f64, f64\\); (\\d+)\\]')"),
    "rule.0.9": Spec("max(lib('clearance.rule_error.0.3'), lib('clearance.rule_error.0.9'))", upper=True),
    "rule.0.99": Spec("lib('clearance.rule_error.0.99')", upper=True),
    "rule.0.999": Spec("lib('clearance.rule_error.0.999')", upper=True),
    "rule.0.9999": Spec("lib('clearance.rule_error.0.9999')", upper=True),
    "t_ref": X(T_REF),
    "yield_stress": COLD_DAY["yield_stress"],
    "consistency": COLD_DAY["consistency"],
    "flow_index": COLD_DAY["flow_index"],
    "yield_activation": COLD_DAY["yield_activation"],
    "consistency_activation": COLD_DAY["consistency_activation"],
    "supply_exponent": COLD_DAY["supply_exponent"],
    "app_visc_20": Spec("lib('grease.apparent_viscosity.25.20')", rel=0.1),
    "app_visc_m54": COLD_DAY["app_visc_m54"],
    "rig.tolerance_pc": COLD_DAY["rig.tolerance_pc"],
    "rig.old_pc": COLD_DAY["rig.old_pc"],
    "rig.t_lo": COLD_DAY["rig.t_lo"],
    "ty_m54_kPa": "1e-3*lib('grease.yield_stress.-54')",
    "k_m54_kPa": "1e-3*lib('grease.consistency.-54')",
    **{k: COLD_DAY[k] for k in ("layer_inverse", "layer_um", "k_ratio_m54", "eta_ratio_m54", "share.25", "share.m54",
                                "app_visc_m54_k", "app_visc_m54_both")},
    "ty_ratio": "lib('grease.yield_stress_ratio.-54')",
    "d1478.54.lo": "lib('grease.d1478_torque.-54/0.2')",
    "d1478.54.hi": "lib('grease.d1478_torque.-54/2')",
    "d1478.73.lo": "lib('grease.d1478_torque.-73/0.2')",
    "d1478.73.hi": "lib('grease.d1478_torque.-73/2')",
    "d1478.54.lo.gcm": Spec(f"lib('grease.d1478_torque.-54/0.2')*{GCM_PER_NM}", sig=2),
    "d1478.54.hi.gcm": Spec(f"lib('grease.d1478_torque.-54/2')*{GCM_PER_NM}", sig=2),
    "d1478.73.lo.gcm": Spec(f"lib('grease.d1478_torque.-73/0.2')*{GCM_PER_NM}", sig=2),
    "d1478.73.hi.gcm": Spec(f"lib('grease.d1478_torque.-73/2')*{GCM_PER_NM}", sig=3),
    "eta.40": "1e3*lib('base_oil.viscosity.40')",
    "eta.100": "1e3*lib('base_oil.viscosity.100')",
    "eta.m54": "lib('base_oil.viscosity.-54')",
    "eta.m73": "1e-3*lib('base_oil.viscosity.-73')",
    **{f"cl.y.{e}": f"lib('clearance.yield.-54.Ey.{e}')" for e in (2440, 3440, 4440)},
    **{f"cl.p.{e}": f"lib('clearance.power.-54.EK.{e}')" for e in (3906, 4906, 5906)},
    "cl.b.m54": "lib('clearance.base.-54')",
    "cl.y.20": "lib('clearance.yield.20')",
    "cl.p.20": "lib('clearance.power.20')",
    "cl.b.20": "lib('clearance.base.20')",
    "joint_T_20kN": "point(kN=20, w=0.1/param('geometry.pin_radius'))['torque']",
    "cl.share.20": "100*(lib('clearance.yield.20') + lib('clearance.power.20') + lib('clearance.base.20'))"
                   "/point(kN=20, w=0.1/param('geometry.pin_radius'))['torque']",
    "tab.near": "lib('clearance.table_error.near')",
    "tab.mid": "lib('clearance.table_error.to_0.99999')",
    "tab.beyond": "lib('clearance.table_error.beyond')",
    "tab.gap": "(1 - 0.99999)*1e6*(param('geometry.bush_radius') - param('geometry.pin_radius'))",
    "clearance_um": X("1e6*(param('geometry.bush_radius') - param('geometry.pin_radius'))"),
}

PAGES = {
    "docs/cold-day.md": COLD_DAY,
    "docs/validity.md": VALIDITY,
    "docs/journal-bearing.md": JOURNAL_BEARING,
}
