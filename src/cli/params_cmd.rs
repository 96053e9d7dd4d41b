//! `pinjoint params`: print the complete parameter file (defaults, or a file's values filled up).

use super::common::ParamsArg;
use super::error::Result;
use super::output::to_stdout;
use clap::Args;

#[derive(Args, Debug)]
#[command(
    about = "Print the complete parameter file (TOML, SI units)",
    long_about = "Print the complete parameter file: every key of Tables 1-3 of the paper plus the \
boundary friction coefficient, in SI units, with symbol, unit and meaning as comments.\n\
What it prints loads back unchanged. With --params, prints that file's values with every \
missing key filled in by its default.\n\n\
Examples:\n  \
pinjoint params > my-joint.toml        # start a parameter file, then edit it\n  \
pinjoint point --load 20000 --rpm 10 --params my-joint.toml"
)]
pub struct ParamsCmd {
    #[command(flatten)]
    pub params: ParamsArg,
}

pub fn run(cmd: &ParamsCmd) -> Result<()> {
    let text = cmd.params.load()?.to_toml_string();
    to_stdout(|w| w.write_all(text.as_bytes()))
}
