//! The position loop linearised about a slip ([`Loop`]) and its matrix exponential
//! ([`Propagator`]), for `Method::Dopri5Dense`: the steady and free responses of
//! `rig/steady.rs` and the Lawson form of `rig/lawson.rs` are built on them.
//!
//! e^{τA} is taken in modal form, V diag(e^{λₖτ}) V⁻¹, with A's eigenvalues from nalgebra's
//! Schur form (polished by Newton on the characteristic polynomial) and eigenvectors
//! (1, λ, Jλ² − dλ) read from A's rows.

use super::state::State;
use super::params::RigParams;
use nalgebra::{Complex, Matrix3, Vector3};

/// The loop linearised about a slip: θ̇ = ω, J ω̇ = T_a − s·T_c + d·ω,
/// τ_s Ṫ_a = K_p(θ_cmd − θ) + K_d(θ̇_cmd − ω) − T_a, with d the friction torque's slope in the
/// speed, negated (d = −∂(μRP)/∂|ω|: a friction falling with speed gives d > 0), and the
/// eigenvalues of its matrix A (on the (θ, ω, T_a) part), when they are distinct and decay.
/// A function of the rig's parameters and d alone, so it can be kept for a load.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Loop {
    /// d (N·m·s/rad).
    pub damping: f64,
    /// J (kg·m²).
    inertia: f64,
    /// A's eigenvalues: a real one, then a conjugate pair as (λ, λ̄) or two more real ones;
    /// None when two are (nearly) equal or one does not decay (no free response is then
    /// subtracted).
    lambda: Option<[Complex<f64>; 3]>,
    /// A itself, row-major.
    a: [[f64; 3]; 3],
}

impl Loop {
    /// The loop of `rig` with the friction slope `damping` (N·m·s/rad).
    pub fn new(rig: &RigParams, damping: f64) -> Self {
        let (j, tau, kp, kd) = (rig.inertia, rig.servo_time_constant, rig.position_gain, rig.velocity_gain);
        let a = [[0.0, 1.0, 0.0], [0.0, damping / j, 1.0 / j], [-kp / tau, -kd / tau, -1.0 / tau]];
        let m = nalgebra::Matrix3::from_fn(|r, c| a[r][c]);
        let lambda = m
            .iter()
            .all(|x| x.is_finite())
            .then(|| m.try_schur(1e-14, 200))
            .flatten()
            .map(|sc| sc.complex_eigenvalues())
            .map(|l| {
                // Polished by Newton on det(sI − A) = s³ + c₂s² + c₁s + c₀ (the Schur iteration
                // stops at 1e-14·‖A‖, and ‖A‖ ≈ K_p/τ_s is large): to round-off.
                let (c2, c1, c0) = (1.0 / tau - damping / j, (kd - damping) / (tau * j), kp / (tau * j));
                [l[0], l[1], l[2]].map(|mut x| {
                    for _ in 0..3 {
                        let (p, dp) = (((x + c2) * x + c1) * x + c0, (x * 3.0 + 2.0 * c2) * x + c1);
                        if dp.norm() > 0.0 {
                            x -= p / dp;
                        }
                    }
                    x
                })
            })
            .filter(|l| {
                let size = l.iter().map(|x| x.norm()).fold(0.0, f64::max);
                (0..3).all(|k| l[k].is_finite() && l[k].re < 0.0 && (0..k).all(|i| (l[k] - l[i]).norm() > 1e-6 * size))
            });
        Self { damping, inertia: j, lambda, a }
    }

    /// Whether its free response decays (distinct eigenvalues with negative real parts).
    pub fn decays(&self) -> bool {
        self.lambda.is_some()
    }

    /// A·x on the (θ, ω, T_a) part.
    #[inline]
    pub fn apply_matrix(&self, x: &[f64; 3]) -> [f64; 3] {
        std::array::from_fn(|r| self.a[r][0] * x[0] + self.a[r][1] * x[1] + self.a[r][2] * x[2])
    }

    /// A's eigenvalues when they are distinct and decay.
    pub fn eigenvalues(&self) -> Option<[Complex<f64>; 3]> {
        self.lambda
    }
}

