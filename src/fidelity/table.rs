//! The `table` level: the Stribeck map tabulated once over the envelope and interpolated
//! bicubically in (ln P, ln |ω|).
//!
//! # What is tabulated
//! The map is steep in its natural variables: across the mixed → full-film transition the
//! asperity share 1/γ2 falls from ~10⁻² to 10⁻²² within a third of a decade of speed (the
//! solver's logit y = ln(x1/x2) grows like ω² there), so μ = μ_f + μ_c/γ2 has a corner
//! that no polynomial of modest degree follows. The table therefore holds three smooth
//! functions of (ln P, ln |ω|) and rebuilds the outputs from them exactly:
//!
//! * `μ_f`, the fluid (Bair–Winer) part of μ — smooth (∝ ω in boundary, saturating in
//!   full film);
//! * `y`, the load sharing's logit (floored at [`LOGIT_FLOOR`]) — smooth: ≈ constant in deep
//!   boundary, growing like ω² through the transition and in full film, where it reaches
//!   10⁶; a cubic follows it to a relative error ~h⁴ (a tenth of a decade per cell changes it by
//!   a few per cent), and where it is large its error does not matter (below);
//! * `h_c`.
//!
//! and then `x1 = 1/(1 + e^{−y})`, `x2 = 1/(1 + e^{y})` (the smaller one as e^{−|y|} times the
//! larger, without cancellation), `μ = μ_f + μ_c·x2`, `T = μ·R·P`, `λ = h_c/σ`. The sigmoid,
//! evaluated exactly, carries the corner; an error δy moves μ by `μ_c·x1·x2·δy`, which
//! vanishes both in boundary and in full film (where y is large, so its absolute error is:
//! x1·x2 ≈ e^{−y} more than makes up for it). Tabulating s = asinh y instead (of order ten
//! everywhere) took one exponential and a division more per evaluation (y = sinh s). Its grids,
//! against these: 66 × 169 against 62 × 161 for the batch benchmark's envelope (1e-4),
//! 232 × 197 against 80 × 160 at 262.9 K over 10–100 N (1e-3), 66 × 211 against 80 × 224 for
//! the paper's model at 1e-5; and at 343 K over 5–60 kN (1e-4) a 5 × 14 table whose error on
//! fresh points, 2.0e-4, exceeded its bound (a 6 × 17 table now, 2.0e-5 within 3.5e-5).
//! (Tabulating ln μ_f and ln h_c instead gave the same grid sizes on the envelopes tried, but
//! costs two more exponentials per call; μ_f and h_c vary by less than a few decades over an
//! envelope and their relative error is what the refinement measures.)
//!
//! # Interpolation
//! A uniform grid in x = ln P and z = ln |ω| covers the envelope exactly (the envelope
//! ends are nodes), plus two rings of ghost nodes outside it. At every node the three
//! values come from the complete solve (warm-started along each row); the slopes ∂/∂x,
//! ∂/∂z and ∂²/∂x∂z come from fourth-order central differences of the node values; each
//! cell stores the 3 × 16 power coefficients of its bicubic Hermite patches
//! (the private `hermite` module), so that an evaluation is two logarithms, an index computation,
//! three Horner evaluations and an exponential (the sigmoid's). The patches share
//! values and slopes at the nodes, so the interpolant is C¹ across cells (no jumps for an
//! adaptive integrator to trip on).
//!
//! # Error control
//! The error of a cubic Hermite patch falls like h⁴ and is largest near the middle of a
//! cell. After each build the table is compared with the complete solve at the centre of
//! *every* cell, at the midpoint of every boundary cell's outer side (one-sided slopes there)
//! and at random points of the envelope; the largest error over those (relative
//! in μ, torque and h_c; absolute in the shares) is the measured error. The grid is refined
//! until `SAFETY × measured ≤ tolerance`, i.e. the measured error is at most half the
//! tolerance; the table advertises min(tolerance, `BOUND_FACTOR × measured`). Each axis is
//! refined separately: the fourth differences Δ⁴ of the node values along x and along z
//! (≈ h⁴·∂⁴/∂x⁴, weighted by how much each tabulated variable moves μ, h_c and the shares)
//! split the measured error between the two directions, and each step is chosen from the
//! h⁴ law so that each direction contributes half the target.
//!
//! # Cells answered by the complete solve
//! The complete model's map has kinks along curves that no grid of [`MAX_CELLS`] resolves at a
//! tight tolerance: where the cold-supplied film bounds the fluid's share to 0 at a finite speed
//! (logit −∞ on one side, a steep non-analytic rise of 1/γ1 on the other), and where the journal
//! weight's smoothstep reaches 1 (C², so the cubic's error falls like h³ only). When the next
//! grid would exceed the budget, the cells whose centre error exceeds half the tolerance, and
//! their eight neighbours, answer with the complete solve instead
//! ([`StribeckTable::solved_cells`]; at most [`MAX_SOLVED_SHARE`] of the cells, else the
//! table is refused); the remaining cells are measured again (every centre, random points) and
//! must meet the same rule, so the advertised bound holds for the interpolated cells as before
//! and the solved cells are the complete solve itself. (At 262.9 K over 10–100 N ×
//! 0.0714–7.14 rad/s and tolerance 10⁻³: 294 of 45 704 cells.)
//!
//! # Slow joints: the speeds below the envelope, down to rest
//! A held or creeping joint moves at speeds far below any envelope's lowest (10⁻⁶ rad/s and
//! less), where the model has a known limit: as ω → 0 the film carries nothing (the logit
//! falls like ln ω, the fluid share like ω) and the torque tends to the rest state's, μ_c·R·P
//! plus the grease's yield torque (the complete model; eq. 11 with μ = μ_c for the paper's),
//! as a power of ω (the default joint: ΔT/T ≈ 2.7·10⁻⁵ at 10⁻⁶ rad/s, 2.7·10⁻⁷ at 10⁻¹¹ rad/s,
//! ∝ ω^0.2). So the table also covers (0, speed_min): below a floor where the rest state is
//! within half the refinement target of the complete solve at every decade down to three below
//! it (measured at 17 loads), the rest state answers; between the floor and speed_min a second
//! table, built and measured as this one (in ln |ω| the approach to the limit is an
//! exponential, smooth and cheap to tabulate). Both errors join the table's measured report,
//! so the advertised bound covers them (`StribeckTable::speed_floor`,
//! `TableStats::low_speed_cells`). Where no floor is found within [`LOW_SPEED_DECADES`]
//! decades, or the low table cannot be built, the complete solve answers there, as before.

