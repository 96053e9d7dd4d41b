//! Link flags of the FMU binary (the cdylib).
//!
//! FMU hosts unload the binary with dlclose after fmi2FreeInstance (fmpy does). The
//! library's one-time statics (the variable tables behind `fmu::registry`) and Rust's
//! thread-local destructors would then point into unmapped memory: valgrind reported
//! the tables as definitely lost after dlclose (tests/valgrind.sh). `-z nodelete`
//! keeps the library mapped, so a later dlopen gets the same, still valid copy.
fn main() {
    if std::env::var("CARGO_CFG_TARGET_OS").as_deref() == Ok("linux") {
        println!("cargo:rustc-cdylib-link-arg=-Wl,-z,nodelete");
    }
    println!("cargo:rerun-if-changed=build.rs");
}
