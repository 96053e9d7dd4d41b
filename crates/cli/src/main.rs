//! The `pinjoint` binary; the commands are in the `pinjoint_cli` library.

fn main() -> std::process::ExitCode {
    pinjoint_cli::main()
}
