//! Logging by category, through the host's log callback of either standard: the version
//! shim wraps its callback (`fmi2CallbackLogger`, `fmi3LogMessageCallback`) in a [`HostLog`],
//! and everything else (categories, the rate limit, number formatting, length bounds) is
//! here, once.
//!
//! Categories (also listed in `<LogCategories>`):
//! - `logEvents`: life-cycle changes (initialization, termination, reset, FMU state);
//! - `logStatusWarning`, `logStatusDiscard`, `logStatusError`, `logStatusFatal`:
//!   messages returned with that status;
//! - `logAll`: every FMI call with its arguments.
//!
//! Debug logging (`loggingOn` of `fmi2Instantiate`/`fmi2SetDebugLogging`) switches the
//! debug categories (events, warnings, discards, all). Error and fatal messages are
//! not debug output: they are reported from instantiation on, unless the host names
//! `logStatusError`/`logStatusFatal` in `fmi2SetDebugLogging` with `loggingOn = false`.
//!
//! Rate limit ([`Repeats`]): a debug message that recurs (the same text with its numbers
//! ignored, in the same category: a flag toggling every step, every `logAll` call line) is logged
//! [`REPEAT_LIMIT`] times, then a line saying further repeats are counted; then one summary
//! line at each power of ten of its count, and a final one at `fmi2Terminate`/`fmi2Reset`
//! ([`Logger::flush_repeats`]). A message repeated n times thus writes at most
//! REPEAT_LIMIT + 2 + log10(n) lines; at most [`REPEAT_KEYS`] distinct messages are counted
//! apart, the rest together. Error and fatal messages are not limited: each goes with a
//! call the host sees fail, and the message is the only place its reason is given.

use super::types::Status;
use std::cell::RefCell;
use std::collections::HashMap;
use std::ffi::{CStr, CString};
use std::fmt::Debug;
use std::rc::Rc;

/// How many times one recurring message is logged before its repeats are only counted.
pub const REPEAT_LIMIT: u64 = 10;

/// How many distinct recurring messages are counted apart (the rest share one count).
pub const REPEAT_KEYS: usize = 256;

/// The counts of the messages logged, by their text with numbers ignored (module doc).
#[derive(Debug, Clone, Default)]
pub struct Repeats {
    /// key → (times seen, the last text, its status and category).
    seen: HashMap<String, (u64, String, Status, Category)>,
}

/// `message` with every run of digits (and a sign, point or exponent inside a number)
/// replaced by `#`: the key under which its repeats are counted.
fn repeat_key(c: Category, message: &str) -> String {
    let mut key = String::with_capacity(message.len() + 8);
    key.push_str(c.name());
    key.push('|');
    let mut in_number = false;
    for ch in message.chars().take(400) {
        let numeric = ch.is_ascii_digit() || (in_number && matches!(ch, '.' | 'e' | 'E' | '-' | '+'));
        if numeric {
            if !in_number {
                key.push('#');
            }
        } else {
            key.push(ch);
        }
        in_number = numeric;
    }
    key
}

/// What to write for one message: nothing, the message, or the message and a note.
enum Verdict {
    Log,
    LogThenNote(u64),
    Summary(u64),
    Quiet,
}

impl Repeats {
    fn see(&mut self, status: Status, c: Category, message: &str) -> Verdict {
        let mut key = repeat_key(c, message);
        if !self.seen.contains_key(&key) && self.seen.len() >= REPEAT_KEYS {
            key = format!("{}|(other messages)", c.name());
        }
        let entry = self.seen.entry(key).or_insert_with(|| (0, String::new(), status, c));
        entry.0 += 1;
        entry.1 = message.to_owned();
        entry.2 = status;
        let n = entry.0;
        if n < REPEAT_LIMIT {
            Verdict::Log
        } else if n == REPEAT_LIMIT {
            Verdict::LogThenNote(n)
        } else if n >= 100 && is_power_of_ten(n) {
            Verdict::Summary(n)
        } else {
            Verdict::Quiet
        }
    }

    /// The messages whose repeats were counted, not logged: (count, last text, status, category); the counts restart.
    fn drain(&mut self) -> Vec<(u64, String, Status, Category)> {
        let mut out: Vec<_> = self.seen.drain().map(|(_, v)| v).filter(|v| v.0 > REPEAT_LIMIT).collect();
        out.sort_by(|a, b| a.1.cmp(&b.1));
        out
    }
}

fn is_power_of_ten(mut n: u64) -> bool {
    while n >= 10 && n.is_multiple_of(10) {
        n /= 10;
    }
    n == 1
}

