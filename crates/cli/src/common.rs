//! Pieces shared by the subcommands: the `--params` flag, speed flags (rad/s or rpm),
//! the result columns of CSV output, number formatting and the rig's operating region.

use super::error::{CliError, Result};
use clap::Args;
use pinjoint::rig::RigConfig;
use pinjoint::{Joint, OperatingPoint, Params};
use std::f64::consts::PI;
use std::path::PathBuf;
pub use super::numbers::{readable, trimmed};

/// rad/s per rpm.
pub const RAD_S_PER_RPM: f64 = 2.0 * PI / 60.0;

/// The paper's rig experiments (section 4.4): ±40° sine strokes at up to 1 Hz under 5–60 kN.
pub const RIG_AMPLITUDE_DEG: f64 = 40.0;
/// Highest stroke frequency of the paper's rig experiments, in Hz.
pub const RIG_MAX_FREQUENCY_HZ: f64 = 1.0;
/// Radial load range of the paper's rig experiments (lowest, highest), in N: the checked load
/// range of the validity envelope ([`pinjoint::validity::LOAD`]).
pub const RIG_LOAD_RANGE_N: (f64, f64) = (pinjoint::validity::LOAD.lo, pinjoint::validity::LOAD.hi);
/// The paper's simulated range (section 3.2): 1 to 800 rpm.
pub const PAPER_RPM_RANGE: (f64, f64) = pinjoint::paper::SPEED_RANGE_RPM;

/// Peak angular velocity of the fastest rig stroke, 2π f A (≈ 4.39 rad/s ≈ 41.9 rpm): the
/// checked speed range of the validity envelope on the paper's pin
/// ([`pinjoint::validity::MAX_RIG_ANGULAR_SPEED`]).
pub fn rig_peak_speed() -> f64 {
    pinjoint::validity::MAX_RIG_ANGULAR_SPEED
}

/// A note for a figure's title when the lubricant temperature `t` (K) is outside the
/// validity envelope's checked 15–25 °C (every point then is an extrapolation, or below 0 °C
/// with the paper's model, `paper`, known to give too low a μ; above the grease's upper
/// service temperature of `params`, outside the model's assumptions); empty inside.
pub fn temperature_note(params: &Params) -> String {
    let (t, paper) = (params.lubricant.temperature, params.model.paper);
    match pinjoint::validity::Edges::new(params).of_point(pinjoint::validity::LOAD.lo, 0.0, t, paper) {
        pinjoint::Validity::Checked => String::new(),
        pinjoint::Validity::Extrapolation => format!("; T = {} K outside the checked 15-25 C: extrapolation everywhere", readable(t)),
        pinjoint::Validity::KnownWrong => format!("; T = {} K below 0 C with the paper's model: μ known to be too LOW everywhere (no grease)", readable(t)),
        pinjoint::Validity::Outside => format!("; T = {} K above the grease's upper service temperature: outside the model's assumptions everywhere", readable(t)),
    }
}

/// The `--params FILE` (and `--temperature`) options shared by every command that evaluates the
/// model.
#[derive(Args, Debug, Clone)]
// The field docs are the --help text, where `[rig]`/`[lubricant]` name TOML sections, not
// intra-doc links; rewording them would change --help.
#[allow(rustdoc::broken_intra_doc_links)]
pub struct ParamsArg {
    /// Parameter file (TOML, SI units; any subset of keys, the rest keep the paper's values).
    /// `pinjoint params` prints a complete one to start from.
    #[arg(long, value_name = "FILE")]
    pub params: Option<PathBuf>,
    /// Lubricant temperature, in K (kelvin; 293.15 K = 20 °C): overrides the file's
    /// [lubricant] temperature. η0 and α follow Roelands' temperature relation from their
    /// values at [lubricant] reference_temperature (default 293.15 K, where Table 3 holds).
    #[arg(long, value_name = "K", allow_negative_numbers = true)]
    pub temperature: Option<f64>,
}

/// Set the lubricant temperature (K) of `p` from a command-line value, validated as the
/// parameter `lubricant.temperature`.
pub fn set_temperature(p: &mut Params, t: Option<f64>) -> Result<()> {
    if let Some(t) = t {
        p.lubricant.temperature = t;
        p.validate().map_err(CliError::Params)?;
    }
    Ok(())
}

impl ParamsArg {
    /// The parameters: the file's (missing keys keep the paper's values) or the defaults, with
    /// --temperature applied. Fails if the file cannot be read or parsed, or a value is invalid.
    pub fn load(&self) -> Result<Params> {
        let mut p = match &self.params {
            None => Params::default(),
            Some(path) => {
                let text = read_param_file(path)?;
                Params::from_toml_str(&text).map_err(|source| CliError::ParamFile { path: path.clone(), source })?
            }
        };
        set_temperature(&mut p, self.temperature)?;
        Ok(p)
    }
    /// The joint built from [`ParamsArg::load`]'s parameters; fails if they are inconsistent (the
    /// error names the file when there is one).
    pub fn joint(&self) -> Result<Joint> {
        let params = self.load()?;
        Joint::new(&params).map_err(|source| match &self.params {
            Some(path) => CliError::ParamFile { path: path.clone(), source },
            None => CliError::Params(source),
        })
    }
}

/// Largest parameter file read (a complete one is ~3 kB): `/dev/zero` or a huge file given as
/// `--params` is an error, not an unbounded read.
pub const MAX_PARAM_FILE_BYTES: u64 = 1 << 20;