/// e^{τL}: e^{τA} on the (θ, ω, T_a) part of a state, the identity on W, D and t.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Propagator {
    lambda: [Complex<f64>; 3],
    /// For each mode, the earlier mode it is the conjugate of (its exponential is reused).
    conjugate_of: [Option<usize>; 3],
    v_re: Matrix3<f64>,
    v_im: Matrix3<f64>,
    vinv_re: Matrix3<f64>,
    vinv_im: Matrix3<f64>,
}

/// The modal factors e^{λₖτ} of one e^{τA}.
pub(crate) type Modal = [Complex<f64>; 3];

impl Propagator {
    /// The propagator of the loop `lin`, None when its free response does not decay
    /// ([`Loop::decays`]) or its eigenvector matrix is singular.
    pub fn new(lin: &Loop) -> Option<Self> {
        let (lambda, inertia) = (lin.eigenvalues()?, lin.inertia);
        let d = lin.damping;
        let v = Matrix3::from_fn(|r, c| {
            let l = lambda[c];
            [Complex::new(1.0, 0.0), l, l * l * inertia - l * d][r]
        });
        // Inverted balanced (rows scaled to 1; their sizes are 1, |λ| and J|λ|², far apart):
        // V⁻¹ = (SV)⁻¹S with S = diag(1/row size).
        let rows = Vector3::from_fn(|r, _| (0..3).map(|c| v[(r, c)].norm()).fold(0.0, f64::max));
        if !rows.iter().all(|x| x.is_finite() && *x > 0.0) {
            return None;
        }
        let balanced = Matrix3::from_fn(|r, c| v[(r, c)] / rows[r]);
        let inverse = balanced.try_inverse()?;
        let vinv = Matrix3::from_fn(|r, c| inverse[(r, c)] / rows[c]);
        let conjugate_of = std::array::from_fn(|k| (0..k).find(|&i| lambda[i].im != 0.0 && lambda[i] == lambda[k].conj()));
        let p = Self {
            lambda,
            conjugate_of,
            v_re: v.map(|x| x.re),
            v_im: v.map(|x| x.im),
            vinv_re: vinv.map(|x| x.re),
            vinv_im: vinv.map(|x| x.im),
        };
        (p.v_re.iter().chain(p.v_im.iter()).chain(p.vinv_re.iter()).chain(p.vinv_im.iter()).all(|x| x.is_finite())).then_some(p)
    }

    /// The largest decay rate −Re λ of A's modes (1/s).
    pub fn fastest_decay(&self) -> f64 {
        self.lambda.iter().map(|l| -l.re).fold(0.0, f64::max)
    }

    /// The factors of e^{τA}.
    #[inline]
    pub fn modal(&self, tau: f64) -> Modal {
        self.per_mode(|l| {
            let m = crate::numerics::fast_math::exp(l.re * tau);
            if l.im == 0.0 {
                Complex::new(m, 0.0)
            } else {
                let (s, c) = crate::numerics::fast_math::sin_cos(l.im * tau);
                Complex::new(m * c, m * s)
            }
        }, |x| x.conj())
    }

    /// `value(λₖ)` for each mode, a conjugate mode's as `conj` of its partner's.
    #[inline]
    fn per_mode<T: Copy + Default>(&self, value: impl Fn(Complex<f64>) -> T, conj: impl Fn(T) -> T) -> [T; 3] {
        let mut out = [T::default(); 3];
        for k in 0..3 {
            out[k] = match self.conjugate_of[k] {
                Some(i) => conj(out[i]),
                None => value(self.lambda[k]),
            };
        }
        out
    }

    /// e^{τL} x, with `e` = [`Self::modal`](τ).
    #[inline]
    pub fn apply(&self, e: &Modal, x: &State) -> State {
        let b = Vector3::new(x[0], x[1], x[2]);
        let (q_re, q_im) = (self.vinv_re * b, self.vinv_im * b);
        let s_re = Vector3::from_fn(|k, _| q_re[k] * e[k].re - q_im[k] * e[k].im);
        let s_im = Vector3::from_fn(|k, _| q_re[k] * e[k].im + q_im[k] * e[k].re);
        let out = self.v_re * s_re - self.v_im * s_im;
        State::from([out[0], out[1], out[2], x[3], x[4], x[5]])
    }

    /// e^{τL} x.
    pub fn propagate(&self, tau: f64, x: &State) -> State {
        self.apply(&self.modal(tau), x)
    }