/// Where messages go: the host's log callback as one standard spells it. The FMI 2.0 shim's
/// sink passes the instance name and escapes `#` (value-reference references); the FMI 3.0
/// one prefixes the instance name (its callback has no argument for it).
pub trait HostLog: Debug {
    /// Pass one message to the host: `status`, the category's name `category`, the message
    /// `message` (already bounded and with short numbers), for the instance `instance_name`.
    fn emit(&self, instance_name: &CStr, status: Status, category: &CStr, message: &str);
}

/// A log category of the FMU (`<LogCategories>` in the modelDescription; module doc).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Category {
    /// `logEvents`: life-cycle changes.
    Events,
    /// `logStatusWarning`: messages returned with `fmi2Warning`.
    StatusWarning,
    /// `logStatusDiscard`: messages returned with `fmi2Discard`.
    StatusDiscard,
    /// `logStatusError`: messages returned with `fmi2Error`.
    StatusError,
    /// `logStatusFatal`: messages returned with `fmi2Fatal`.
    StatusFatal,
    /// `logAll`: every FMI call with its state.
    All,
}

impl Category {
    /// Every category, in the order of `<LogCategories>`.
    pub const ALL: [Category; 6] = [
        Category::Events,
        Category::StatusWarning,
        Category::StatusDiscard,
        Category::StatusError,
        Category::StatusFatal,
        Category::All,
    ];

    /// The category's name in the modelDescription and in `fmi2SetDebugLogging`.
    pub fn name(self) -> &'static str {
        match self {
            Category::Events => "logEvents",
            Category::StatusWarning => "logStatusWarning",
            Category::StatusDiscard => "logStatusDiscard",
            Category::StatusError => "logStatusError",
            Category::StatusFatal => "logStatusFatal",
            Category::All => "logAll",
        }
    }

    /// The `description` attribute of the category in the modelDescription, each status
    /// named by `status_name` (the standard's word for it, e.g. `fmi2Error`).
    pub fn description(self, status_name: fn(Status) -> &'static str) -> String {
        match self {
            Category::Events => "Life-cycle events: initialization, termination, reset, FMU state get/set".to_owned(),
            Category::StatusWarning => format!("Messages returned with status {}", status_name(Status::Warning)),
            Category::StatusDiscard => format!("Messages returned with status {}", status_name(Status::Discard)),
            Category::StatusError => format!("Messages returned with status {} (on by default)", status_name(Status::Error)),
            Category::StatusFatal => format!("Messages returned with status {} (on by default)", status_name(Status::Fatal)),
            Category::All => "Every FMI function call with its arguments".to_owned(),
        }
    }

    /// The category named `name`, or `None` for a name this FMU does not declare.
    pub fn from_name(name: &str) -> Option<Category> {
        Category::ALL.into_iter().find(|c| c.name() == name)
    }

    /// The category of a message returned with `status`.
    pub fn for_status(status: Status) -> Category {
        match status {
            Status::Warning => Category::StatusWarning,
            Status::Discard => Category::StatusDiscard,
            Status::Error => Category::StatusError,
            Status::Fatal => Category::StatusFatal,
            Status::Ok | Status::Pending => Category::Events,
        }
    }

    fn bit(self) -> u8 {
        1 << (self as u8)
    }
}

/// The host's logger and which categories it wants.
#[derive(Debug, Clone)]
pub struct Logger {
    /// The host's callback; `None` logs nothing (FMI 3.0 allows a NULL `logMessage`).
    sink: Option<Rc<dyn HostLog>>,
    instance_name: CString,
    enabled: u8,
    /// The rate limit's counts (module doc).
    repeats: RefCell<Repeats>,
}

impl Logger {
    /// A logger that passes messages to `sink` (`None`: nowhere) for the instance
    /// `instance_name`; `logging_on` is `loggingOn` of the instantiation function.
    pub fn new(sink: Option<Rc<dyn HostLog>>, instance_name: &str, logging_on: bool) -> Self {
        let mut l = Logger { sink, instance_name: c_text(instance_name), enabled: 0, repeats: RefCell::default() };
        l.set_all(logging_on);
        l
    }

    /// `loggingOn` for every category; error and fatal stay on (module doc).
    pub fn set_all(&mut self, on: bool) {
        self.enabled = Category::StatusError.bit() | Category::StatusFatal.bit();
        if on {
            self.enabled |= Category::ALL.iter().fold(0, |b, c| b | c.bit());
        }
    }

    /// Switch category `c` on or off (`fmi2SetDebugLogging` with named categories).
    pub fn set(&mut self, c: Category, on: bool) {
        if on {
            self.enabled |= c.bit();
        } else {
            self.enabled &= !c.bit();
        }
    }

