//! `pinjoint params`: print the complete parameter file (defaults, or a file's values filled up).

use crate::common::ParamsArg;
use crate::common::load_rig_config;
use crate::error::Result;
use crate::output::to_stdout;
use clap::Args;

#[derive(Args, Debug)]
#[command(
    about = "Print the complete parameter file (TOML, SI units)",
    long_about = "Print the complete parameter file: every key of Tables 1-3 of the paper plus the \
boundary friction coefficient, in SI units, with symbol, unit and meaning as comments.\n\
What it prints loads back unchanged. With --params, prints that file's values with every \
missing key filled in by its default. With --rig, adds the [rig] section of the simulated test rig \
(`pinjoint cycle`; constants and their reasoning in src/rig/params.rs).\n\n\
Examples:\n  \
pinjoint params > my-joint.toml        # start a parameter file, then edit it\n  \
pinjoint point --load 20000 --rpm 10 --params my-joint.toml\n  \
pinjoint params --rig > rig.toml       # model and rig, for `pinjoint cycle --params rig.toml`\n  \
pinjoint params --reference-temperature 313.15 > at40C.toml   # the same joint quoted at 40 C"
)]
/// Arguments of `pinjoint params` (its `--help` text is the `#[command]` attribute's).
// The field docs are the --help text, where `[rig]`/`[lubricant]` name TOML sections, not
// intra-doc links; rewording them would change --help.
#[allow(rustdoc::broken_intra_doc_links)]
pub struct ParamsCmd {
    /// --params and --temperature: the file (and temperature) whose values are printed.
    #[command(flatten)]
    pub params: ParamsArg,
    /// Also print the [rig] section (the file then suits `pinjoint cycle --params`)
    #[arg(long)]
    pub rig: bool,
    /// Quote the joint at this reference temperature, in K (a data sheet's 40 °C = 313.15 K):
    /// η0 and α by Roelands' temperature relation, the grease's yield stress and consistency
    /// by their Arrhenius laws and its supply layer by its viscosity law are moved there, so
    /// every property at every temperature, and every answer, stays the same
    #[arg(long, value_name = "K", allow_negative_numbers = true)]
    pub reference_temperature: Option<f64>,
}

/// Runs `pinjoint params`: prints the parameter file (with --rig, the rig section too) to
/// standard output. Fails if --params cannot be read or holds invalid values.
pub fn run(cmd: &ParamsCmd) -> Result<()> {
    let requote = |p: &pinjoint::Params| match cmd.reference_temperature {
        Some(t) => p.requoted_at(t).map_err(crate::error::CliError::Params),
        None => Ok(*p),
    };
    let text = if cmd.rig {
        let mut config = load_rig_config(cmd.params.params.as_ref())?;
        config.model = requote(&config.model)?;
        config.to_toml_string()
    } else {
        requote(&cmd.params.load()?)?.to_toml_string()
    };
    to_stdout(|w| w.write_all(text.as_bytes()))
}
