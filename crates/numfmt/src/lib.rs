//! Numbers in messages: the short round-trip form (`1e308`, `2.5e-7`, `20000`, `0.001`), never
//! the 309 digits `{}` gives for 1e308 nor the 300 zeros it gives for 1e-308.
//!
//! [`Num`] formats one value; [`short_numbers`] rewrites every over-long decimal number in a
//! finished message (what the CLI prints and what the FMUs log), so a message built anywhere
//! with `{}` leaves the program in the short form. Both are lossless: Rust prints the shortest
//! digits that parse back to the same `f64`, in either notation.

use std::fmt;

/// An `f64` displayed in the short round-trip form: plain decimal for 1e-4 ≤ |x| < 1e15 (as
/// `{}` prints it), scientific (`{:e}`, shortest round-trip digits) outside; NaN and ±inf as is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Num(pub f64);

impl From<f64> for Num {
    fn from(x: f64) -> Self {
        Num(x)
    }
}

impl fmt::Display for Num {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let x = self.0;
        let a = x.abs();
        if !x.is_finite() || a == 0.0 || (1e-4..1e15).contains(&a) {
            write!(f, "{x}")
        } else {
            write!(f, "{x:e}")
        }
    }
}

/// `message` with every decimal number (digits, at most one point) that [`Num`] writes
/// shorter rewritten in that form (`0.0000005282307976058009` → `5.282307976058009e-7`, 309
/// digits → `1e308`); everything else, including numbers with leading zeros such as `007`,
/// unchanged.
pub fn short_numbers(message: &str) -> String {
    let b = message.as_bytes();
    let mut out = String::with_capacity(message.len());
    let mut i = 0;
    while i < b.len() {
        if b[i].is_ascii_digit() && (i == 0 || !(b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_')) {
            let start = i;
            let mut dot = false;
            while i < b.len() && (b[i].is_ascii_digit() || (b[i] == b'.' && !dot && i + 1 < b.len() && b[i + 1].is_ascii_digit())) {
                dot |= b[i] == b'.';
                i += 1;
            }
            let token = &message[start..i];
            let plain_zeros = token.len() > 1 && token.starts_with('0') && !token.starts_with("0.");
            match token.parse::<f64>() {
                Ok(x) if !plain_zeros && Num(x).to_string().len() < token.len() => out.push_str(&Num(x).to_string()),
                _ => out.push_str(token),
            }
        } else {
            let ch = message[i..].chars().next().unwrap_or('\u{fffd}');
            out.push(ch);
            i += ch.len_utf8().max(1);
        }
    }
    out
}

/// The most characters of an input (a file's line, a key, a value's text) that any message
/// quotes: [`excerpt`].
pub const EXCERPT_CHARS: usize = 200;

/// The most characters of any one error message a front end prints, logs or raises
/// ([`bounded_message`]): a message quoting an [`excerpt`] of its input stays far below it.
pub const MESSAGE_CHARS: usize = 1000;

/// `text` as a message may quote it: unchanged when it has at most [`EXCERPT_CHARS`]
/// characters, else its first [`EXCERPT_CHARS`] characters and how many were left out
/// (`abc… (9999800 more characters)`).
pub fn excerpt(text: &str) -> String {
    match text.char_indices().nth(EXCERPT_CHARS) {
        None => text.to_string(),
        Some((cut, _)) => format!("{}… ({} more characters)", &text[..cut], text[cut..].chars().count()),
    }
}

/// `message` with at most about [`MESSAGE_CHARS`] characters: unchanged when it is that
/// short, else its beginning and its end (where the CLI's usage hint stands) with the number
/// of characters left out between them. The last guard of every front end, whatever a
/// message quoted.
pub fn bounded_message(message: &str) -> String {
    let n = message.chars().count();
    if n <= MESSAGE_CHARS {
        return message.to_string();
    }
    let (head, tail) = (MESSAGE_CHARS * 4 / 5, MESSAGE_CHARS / 10);
    let head_end = message.char_indices().nth(head).map_or(message.len(), |(i, _)| i);
    let tail_start = message.char_indices().nth(n - tail).map_or(message.len(), |(i, _)| i);
    format!("{} … ({} characters left out) … {}", &message[..head_end], n - head - tail, &message[tail_start..])
}

/// `v` with trailing zeros trimmed: in fixed notation with `digits` significant digits (at
/// most `digits + 2` decimals) for 1e-3 ≤ |v| < 10^(digits + 1), else in scientific notation
/// with `sci_decimals` decimals in the mantissa. The numbers for people of the
/// front ends (the CLI's `readable`) and the plots' tick labels (`pinjoint-plot`).
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn excerpt_and_bounded_message_cap_the_length() {
        assert_eq!(excerpt("short"), "short");
        let long = "é".repeat(10 * EXCERPT_CHARS);
        let e = excerpt(&long);
        assert!(e.starts_with(&"é".repeat(EXCERPT_CHARS)) && e.ends_with(&format!("({} more characters)", 9 * EXCERPT_CHARS)), "{e}");
        assert!(e.chars().count() < EXCERPT_CHARS + 30);
        let m = format!("error: {}\nFor more information, try '--help'.", "x".repeat(1_000_000));
        let b = bounded_message(&m);
        assert!(b.chars().count() <= MESSAGE_CHARS + 60 && b.starts_with("error: xxx") && b.ends_with("try '--help'."), "{b}");
        assert_eq!(bounded_message("plain"), "plain");
    }

    #[test]
    fn short_and_round_trip() {
        for (x, s) in [(1e308, "1e308"), (1e-308, "1e-308"), (20e3, "20000"), (0.001, "0.001"), (-2.5e-7, "-2.5e-7"), (5e-324, "5e-324")] {
            assert_eq!(Num(x).to_string(), s);
            assert_eq!(Num(x).to_string().parse::<f64>().unwrap(), x);
        }
        assert_eq!(Num(f64::NAN).to_string(), "NaN");
        assert_eq!(Num(f64::NEG_INFINITY).to_string(), "-inf");
    }

    #[test]
    fn long_numbers_in_messages_are_shortened() {
        let m = format!("load = {} N, radius = {} m, speed = {} rad/s (x1.5, run2)", 1e308, 1e-308, 12.5);
        assert!(m.len() > 600);
        assert_eq!(short_numbers(&m), "load = 1e308 N, radius = 1e-308 m, speed = 12.5 rad/s (x1.5, run2)");
        let m = format!("-{} and 123456789012345678901234567890.5 µs", 2.0f64.powi(200));
        let s = short_numbers(&m);
        assert_eq!(s, format!("-{:e} and 1.2345678901234568e29 µs", 2.0f64.powi(200)));
        assert_eq!(short_numbers("v1.2.3 at 0.000001 s"), "v1.2.3 at 1e-6 s");
        assert_eq!(short_numbers("t = 0.0000005282307976058009 s, 2031616 steps, 007"), "t = 5.282307976058009e-7 s, 2031616 steps, 007");
    }
}