use super::check::{CheckRng, ErrorReport};
use super::envelope::{solve_at, Envelope};
use super::error::FidelityError;
use super::evaluation::{regime_from_shares, Evaluation, Source};
use super::hermite::{bicubic, bicubic_coefficients, bicubic_pair, central_slope, fourth_difference};
use super::rest::RestTable;
use crate::composite::RestYield;
use crate::joint::Joint;
use serde::Serialize;

/// Refinement target: the table is refined until `SAFETY` × the largest error measured on
/// the check points is within the tolerance.
pub const SAFETY: f64 = 2.0;
/// Advertised bound = min(tolerance, `BOUND_FACTOR` × the largest measured error). The check
/// points (cell centres and random points) can miss a cell's true maximum by a little: a
/// bound of 2× measured was once exceeded by 4 % on points the table had not checked
/// (3.37e-5 against 3.24e-5, 5–60 kN × 0.01–10 rad/s at 1e-4), hence twice the margin.
pub const BOUND_FACTOR: f64 = 4.0;
/// Largest table, in cells (each cell holds 3 × 16 coefficients, 384 bytes).
pub const MAX_CELLS: usize = 1 << 16;
/// Random check points per build, besides every cell centre.
pub const RANDOM_CHECKS: usize = 256;
/// Largest share of the cells that may answer with the complete solve when the budget is
/// reached ([`StribeckTable::solved_cells`]); beyond it the table is refused.
pub const MAX_SOLVED_SHARE: f64 = 0.25;
/// Initial grid step in ln P and ln |ω|.
const INITIAL_STEP: f64 = 0.5;

/// One cell: the bicubic coefficients of μ_f and the logit y interleaved (`friction[i]` is
/// coefficient i of each: evaluated together, a pair per operation, [`bicubic_pair`]), then
/// those of h_c.
#[derive(Debug, Clone, Copy)]
#[repr(C, align(64))]
struct Cell {
    friction: [[f64; 2]; 16],
    film: [f64; 16],
}

impl Cell {
    /// The cell of the patches of μ_f, y and h_c (power coefficients, [`bicubic_coefficients`]).
    fn new([mu_f, y, film]: [[f64; 16]; 3]) -> Self {
        Cell { friction: std::array::from_fn(|i| [mu_f[i], y[i]]), film }
    }
}

/// What a table build cost and produced.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TableStats {
    /// Cells along ln P.
    pub load_cells: usize,
    /// Cells along ln |ω|.
    pub speed_cells: usize,
    /// Refinement passes.
    pub passes: usize,
    /// Complete solves at the table nodes, all passes.
    pub node_solves: usize,
    /// Complete solves at the check points (every cell centre and random points), all passes.
    pub check_solves: usize,
    /// Cells of the 1-D rest table.
    pub rest_cells: usize,
    /// Cells the grid could not resolve within [`MAX_CELLS`] and that answer with the
    /// complete solve instead (0 when the whole envelope is interpolated).
    pub solved_cells: usize,
    /// Wall time of the build, s (measured with `std::time::Instant`), the low speeds' included.
    pub build_seconds: f64,
    /// Cells (along ln P times along ln |ω|) of the table of the speeds below the envelope's,
    /// from [`TableStats::speed_floor`] up ([`StribeckTable`]'s section on slow joints; 0 when
    /// it was not built).
    pub low_speed_cells: usize,
    /// The speed |ω| (rad/s) below which a moving joint is answered by the rest state (the
    /// model's ω → 0 limit, within the measured error there); 0 when the low speeds are not
    /// covered.
    pub speed_floor: f64,
}

/// The Stribeck map over an envelope, interpolated bicubically in (ln P, ln |ω|).
#[derive(Debug, Clone)]
pub struct StribeckTable {
    x0: f64,
    inv_hx: f64,
    nx: usize,
    z0: f64,
    inv_hz: f64,
    nz: usize,
    /// nx − 1 and nz − 1, the last cell's indices, as floats.
    last_x: f64,
    last_z: f64,
    cells: Vec<Cell>,
    /// Per cell: answered by the complete solve (empty when no cell is).
    solve: Vec<bool>,
    envelope: Envelope,
    mu_c: f64,
    radius: f64,
    roughness: f64,
    rest: RestTable,
    rest_yield: RestYield,
    report: ErrorReport,
    stats: TableStats,
    /// The tolerance the table was built for (caps the advertised bound).
    tolerance: f64,
    /// The speeds below the envelope's, down to rest (None: not covered, the complete solve
    /// answers there).
    low: Option<Box<LowSpeeds>>,
}

