//! Numbers for people: the text of numbers in tables, captions, claims and tick labels (the
//! CSV files' exact numbers are `exact`'s).

/// A number for people: 6 significant digits, fixed or scientific as fits.
pub fn readable(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    trimmed(v, 6, 5)
}

/// `v` with trailing zeros trimmed to `digits` significant digits ([`pinjoint::fmt::trimmed`]:
/// [`readable`] here, the tick labels of the plots there).
pub use pinjoint::fmt::trimmed;

/// A fraction as a percentage with one decimal, e.g. `7.8 %`.
pub fn pct(x: f64) -> String {
    format!("{} %", readable((x * 1000.0).round() / 10.0))
}

/// `x` rounded to `n` significant digits, for reading.
pub fn sig(x: f64, n: i32) -> String {
    if x == 0.0 || !x.is_finite() {
        return readable(x);
    }
    let scale = 10f64.powi(n - 1 - x.abs().log10().floor() as i32);
    readable((x * scale).round() / scale)
}

/// A torque in N·m with one decimal, e.g. `67.2 N·m`.
pub fn nm(x: f64) -> String {
    format!("{} N·m", readable((x * 10.0).round() / 10.0))
}
