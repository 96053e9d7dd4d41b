//! Logging through the host's `fmi2CallbackLogger`, by category.
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

use super::types::{Fmi2CallbackLogger, Fmi2ComponentEnvironment, Status};
use std::ffi::{c_char, c_int, c_void, CString};

/// FMI 3.0 `fmi3LogMessageCallback(instanceEnvironment, status, category, message)`.
pub type Fmi3LogMessageCallback = unsafe extern "C" fn(*mut c_void, c_int, *const c_char, *const c_char);

/// Where messages go: the FMI 2.0 logger (variadic, `#vr#` references), the FMI 3.0 one
/// (plain text), or nowhere (FMI 3.0 allows a NULL `logMessage`).
#[derive(Debug, Clone, Copy)]
enum Sink {
    Fmi2(Fmi2CallbackLogger),
    Fmi3(Fmi3LogMessageCallback),
    None,
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

    /// The `description` attribute of the category in the modelDescription.
    pub fn description(self) -> &'static str {
        match self {
            Category::Events => "Life-cycle events: initialization, termination, reset, FMU state get/set",
            Category::StatusWarning => "Messages returned with status fmi2Warning",
            Category::StatusDiscard => "Messages returned with status fmi2Discard",
            Category::StatusError => "Messages returned with status fmi2Error (on by default)",
            Category::StatusFatal => "Messages returned with status fmi2Fatal (on by default)",
            Category::All => "Every FMI function call with its arguments",
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
    callback: Sink,
    env: Fmi2ComponentEnvironment,
    instance_name: CString,
    enabled: u8,
}

impl Logger {
    /// The FMI 2.0 logger: messages go to `callback` with `env` as its first argument and
    /// `instance_name`; `logging_on` is `loggingOn` of `fmi2Instantiate`.
    pub fn new(callback: Fmi2CallbackLogger, env: Fmi2ComponentEnvironment, instance_name: &str, logging_on: bool) -> Self {
        let mut l = Logger { callback: Sink::Fmi2(callback), env, instance_name: c_text(instance_name), enabled: 0 };
        l.set_all(logging_on);
        l
    }

    /// The FMI 3.0 logger (`logMessage` may be NULL: then nothing is logged).
    pub fn new_fmi3(callback: Option<Fmi3LogMessageCallback>, env: *mut c_void, instance_name: &str, logging_on: bool) -> Self {
        let sink = callback.map_or(Sink::None, Sink::Fmi3);
        let mut l = Logger { callback: sink, env, instance_name: c_text(instance_name), enabled: 0 };
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

    /// Send `message` in category `c` with `status`, if that category is on.
    pub fn log(&self, status: Status, c: Category, message: &str) {
        if self.is_enabled(c) {
            self.emit(status, c, message);
        }
    }

    fn emit(&self, status: Status, c: Category, message: &str) {
        let category = c_text(c.name());
        // Numbers in the short round-trip form however the message was built (no 309 digits).
        let message = crate::fmt::short_numbers(message);
        match self.callback {
            Sink::Fmi2(cb) => {
                // '#' introduces a value-reference reference in FMI 2.0 messages; "##" is a literal '#'.
                let msg = c_text(&message.replace('#', "##"));
                // SAFETY: the callback was checked non-NULL at instantiation; all strings are
                // NUL-terminated and outlive the call; the message goes through "%s".
                unsafe {
                    cb(self.env, self.instance_name.as_ptr(), status.c(), category.as_ptr(), c"%s".as_ptr(), msg.as_ptr());
                }
            }
            Sink::Fmi3(cb) => {
                // FMI 3.0 messages carry no instance name: it is prefixed.
                let msg = c_text(&format!("[{}] {message}", self.instance_name.to_string_lossy()));
                // SAFETY: non-NULL callback from the host; the strings outlive the call.
                unsafe { cb(self.env, status.c(), category.as_ptr(), msg.as_ptr()) }
            }
            Sink::None => {}
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
    use super::show;

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