/// The speeds between rest and the envelope's lowest (see "Slow joints" in the module doc): a
/// table over [floor, speed_min] and, below the floor, the rest state.
#[derive(Debug, Clone)]
struct LowSpeeds {
    table: StribeckTable,
    floor: f64,
}

/// Decades below the envelope's lowest speed searched for the floor of the rest state.
pub const LOW_SPEED_DECADES: i32 = 14;
/// Loads (uniform in ln P, the ends included) at which the rest state is measured against
/// the complete solve at each candidate floor and below it.
const FLOOR_LOADS: usize = 17;

/// The logit below which the table holds [`LOGIT_FLOOR`]: x1 = e^y < 4.3e-18 there, below any
/// tolerance in the shares and in μ. A moving joint whose film is bounded (the complete
/// model's cold supply in the journal's region, a starved inlet) can have its fluid carry
/// nothing (logit −∞) at a finite speed; the floor keeps the tabulated y finite there.
pub const LOGIT_FLOOR: f64 = -40.0;

/// The tabulated variables at one solution.
#[inline]
fn variables(op: &crate::OperatingPoint) -> [f64; 3] {
    [op.fluid_friction_coefficient, op.logit.max(LOGIT_FLOOR), op.film_thickness]
}

/// Weights turning errors in the three tabulated variables into errors of the outputs:
/// (1/μ for μ_f, μ_c·x1·x2/μ and x1·x2 for y (dx2/dy = −x1·x2), 1/h_c for h_c).
#[inline]
fn weights(op: &crate::OperatingPoint, mu_c: f64) -> (f64, f64, f64, f64) {
    let mu = op.friction_coefficient;
    let share = op.fluid_load_fraction * op.asperity_load_fraction;
    (1.0 / mu, mu_c * share / mu, share, 1.0 / op.film_thickness)
}

/// A point located in a [`StribeckTable`] ([`StribeckTable::locate_torque`]): its cell and the
/// local coordinates (t, u) ∈ [0, 1]² there, or outside the envelope.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Located {
    cell: usize,
    t: f64,
    u: f64,
}

impl Located {
    /// Outside the envelope (no cell).
    pub const OUTSIDE: Located = Located { cell: usize::MAX, t: 0.0, u: 0.0 };
}

