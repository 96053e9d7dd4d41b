//! Numbers for people: the text of numbers in tables, captions, claims and tick labels (the
//! CSV files' exact numbers are `exact`'s).

/// A number for people: 6 significant digits, fixed or scientific as fits.
pub fn readable(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    trimmed(v, 6, 5)
}

/// `v` with trailing zeros trimmed: in fixed notation with `digits` significant digits (at
/// most `digits + 2` decimals) for 1e-3 ≤ |v| < 10^(digits + 1), else in scientific notation
/// with `sci_decimals` decimals in the mantissa. [`readable`] and the plots' tick labels.
pub fn trimmed(v: f64, digits: i32, sci_decimals: usize) -> String {
    let a = v.abs();
    if (1e-3..10f64.powi(digits + 1)).contains(&a) {
        let decimals = (digits - 1 - a.log10().floor() as i32).clamp(0, digits + 2) as usize;
        let s = format!("{v:.decimals$}");
        if s.contains('.') { s.trim_end_matches('0').trim_end_matches('.').to_string() } else { s }
    } else {
        let s = format!("{v:.sci_decimals$e}");
        let (m, e) = s.split_once('e').unwrap_or((&s, "0"));
        let m = if m.contains('.') { m.trim_end_matches('0').trim_end_matches('.') } else { m };
        format!("{m}e{e}")
    }
}

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