/// The text of a parameter file, at most [`MAX_PARAM_FILE_BYTES`].
pub fn read_param_file(path: &std::path::Path) -> Result<String> {
    use std::io::Read;
    let rerr = |source: std::io::Error| CliError::Read { path: path.to_path_buf(), source };
    let file = std::fs::File::open(path).map_err(rerr)?;
    let mut bytes = Vec::new();
    file.take(MAX_PARAM_FILE_BYTES + 1).read_to_end(&mut bytes).map_err(rerr)?;
    if bytes.len() as u64 > MAX_PARAM_FILE_BYTES {
        return Err(rerr(std::io::Error::other(format!("larger than {MAX_PARAM_FILE_BYTES} bytes: not a parameter file"))));
    }
    String::from_utf8(bytes).map_err(|e| rerr(std::io::Error::new(std::io::ErrorKind::InvalidData, e)))
}

/// A value given on the command line must be finite.
pub fn finite(name: &str, value: f64, unit: &str) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(CliError::Invalid(format!("{name} = {value} {unit} is not a finite number")))
    }
}

/// A value given on the command line must be finite and > 0.
pub fn positive(name: &str, value: f64, unit: &str) -> Result<f64> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(CliError::Invalid(format!("{name} = {value} {unit} is invalid: it must be a finite number > 0 {unit}")))
    }
}

/// `n` values from `lo` to `hi` (both included), evenly spaced in log.
pub fn log_space(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    if n == 1 {
        return vec![lo];
    }
    let (a, b) = (lo.ln(), hi.ln());
    (0..n)
        .map(|i| match i {
            0 => lo,
            _ if i == n - 1 => hi,
            _ => (a + (b - a) * i as f64 / (n - 1) as f64).exp(),
        })
        .collect()
}

/// `n` values from `lo` to `hi` (both included), evenly spaced.
pub fn lin_space(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    if n == 1 {
        return vec![lo];
    }
    (0..n).map(|i| if i == n - 1 { hi } else { lo + (hi - lo) * i as f64 / (n - 1) as f64 }).collect()
}

/// The model's outputs in CSV files, after the input columns (SI units). The h_min columns
/// (an extension) and `validity` come last so that the earlier columns keep their positions.
pub const RESULT_COLUMNS: [&str; pinjoint::record::NAMES.len()] = pinjoint::record::NAMES;

/// A csv writer error as an io::Error that keeps its kind (so a closed pipe stays a
/// `BrokenPipe`, which ends the program quietly).
pub fn csv_io(e: csv::Error) -> std::io::Error {
    match e.into_kind() {
        csv::ErrorKind::Io(e) => e,
        other => std::io::Error::other(format!("{other:?}")),
    }
}

/// A CSV table into `w`: the `header` record, then one record per row (each field text:
/// numbers through [`exact`]), with the csv crate's defaults. The one CSV writer of the
/// commands' whole-file outputs (the figures, `stribeck`, `map`; [`crate::output::write_csv`]
/// writes one to a file); `sweep` and `cycle` stream theirs record by record.
pub fn csv_table<H, R>(w: &mut dyn std::io::Write, header: H, rows: impl IntoIterator<Item = R>) -> std::io::Result<()>
where
    H: IntoIterator,
    H::Item: AsRef<[u8]>,
    R: IntoIterator,
    R::Item: AsRef<[u8]>,
{
    let mut wtr = csv::Writer::from_writer(w);
    wtr.write_record(header).map_err(csv_io)?;
    for row in rows {
        wtr.write_record(row).map_err(csv_io)?;
    }
    wtr.flush()
}

/// A number in CSV: the shortest text that parses back to the same f64 (never rounded).
pub fn exact(v: f64) -> String {
    super::exact::exact_string(v)
}

/// The values of [`RESULT_COLUMNS`] for one point, at full precision.
pub fn result_fields(op: &OperatingPoint) -> [String; pinjoint::record::NAMES.len()] {
    pinjoint::record::COLUMNS.map(|c| match c.value {
        pinjoint::record::Value::Number(f) => exact(f(op)),
        pinjoint::record::Value::Regime => op.regime.as_str().to_string(),
        pinjoint::record::Value::Validity => op.validity.as_str().to_string(),
    })
}

/// The model and rig parameters of a file (model sections + `[rig]`), or the defaults.
pub fn load_rig_config(path: Option<&PathBuf>) -> Result<RigConfig> {
    match path {
        None => Ok(RigConfig::default()),
        Some(path) => {
            let text = read_param_file(path)?;
            RigConfig::from_toml_str(&text).map_err(|source| CliError::ParamFile { path: path.clone(), source })
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rig_peak_speed_is_about_42_rpm() {
        assert!((rig_peak_speed() / RAD_S_PER_RPM - 41.888).abs() < 1e-3);
    }

    #[test]
    fn spaces_hit_their_ends_exactly() {
        let v = log_space(0.01, 1000.0, 6);
        assert_eq!((v[0], v[5]), (0.01, 1000.0));
        assert!((v[2] - 1.0).abs() < 1e-12);
        assert_eq!(lin_space(5e3, 60e3, 12)[1], 10e3);
    }

    #[test]
    fn exact_round_trips_and_readable_rounds() {
        for v in [0.1 + 0.2, 1e-300, 123456.789e10, -2.5e-7] {
            assert_eq!(exact(v).parse::<f64>().unwrap(), v);
        }
        assert_eq!(readable(0.118871234), "0.118871");
        assert_eq!(readable(20000.0), "20000");
        assert_eq!(readable(3.31024e-6), "3.31024e-6");
        assert_eq!(readable(4.134e-4), "4.134e-4");
    }
}