/// Ask the processor to bring the coefficients [`StribeckTable::torque_located`] reads (the
/// first two patches of `cell`, 256 bytes: four cache lines, the cell being aligned to one)
/// into its caches: a hint, no effect on any value; nothing on targets other than x86_64.
#[inline(always)]
fn prefetch_torque_patches(cell: &Cell) {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{_mm_prefetch, _MM_HINT_T0};
        let p = std::ptr::from_ref(&cell.friction).cast::<i8>();
        for line in [0, 64, 128, 192] {
            // SAFETY: a prefetch reads nothing the program sees and cannot fault (it is a
            // hint, dropped for an unmapped address); the address is inside `cell`. SSE, its
            // target feature, is part of every x86_64 target.
            unsafe { _mm_prefetch::<_MM_HINT_T0>(p.wrapping_add(line)) };
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = cell;
}

impl StribeckTable {
    /// Tabulate the map of `joint` over `envelope`, refined until the error measured against
    /// the complete solve, times [`SAFETY`], is at most `tolerance`.
    pub fn build(joint: &Joint, envelope: &Envelope, tolerance: f64) -> Result<Self, FidelityError> {
        Self::build_with(joint, envelope, tolerance, true)
    }

    /// [`Self::build`], covering the speeds below the envelope's down to rest when
    /// `low_speeds` (and when the model allows it within the tolerance: [`Self::cover_low_speeds`]).
    fn build_with(joint: &Joint, envelope: &Envelope, tolerance: f64, low_speeds: bool) -> Result<Self, FidelityError> {
        envelope.validate()?;
        if !(tolerance.is_finite() && tolerance > 0.0) {
            return Err(FidelityError::Tolerance(tolerance));
        }
        let start = std::time::Instant::now();
        let target = tolerance / SAFETY;
        let lx = envelope.load_max.ln() - envelope.load_min.ln();
        let lz = envelope.speed_max.ln() - envelope.speed_min.ln();
        let mut nx = ((lx / INITIAL_STEP).ceil() as usize).max(2);
        let mut nz = ((lz / INITIAL_STEP).ceil() as usize).max(2);
        let rest = RestTable::build(joint, envelope.load_min, envelope.load_max, target)?;
        let (mut node_solves, mut check_solves, mut passes) = (0, 0, 0);
        loop {
            passes += 1;
            let (mut table, ex, ez) = Self::tabulate(joint, envelope, nx, nz, rest.clone())?;
            node_solves += (nx + 5) * (nz + 5);
            let (mut report, cell_errors) = table.check_centres(joint)?;
            check_solves += report.points;
            if SAFETY * report.max() <= tolerance {
                let mut rng = CheckRng::new(0x5eed_0000 + passes as u64);
                report.merge(&table.check_random(joint, &mut rng, RANDOM_CHECKS)?);
                check_solves += RANDOM_CHECKS;
            }
            let mut measured = report.max();
            let met = SAFETY * measured <= tolerance; // false for NaN
            let next = (!met).then(|| next_grid(nx, nz, ex, ez, measured, target));
            if let Some((mx, mz)) = next.filter(|&(mx, mz)| mx * mz > MAX_CELLS) {
                // The budget is reached: the cells the grid does not resolve (a kink of the
                // map along a curve), and their neighbours, answer with the complete solve;
                // the rest is measured again (every centre, random points) and must meet the
                // tolerance as before.
                let solve = unresolved(&cell_errors, nx, nz, target);
                let solved = solve.iter().filter(|&&b| b).count();
                if solved as f64 > MAX_SOLVED_SHARE * (nx * nz) as f64 {
                    return Err(FidelityError::TableTooLarge { tolerance, cells: mx * mz, limit: MAX_CELLS, measured });
                }
                table.solve = solve;
                report = table.check_centres(joint)?.0;
                check_solves += report.points;
                let mut rng = CheckRng::new(0x5eed_1000 + passes as u64);
                report.merge(&table.check_random(joint, &mut rng, RANDOM_CHECKS)?);
                check_solves += RANDOM_CHECKS;
                measured = report.max();
                if SAFETY * measured > tolerance {
                    return Err(FidelityError::TableTooLarge { tolerance, cells: mx * mz, limit: MAX_CELLS, measured });
                }
            }
            if SAFETY * measured <= tolerance {
                let rest_measured = table.rest.measured_error();
                table.report = report;
                table.tolerance = tolerance;
                table.report.film_thickness = table.report.film_thickness.max(rest_measured);
                table.stats = TableStats {
                    load_cells: nx,
                    speed_cells: nz,
                    passes,
                    node_solves,
                    check_solves,
                    rest_cells: table.rest.cells(),
                    solved_cells: table.solve.iter().filter(|&&b| b).count(),
                    build_seconds: 0.0,
                    low_speed_cells: 0,
                    speed_floor: 0.0,
                };
                if low_speeds {
                    table.cover_low_speeds(joint, tolerance);
                }
                table.stats.build_seconds = start.elapsed().as_secs_f64();
                return Ok(table);
            }
            // Not met and within the budget: refine.
            (nx, nz) = next.unwrap_or_else(|| next_grid(nx, nz, ex, ez, measured, target));
        }
    }

    /// Cover the speeds below the envelope's, down to rest, when the model allows it within
    /// the tolerance: the floor is the highest speed speed_min·10⁻ᵏ (k = 1 ..=
    /// [`LOW_SPEED_DECADES`]) at and below which the rest state (μ_c and the grease's yield
    /// torque, the rest table's film) is within half the refinement target of the complete
    /// solve at every one of [`FLOOR_LOADS`] loads, checked at every decade down to three
    /// below the floor; a table over [floor, speed_min] built to the same tolerance answers
    /// above it. The errors measured on both join the table's report (its advertised bound).
    /// When no floor is found, or the low table cannot be built, nothing changes: the
    /// complete solve answers there as before.
    fn cover_low_speeds(&mut self, joint: &Joint, tolerance: f64) {
        let env = self.envelope;
        let half_target = 0.5 * tolerance / SAFETY;
        let (x0, x1) = (env.load_min.ln(), env.load_max.ln());
        let loads: Vec<f64> = (0..FLOOR_LOADS).map(|i| (x0 + (x1 - x0) * i as f64 / (FLOOR_LOADS - 1) as f64).exp().clamp(env.load_min, env.load_max)).collect();
        // The rest state's error at each decade below speed_min (k = 1 ..= DECADES + 3).
        let mut errors = Vec::new();
        let mut reports = Vec::new();
        for k in 1..=LOW_SPEED_DECADES + 3 {
            let omega = env.speed_min * 10f64.powi(-k);
            let mut r = ErrorReport::default();
            for &p in &loads {
                let Ok(op) = solve_at(joint, p, omega, None) else { return };
                let Some(mut e) = self.rest(p) else { return };
                e.angular_velocity = omega;
                r.add(&e, &op);
            }
            self.stats.check_solves += loads.len();
            errors.push(r.max());
            reports.push(r);
        }
        // The highest decade from which every error below (NaN fails) is within half the target.
        let Some(first) = (0..LOW_SPEED_DECADES as usize).find(|&i| errors[i..].iter().all(|&e| e <= half_target)) else { return };
        let floor = env.speed_min * 10f64.powi(-(first as i32 + 1));
        let low_env = Envelope { speed_min: floor, speed_max: env.speed_min, ..env };
        let Ok(table) = Self::build_with(joint, &low_env, tolerance, false) else { return };
        for r in &reports[first..] {
            self.report.merge(r);
        }
        self.report.merge(table.measured());
        let st = *table.stats();
        self.stats.node_solves += st.node_solves;
        self.stats.check_solves += st.check_solves;
        self.stats.passes += st.passes;
        self.stats.low_speed_cells = st.load_cells * st.speed_cells;
        self.stats.speed_floor = floor;
        self.low = Some(Box::new(LowSpeeds { table, floor }));
    }

    /// Solve at the nodes, build the cells; returns the table and the fourth-difference
    /// error indicators along ln P and ln |ω|.
    fn tabulate(joint: &Joint, env: &Envelope, nx: usize, nz: usize, rest: RestTable) -> Result<(Self, f64, f64), FidelityError> {
        let p = joint.params();
        let mu_c = p.friction.boundary_friction_coefficient;
        let (x0, z0) = (env.load_min.ln(), env.speed_min.ln());
        let hx = (env.load_max.ln() - x0) / nx as f64;
        let hz = (env.speed_max.ln() - z0) / nz as f64;
        let (gx, gz) = (nx + 5, nz + 5); // nodes −2 ..= n + 2
        let at = |k: usize, n: usize, v0: f64, h: f64, lo: f64, hi: f64| {
            // Envelope ends exactly, for the nodes on them.
            if k == 2 {
                lo
            } else if k == n + 2 {
                hi
            } else {
                (v0 + (k as f64 - 2.0) * h).exp()
            }
        };
        let mut q = vec![[0.0f64; 3]; gx * gz];
        let mut w = vec![(0.0f64, 0.0f64, 0.0f64, 0.0f64); gx * gz];
        for a in 0..gx {
            let load = at(a, nx, x0, hx, env.load_min, env.load_max);
            let mut guess = None;
            for b in 0..gz {
                let omega = at(b, nz, z0, hz, env.speed_min, env.speed_max);
                let op = solve_at(joint, load, omega, guess)?;
                guess = Some(op.logit);
                q[a * gz + b] = variables(&op);
                w[a * gz + b] = weights(&op, mu_c);
            }
        }
        let idx = |a: usize, b: usize| a * gz + b;
        // Slopes (per unit local coordinate) at nodes a ∈ 1..gx−1, b ∈ 1..gz−1 as needed.
        let mut sx = vec![[0.0f64; 3]; gx * gz];
        let mut sz = vec![[0.0f64; 3]; gx * gz];
        let mut sxz = vec![[0.0f64; 3]; gx * gz];
        for a in 0..gx {
            for b in 2..gz - 2 {
                for v in 0..3 {
                    sz[idx(a, b)][v] = central_slope(q[idx(a, b - 2)][v], q[idx(a, b - 1)][v], q[idx(a, b + 1)][v], q[idx(a, b + 2)][v]);
                }
            }
        }
        for a in 2..gx - 2 {
            for b in 2..gz - 2 {
                for v in 0..3 {
                    sx[idx(a, b)][v] = central_slope(q[idx(a - 2, b)][v], q[idx(a - 1, b)][v], q[idx(a + 1, b)][v], q[idx(a + 2, b)][v]);
                    sxz[idx(a, b)][v] =
                        central_slope(sz[idx(a - 2, b)][v], sz[idx(a - 1, b)][v], sz[idx(a + 1, b)][v], sz[idx(a + 2, b)][v]);
                }
            }
        }
        // Error indicators: weighted fourth differences at the envelope's nodes.
        let (mut ex, mut ez) = (0.0f64, 0.0f64);
        for a in 2..=nx + 2 {
            for b in 2..=nz + 2 {
                let (wf, wsm, wsx, wh) = w[idx(a, b)];
                let ind = |d: [f64; 3]| (wf * d[0].abs() + wsm * d[1].abs()).max(wsx * d[1].abs()).max(wh * d[2].abs());
                let dx: [f64; 3] = std::array::from_fn(|v| fourth_difference(std::array::from_fn(|k| q[idx(a + k - 2, b)][v])));
                let dz: [f64; 3] = std::array::from_fn(|v| fourth_difference(std::array::from_fn(|k| q[idx(a, b + k - 2)][v])));
                ex = ex.max(ind(dx));
                ez = ez.max(ind(dz));
            }
        }
        let mut cells = Vec::with_capacity(nx * nz);
        for i in 0..nx {
            for j in 0..nz {
                let (a, b) = (i + 2, j + 2);
                let corner = |s: &[[f64; 3]], v: usize| {
                    [[s[idx(a, b)][v], s[idx(a, b + 1)][v]], [s[idx(a + 1, b)][v], s[idx(a + 1, b + 1)][v]]]
                };
                cells.push(Cell::new(std::array::from_fn(|v| {
                    bicubic_coefficients(corner(&q, v), corner(&sx, v), corner(&sz, v), corner(&sxz, v))
                })));
            }
        }
        let table = Self {
            x0,
            inv_hx: 1.0 / hx,
            nx,
            z0,
            inv_hz: 1.0 / hz,
            nz,
            last_x: (nx - 1) as f64,
            last_z: (nz - 1) as f64,
            cells,
            solve: Vec::new(),
            envelope: *env,
            mu_c,
            radius: p.geometry.pin_radius,
            roughness: joint.composite_roughness(),
            rest,
            rest_yield: joint.rest_yield(),
            tolerance: f64::INFINITY,
            report: ErrorReport::default(),
            stats: TableStats {
                load_cells: nx,
                speed_cells: nz,
                passes: 0,
                node_solves: 0,
                check_solves: 0,
                rest_cells: 0,
                solved_cells: 0,
                build_seconds: 0.0,
                low_speed_cells: 0,
                speed_floor: 0.0,
            },
            low: None,
        };
        Ok((table, ex / 384.0, ez / 384.0))
    }

    /// Errors at the centre of every interpolated cell and at the outer side's midpoint of every
    /// boundary cell (solves warm-started along each row), and each cell's largest error (0 for the cells answered by the complete solve).
    fn check_centres(&self, joint: &Joint) -> Result<(ErrorReport, Vec<f64>), FidelityError> {
        let mut r = ErrorReport::default();
        let mut errors = vec![0.0; self.nx * self.nz];
        let hx = 1.0 / self.inv_hx;
        let hz = 1.0 / self.inv_hz;
        for i in 0..self.nx {
            let load = (self.x0 + (i as f64 + 0.5) * hx).exp();
            let mut guess = None;
            for j in 0..self.nz {
                if self.solved(i * self.nz + j) {
                    continue;
                }
                let omega = (self.z0 + (j as f64 + 0.5) * hz).exp();
                let op = solve_at(joint, load, omega, guess)?;
                guess = Some(op.logit);
                errors[i * self.nz + j] = r.add(&self.interpolate(load, omega), &op);
            }
        }
        // The envelope's sides: a boundary cell's patch takes one-sided slopes there, and its
        // error peaks on the side, not at the centre (at 343 K over 5–60 kN at 1e-4 a point
        // 3 % inside the lowest load erred by 4.2× the centres' largest error). The midpoint of
        // every boundary cell's outer side is checked too.
        let (x_end, z_end) = (self.x0 + self.nx as f64 * hx, self.z0 + self.nz as f64 * hz);
        for (i, x) in [(0, self.x0), (self.nx - 1, x_end)] {
            let mut guess = None;
            for j in 0..self.nz {
                if self.solved(i * self.nz + j) {
                    continue;
                }
                let (load, omega) = (x.exp(), (self.z0 + (j as f64 + 0.5) * hz).exp());
                let op = solve_at(joint, load, omega, guess)?;
                guess = Some(op.logit);
                let e = r.add(&self.interpolate(load, omega), &op);
                errors[i * self.nz + j] = errors[i * self.nz + j].max(e);
            }
        }
        for (j, z) in [(0, self.z0), (self.nz - 1, z_end)] {
            let mut guess = None;
            for i in 0..self.nx {
                if self.solved(i * self.nz + j) {
                    continue;
                }
                let (load, omega) = ((self.x0 + (i as f64 + 0.5) * hx).exp(), z.exp());
                let op = solve_at(joint, load, omega, guess)?;
                guess = Some(op.logit);
                let e = r.add(&self.interpolate(load, omega), &op);
                errors[i * self.nz + j] = errors[i * self.nz + j].max(e);
            }
        }
        Ok((r, errors))
    }

    /// Whether cell `k` answers with the complete solve.
    #[inline(always)]
    fn solved(&self, k: usize) -> bool {
        !self.solve.is_empty() && self.solve[k]
    }

    /// The cell holding (load, |ω|) and the local coordinates in it.
    #[inline(always)]
    fn locate(&self, load: f64, omega: f64) -> (usize, f64, f64) {
        let fx = (crate::numerics::fast_ln::ln_normal(load) - self.x0) * self.inv_hx;
        let fz = (crate::numerics::fast_ln::ln_normal(omega.abs()) - self.z0) * self.inv_hz;
        // The cell index ⌊f⌋ within 0 ..= n − 1 (a rounding to just below 0 gives cell 0, NaN
        // too: `max` answers 0 for NaN), bounded as a float first.
        let (i, j) = (fx.max(0.0).min(self.last_x), fz.max(0.0).min(self.last_z));
        // SAFETY: i and j are numbers (never NaN, above) in [0, n − 1] with n ≤ MAX_CELLS < 2^32:
        // truncating them to u32 is defined (the checked `as` conversion adds a saturation the
        // values never need).
        let (i, j) = unsafe { (i.to_int_unchecked::<u32>(), j.to_int_unchecked::<u32>()) };
        (i as usize * self.nz + j as usize, fx - f64::from(i), fz - f64::from(j))
    }

    /// Errors at `n` random points of the envelope, uniform in (ln P, ln |ω|).
    fn check_random(&self, joint: &Joint, rng: &mut CheckRng, n: usize) -> Result<ErrorReport, FidelityError> {
        let mut r = ErrorReport::default();
        for _ in 0..n {
            let (load, omega) = self.envelope.at_log_fraction(rng.uniform(), rng.uniform());
            if self.solved(self.locate(load, omega).0) {
                continue; // answered by the complete solve itself
            }
            let op = solve_at(joint, load, omega, None)?;
            r.add(&self.interpolate(load, omega), &op);
        }
        Ok(r)
    }

    /// μ_f, the logit y and the shares (x1, x2) at the local coordinates (t, u) of the cell
    /// `c`: the part of the interpolation every path shares ([`Self::interpolate`],
    /// [`Self::torque`]), so that their μ agrees bit for bit.
    #[inline(always)]
    fn friction_parts(c: &Cell, t: f64, u: f64) -> (f64, f64, f64, f64) {
        let [mu_f, y] = bicubic_pair(&c.friction, t, u);
        // μ_f ≥ 0 always; an interpolated value can only dip below 0 where μ_f ≪ μ.
        let mu_f = mu_f.max(0.0);
        // x1 = 1/(1+e^{−y}), x2 = 1/(1+e^{y}), the small one as e^{−|y|}·(the large one).
        let (x1, x2) = if y <= 0.0 {
            let e = y.exp();
            let x2 = 1.0 / (1.0 + e);
            (e * x2, x2)
        } else {
            let e = (-y).exp();
            let x1 = 1.0 / (1.0 + e);
            (x1, e * x1)
        };
        (mu_f, y, x1, x2)
    }

    /// Interpolate at (load, |ω|) inside the envelope (not checked here).
    #[inline(always)]
    fn interpolate(&self, load: f64, omega: f64) -> Evaluation {
        let (k, t, u) = self.locate(load, omega);
        self.interpolate_at(load, omega, k, t, u)
    }

    /// [`Self::interpolate`] in the cell `k` at its local coordinates (t, u), as
    /// [`Self::locate`] gives them.
    #[inline(always)]
    fn interpolate_at(&self, load: f64, omega: f64, k: usize, t: f64, u: f64) -> Evaluation {
        let c = &self.cells[k];
        let (mu_f, y, x1, x2) = Self::friction_parts(c, t, u);
        let h = bicubic(&c.film, t, u);
        let mu_a = self.mu_c * x2;
        let mu = mu_f + mu_a;
        Evaluation {
            load,
            angular_velocity: omega,
            friction_coefficient: mu,
            torque: mu * self.radius * load,
            film_thickness: h,
            lambda_ratio: h / self.roughness,
            fluid_load_fraction: x1,
            asperity_load_fraction: x2,
            fluid_friction_coefficient: mu_f,
            asperity_friction_coefficient: mu_a,
            logit: y,
            regime: regime_from_shares(x1, x2),
            source: Source::Table,
            first_fallback: false,
        }
    }

    /// The sliding torque T = μ·R·P (N·m) of [`Self::evaluate`] at (`load` > 0, `omega`),
    /// bit for bit its `torque`, and nothing else: the film, the other outputs and the
    /// regime are not computed (two of the three patches, no `Evaluation`). `None` where
    /// [`Self::evaluate`] is. For a caller that needs only the torque (the presliding law's
    /// bound) of a model whose film is not checked against the clearance (the complete
    /// model: see `Evaluator::torque_inside`).
    #[inline]
    pub fn torque(&self, load: f64, omega: f64) -> Option<f64> {
        self.torque_located(load, omega, self.located(load, omega))
    }

    /// Where (`load`, `omega`) falls: its cell and the local coordinates there inside the
    /// envelope, [`Located::OUTSIDE`] elsewhere.
    #[inline(always)]
    fn located(&self, load: f64, omega: f64) -> Located {
        if self.envelope.contains(load, omega) {
            let (cell, t, u) = self.locate(load, omega);
            Located { cell, t, u }
        } else {
            Located::OUTSIDE
        }
    }

    /// [`Self::torque`] in two halves, for a caller with many points: `locate_torque` finds
    /// the cell and asks the processor to bring the coefficients the torque reads (its first
    /// two patches, 256 bytes) into the cache; [`Self::torque_located`] answers. A caller that
    /// locates a few points before answering them lets those loads overlap (a table of
    /// thousands of cells is larger than a core's cache, and points of different joints fall
    /// in unrelated cells).
    #[inline]
    pub fn locate_torque(&self, load: f64, omega: f64) -> Located {
        let q = self.located(load, omega);
        if let Some(cell) = self.cells.get(q.cell) {
            prefetch_torque_patches(cell);
        }
        q
    }

    /// The torque of [`Self::torque`] at (`load` > 0, `omega`) located by
    /// [`Self::locate_torque`] (of this table, at the same point), bit for bit. (A cell this
    /// table does not have is located again.)
    #[inline(always)]
    pub fn torque_located(&self, load: f64, omega: f64, q: Located) -> Option<f64> {
        if q.cell != Located::OUTSIDE.cell {
            let Some(cell) = self.cells.get(q.cell) else {
                return self.torque_relocated(load, omega);
            };
            if self.solved(q.cell) {
                return None;
            }
            let (mu_f, _, _, x2) = Self::friction_parts(cell, q.t, q.u);
            let mu = mu_f + self.mu_c * x2;
            Some(mu * self.radius * load)
        } else if omega == 0.0 {
            self.rest.contains(load).then(|| rest_torque(load, self.mu_c, self.radius, &self.rest_yield))
        } else {
            self.torque_low(load, omega)
        }
    }

    /// [`Self::torque`] below the envelope's speeds: the rest state's torque under the floor,
    /// the low table's above it ([`Self::cover_low_speeds`]); `None` elsewhere.
    #[inline]
    fn torque_low(&self, load: f64, omega: f64) -> Option<f64> {
        let low = self.low.as_deref()?;
        let w = omega.abs();
        if w < low.floor {
            (w > 0.0 && self.rest.contains(load)).then(|| rest_torque(load, self.mu_c, self.radius, &self.rest_yield))
        } else {
            low.table.torque(load, omega)
        }
    }

    /// [`Self::evaluate`] below the envelope's speeds ([`Self::torque_low`]'s answer, whole).
    #[inline]
    fn evaluate_low(&self, load: f64, omega: f64) -> Option<Evaluation> {
        let low = self.low.as_deref()?;
        let w = omega.abs();
        if w < low.floor {
            let mut e = if w > 0.0 { self.rest(load)? } else { return None };
            e.angular_velocity = omega;
            Some(e)
        } else {
            low.table.evaluate(load, omega)
        }
    }

    /// [`Self::torque`], for a point located in another table.
    #[cold]
    #[inline(never)]
    fn torque_relocated(&self, load: f64, omega: f64) -> Option<f64> {
        self.torque(load, omega)
    }

    /// The interpolated point, or `None` outside the envelope and in the cells answered by
    /// the complete solve ([`Self::solved_cells`]). At ω = 0 exactly: the rest state (μ_c
    /// plus the grease's yield torque over R·P, h_c from the rest table) when the load is
    /// inside the range.
    #[inline]
    pub fn evaluate(&self, load: f64, omega: f64) -> Option<Evaluation> {
        if self.envelope.contains(load, omega) {
            // Located once: the cell decides whether the table answers, then interpolates.
            let (k, t, u) = self.locate(load, omega);
            if self.solved(k) {
                return None;
            }
            Some(self.interpolate_at(load, omega, k, t, u))
        } else if omega == 0.0 {
            self.rest(load)
        } else {
            self.evaluate_low(load, omega)
        }
    }

    /// The rest state at `load` (N) from the rest table, or `None` outside the load range.
    #[inline]
    pub fn rest(&self, load: f64) -> Option<Evaluation> {
        let h = self.rest.film(load)?;
        Some(rest_evaluation(load, h, self.mu_c, self.radius, self.roughness, &self.rest_yield, Source::Rest))
    }

    /// Largest errors measured against the complete solve on the check points (every cell
    /// centre, random points; h_c includes the rest table's).
    pub fn measured(&self) -> &ErrorReport {
        &self.report
    }

    /// The advertised bound: min(tolerance, [`BOUND_FACTOR`] × the largest measured error),
    /// and at least the complete solve's [`super::FULL_ERROR_BOUND`] where cells answer with it.
    pub fn error_bound(&self) -> f64 {
        let b = (BOUND_FACTOR * self.report.max()).min(self.tolerance);
        if self.solve.contains(&true) { b.max(super::FULL_ERROR_BOUND) } else { b }
    }

    /// Whether (load, |ω|) inside the envelope lies in a cell answered by the complete solve.
    pub fn solved_at(&self, load: f64, omega: f64) -> bool {
        (self.envelope.contains(load, omega) && self.solved(self.locate(load, omega).0)) || self.low.as_ref().is_some_and(|l| l.table.solved_at(load, omega))
    }

    /// The speed |ω| (rad/s) below which a moving joint is answered by the rest state, and
    /// the low speeds' table above it up to the envelope's (None: the speeds below the
    /// envelope's are not covered; the complete solve answers there).
    pub fn speed_floor(&self) -> Option<f64> {
        self.low.as_ref().map(|l| l.floor)
    }

    /// Cells answered by the complete solve: those the grid did not resolve within
    /// [`MAX_CELLS`], and their neighbours (at most [`MAX_SOLVED_SHARE`] of the cells).
    pub fn solved_cells(&self) -> usize {
        self.stats.solved_cells
    }

    /// Size, passes and cost of the table's build.
    pub fn stats(&self) -> &TableStats {
        &self.stats
    }

    /// The envelope of loads (N) and speeds |ω| (rad/s) the table covers.
    pub fn envelope(&self) -> &Envelope {
        &self.envelope
    }

    /// Memory held by the cells, bytes.
    pub fn size_bytes(&self) -> usize {
        self.cells.len() * std::mem::size_of::<Cell>() + self.low.as_ref().map_or(0, |l| l.table.size_bytes())
    }
}

/// The next grid: the measured error split between the directions by the fourth differences
/// `ex`, `ez`, each step chosen from the h⁴ law so that each direction contributes target/2.
fn next_grid(nx: usize, nz: usize, ex: f64, ez: f64, measured: f64, target: f64) -> (usize, usize) {
    let (ex, ez) = if ex + ez > 0.0 && measured.is_finite() { (ex, ez) } else { (1.0, 1.0) };
    let c = if measured.is_finite() { measured / (ex + ez) } else { 16.0 * target / (ex + ez) };
    let grow = |n: usize, e: f64| {
        let f = (2.0 * c * e / target).powf(0.25) * 1.05;
        ((n as f64 * f.clamp(1.0, 4.0)).ceil() as usize).max(n)
    };
    let (mut mx, mut mz) = (grow(nx, ex), grow(nz, ez));
    if mx == nx && mz == nz {
        if ex >= ez {
            mx = nx + nx.div_ceil(4);
        } else {
            mz = nz + nz.div_ceil(4);
        }
    }
    (mx, mz)
}

/// The cells whose centre error exceeds `target` (NaN included), and their eight neighbours.
fn unresolved(errors: &[f64], nx: usize, nz: usize, target: f64) -> Vec<bool> {
    let mut solve = vec![false; nx * nz];
    for i in 0..nx {
        for j in 0..nz {
            let resolved = errors[i * nz + j] <= target; // false for NaN
            if !resolved {
                for a in i.saturating_sub(1)..(i + 2).min(nx) {
                    for b in j.saturating_sub(1)..(j + 2).min(nz) {
                        solve[a * nz + b] = true;
                    }
                }
            }
        }
    }
    solve
}

/// μ_f (the grease's yield torque at rest over R·P; 0 for the paper's model) and μ = μ_f + μ_c
/// of the rest state at `load` (N): the friction of [`rest_evaluation`], shared with
/// [`rest_torque`] so that both agree bit for bit.
#[inline(always)]
fn rest_friction(load: f64, mu_c: f64, radius: f64, rest_yield: &RestYield) -> (f64, f64) {
    // The grease's yield torque at rest (complete model; 0 for the paper's: μ = μ_c exactly),
    // composed as the complete solve composes it at ω = 0.
    let mu_f = rest_yield.at(load) / (radius * load);
    (mu_f, mu_f + mu_c)
}

/// The torque μ·R·P (N·m) of [`rest_evaluation`] at `load` (N), bit for bit, without its
/// film.
#[inline(always)]
pub(crate) fn rest_torque(load: f64, mu_c: f64, radius: f64, rest_yield: &RestYield) -> f64 {
    rest_friction(load, mu_c, radius, rest_yield).1 * radius * load
}

/// The rest state (ω = 0): 1/γ1 = 0, 1/γ2 = 1, μ = μ_c plus the grease's yield torque over
/// R·P (complete model), film `h`. Also the boundary level's
/// answer at any speed (with `omega` as given).
#[inline(always)]
pub(crate) fn rest_evaluation(load: f64, h: f64, mu_c: f64, radius: f64, roughness: f64, rest_yield: &RestYield, source: Source) -> Evaluation {
    let (mu_f, mu) = rest_friction(load, mu_c, radius, rest_yield);
    Evaluation {
        load,
        angular_velocity: 0.0,
        friction_coefficient: mu,
        torque: mu * radius * load,
        film_thickness: h,
        lambda_ratio: h / roughness,
        fluid_load_fraction: 0.0,
        asperity_load_fraction: 1.0,
        fluid_friction_coefficient: mu_f,
        asperity_friction_coefficient: mu_c,
        logit: f64::NEG_INFINITY,
        regime: crate::Regime::Boundary,
        source,
        first_fallback: false,
    }
}