    /// ∫₀^θ e^{(θ−σ)hL} G(σ) dσ·h for the cubic G(σ) = Σⱼ gⱼσʲ: h Σⱼ j!·θ^{j+1}·φ_{j+1}(θhL)gⱼ
    /// (exponential quadrature), with φ₀(μ) = e^μ, φ_{j+1}(μ) = (φⱼ(μ) − 1/j!)/μ per mode
    /// (their Taylor series below |μ| = 1/2, where the recurrence would cancel); on W, D, t
    /// (L = 0) h Σⱼ gⱼθ^{j+1}/(j+1).
    pub fn quadrature(&self, theta: f64, h: f64, g: &[State; 4]) -> State {
        let w = self.per_mode(
            |l| {
                let phi = phis(l * (theta * h));
                let (mut fact, mut pow) = (1.0, theta);
                std::array::from_fn::<_, 4, _>(|j| {
                    if j > 0 {
                        fact *= j as f64;
                    }
                    let v = phi[j + 1] * (fact * pow);
                    pow *= theta;
                    v
                })
            },
            |w| w.map(|x| x.conj()),
        );
        let mut s_re = Vector3::zeros();
        let mut s_im = Vector3::zeros();
        let mut rest = [0.0; 3];
        let mut pow = theta;
        for (j, gj) in g.iter().enumerate() {
            let b = Vector3::new(gj[0], gj[1], gj[2]);
            let (q_re, q_im) = (self.vinv_re * b, self.vinv_im * b);
            for k in 0..3 {
                let c = w[k][j];
                s_re[k] += q_re[k] * c.re - q_im[k] * c.im;
                s_im[k] += q_re[k] * c.im + q_im[k] * c.re;
            }
            for i in 0..3 {
                rest[i] += gj[3 + i] * pow / (j + 1) as f64;
            }
            pow *= theta;
        }
        let out = self.v_re * s_re - self.v_im * s_im;
        State::from([out[0], out[1], out[2], rest[0], rest[1], rest[2]]) * h
    }

    /// ∫₀^τ e^{sL} x ds = τ·φ₁(τL)x: L⁻¹(e^{τL} − I)x on the (θ, ω, T_a) part, τx on the rest.
    /// Per mode (e^{λτ} − 1)/λ, formed without cancellation as τ·e^{λτ/2}·sinhc(λτ/2)... in
    /// its real form: e^{a+ib} − 1 = expm1(a)·cos b − 2 sin²(b/2) + i·e^a·sin b.
    pub fn integral(&self, tau: f64, x: &State) -> State {
        let w = self.per_mode(
            |l| {
                let (a, b) = (l.re * tau, l.im * tau);
                // (e^{λτ} − 1)/λ; below |λτ| = 1e-8 its series τ(1 + λτ/2).
                if a * a + b * b < 1e-16 {
                    Complex::new(tau, 0.0) * (Complex::new(1.0, 0.0) + l * (0.5 * tau))
                } else {
                    let (sb, cb) = b.sin_cos();
                    let sh = (0.5 * b).sin();
                    Complex::new(a.exp_m1() * cb - 2.0 * sh * sh, a.exp() * sb) / l
                }
            },
            |x| x.conj(),
        );
        let mut out = self.apply(&w, x);
        for i in 3..6 {
            out[i] = tau * x[i];
        }
        out
    }
}

/// φ₀(μ) … φ₄(μ).
fn phis(mu: Complex<f64>) -> [Complex<f64>; 5] {
    let one = Complex::new(1.0, 0.0);
    if mu.norm() < 0.5 {
        // φⱼ(μ) = Σₘ μᵐ/(m + j)!, to m = 18 (remainder below 0.5¹⁹/19! ≈ 2e-23).
        std::array::from_fn(|j| {
            let mut term = one;
            for i in 1..=j {
                term /= i as f64;
            }
            let mut sum = term;
            for m in 1..=18 {
                term = term * mu / (m + j) as f64;
                sum += term;
            }
            sum
        })
    } else {
        let mut out = [one; 5];
        out[0] = mu.exp();
        let mut fact = 1.0;
        for j in 0..4 {
            out[j + 1] = (out[j] - one / fact) / mu;
            fact *= (j + 1) as f64;
        }
        out
    }
}