    /// Whether messages of category `c` are passed to the host.
    pub fn is_enabled(&self, c: Category) -> bool {
        self.enabled & c.bit() != 0
    }

    /// Send `message` in category `c` with `status`, if that category is on and the message
    /// is not over its repeat limit (module doc).
    pub fn log(&self, status: Status, c: Category, message: &str) {
        if !self.is_enabled(c) {
            return;
        }
        if status >= Status::Error {
            self.emit(status, c, message);
            return;
        }
        let verdict = self.repeats.borrow_mut().see(status, c, message);
        match verdict {
            Verdict::Log => self.emit(status, c, message),
            Verdict::LogThenNote(n) => {
                self.emit(status, c, message);
                self.emit(status, c, &format!("(the message above was logged {n} times; its further repeats, numbers aside, are counted, not logged: a summary at 100, 1000, ... repeats and at Terminate or Reset)"));
            }
            Verdict::Summary(n) => self.emit(status, c, &format!("(repeated {n} times so far, the last:) {}", crate::fmt::excerpt(message))),
            Verdict::Quiet => {}
        }
    }

    /// The final summary of the messages over their repeat limit (one line each), then the
    /// counts restart: called at `fmi2Terminate`/`fmi3Terminate` and `fmi2Reset`/`fmi3Reset`.
    pub fn flush_repeats(&self) {
        let over = self.repeats.borrow_mut().drain();
        for (n, last, status, c) in over {
            if self.is_enabled(c) {
                self.emit(status, c, &format!("(repeated {n} times in all, the last:) {}", crate::fmt::excerpt(&last)));
            }
        }
    }

    fn emit(&self, status: Status, c: Category, message: &str) {
        let category = c_text(c.name());
        // Numbers in the short round-trip form however the message was built (no 309 digits).
        // And at most about MESSAGE_CHARS characters, whatever input a message quoted.
        let message = crate::fmt::bounded_message(&crate::fmt::short_numbers(message));
        if let Some(sink) = &self.sink {
            sink.emit(&self.instance_name, status, &category, &message);
        }
    }
}

/// A C string of `s`; an interior NUL (which C cannot carry) becomes U+FFFD.
pub fn c_text(s: &str) -> CString {
    CString::new(s.replace('\0', "\u{fffd}")).expect("NULs were replaced")
}

/// A number for messages: plain decimal in the everyday range, scientific
/// notation for very small or very large magnitudes (5e-324, not 323 zeros).
pub fn show(v: f64) -> String {
    crate::fmt::Num(v).to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A flag toggling every step (two alternating messages with changing numbers) for 20 000
    /// steps writes a bounded number of lines, then the summary.
    #[test]
    fn a_toggling_flag_logs_a_bounded_number_of_lines() {
        let mut r = Repeats::default();
        let mut lines = 0;
        for i in 0..20_000u64 {
            let (c, m) = if i % 2 == 0 {
                (Category::Events, format!("validity 2 (known_wrong): temperature {} K is below 273.15 K", 273.1 - i as f64 * 1e-6))
            } else {
                (Category::All, "fmi2DoStep called in state stepComplete".to_string())
            };
            lines += match r.see(Status::Ok, c, &m) {
                Verdict::Log | Verdict::Summary(_) => 1,
                Verdict::LogThenNote(_) => 2,
                Verdict::Quiet => 0,
            };
        }
        // Per message: REPEAT_LIMIT + the note + summaries at 100, 1000, 10 000.
        assert_eq!(lines, 2 * (REPEAT_LIMIT + 1 + 3));
        let left = r.drain();
        assert_eq!(left.len(), 2);
        assert!(left.iter().all(|x| x.0 == 10_000));
        assert!(r.drain().is_empty());
        // Messages that differ in more than numbers are counted apart; beyond REPEAT_KEYS together.
        for i in 0..1000 {
            let _ = r.see(Status::Ok, Category::Events, &format!("message {}", char::from_u32(0x4e00 + i).unwrap()));
        }
        assert_eq!(r.seen.len(), REPEAT_KEYS + 1);
        assert!(is_power_of_ten(1000) && !is_power_of_ten(1001) && is_power_of_ten(1));
    }

    #[test]
    fn numbers_in_messages() {
        assert_eq!(show(5e-324), "5e-324");
        assert_eq!(show(-5e9), "-5000000000");
        assert_eq!(show(0.25), "0.25");
        assert_eq!(show(1e20), "1e20");
        assert_eq!(show(f64::NAN), "NaN");
        assert_eq!(show(-0.0), "-0");
    }
}
