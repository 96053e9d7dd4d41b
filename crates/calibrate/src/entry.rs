//! The entry point: records in, the model chosen by the options, long records block-averaged
//! to the sample budget first ([`crate::decimate`]).

use super::decimate::reduce;
use super::error::CalibrationError;
use super::estimates::check_options;
use super::fit::calibrate_core;
use super::options::{Model, Options};
use super::record::{Columns, Record};
use super::result::Calibration;
use super::rig_fit::calibrate_rig;

/// Fit `records` as `options` asks. See the crate documentation for the model.
///
/// Records holding more than `options.max_samples` samples together are block-averaged to
/// that budget first ([`crate::decimate`]); the result's `block_length` and `samples_read` say
/// so.
pub fn calibrate(records: &[Record], options: &Options) -> Result<Calibration, CalibrationError> {
    check_options(options)?;
    let total: usize = records.iter().map(Record::len).sum();
    if total <= options.max_samples {
        return dispatch(records, options);
    }
    let columns: Vec<Columns<'_>> = records.iter().map(Record::columns).collect();
    calibrate_columns(&columns, options)
}

/// [`calibrate`] on borrowed columns (e.g. NumPy arrays): a long record is checked and
/// block-averaged without a copy of every sample.
pub fn calibrate_columns(records: &[Columns<'_>], options: &Options) -> Result<Calibration, CalibrationError> {
    check_options(options)?;
    if records.is_empty() {
        return Err(CalibrationError::NoRecords);
    }
    let total: usize = records.iter().map(Columns::len).sum();
    let (reduced, m) = reduce(records, options.max_samples)?;
    let mut c = dispatch(&reduced, options)?;
    c.samples_read = total;
    c.block_length = m;
    Ok(c)
}

fn dispatch(records: &[Record], options: &Options) -> Result<Calibration, CalibrationError> {
    match options.model {
        Model::Core => calibrate_core(records, options),
        Model::Rig => calibrate_rig(records, options),
    }
}
