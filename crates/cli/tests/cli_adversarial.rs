//! The CLI against an adversarial user (issue 9): outputs that are FIFOs, devices, symlinks,
//! private files or the input itself; inputs that panicked or hung before. Every run has a
//! time limit and must exit 0, 1 or 2 (never 101, never a signal).

use std::os::unix::fs::{FileTypeExt, PermissionsExt};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Duration;

mod cli_support;
use cli_support::{run, run_limited, s, Out};

/// Runs and expects failure (exit code 1) with every `needles` in standard error.
fn fails(args: &[&str], needles: &[&str]) -> Out {
    cli_support::fails(args, None, 1, needles)
}

const INPUT: &str = "# my precious comments\nload,speed\n20000,0.5\n5000,-1\n";

/// A temporary directory holding `in.csv` = [`INPUT`], and that file's path.
fn input_dir() -> (tempfile::TempDir, PathBuf) {
    let d = tempfile::tempdir().unwrap();
    let inp = d.path().join("in.csv");
    std::fs::write(&inp, INPUT).unwrap();
    (d, inp)
}

fn sweep_to(input: &Path, output: &str) -> Out {
    run(&["sweep", "--input", s(input), "--output", output])
}

// ------------------------------------------------------------ output mechanism

#[test]
fn output_equal_to_the_input_is_refused_before_anything_is_read_or_written() {
    let (d, inp) = input_dir();
    // Same path, another spelling, a hard link, a symlink: all the same inode.
    let link = d.path().join("hard.csv");
    std::fs::hard_link(&inp, &link).unwrap();
    let sym = d.path().join("sym.csv");
    std::os::unix::fs::symlink(&inp, &sym).unwrap();
    let other_spelling = format!("{}/./sub/../in.csv", d.path().display());
    std::fs::create_dir(d.path().join("sub")).unwrap();
    for out in [s(&inp).to_string(), other_spelling, s(&link).to_string(), s(&sym).to_string()] {
        let o = sweep_to(&inp, &out);
        assert_eq!(o.code, 1, "{out}: {}", o.stderr);
        assert!(o.stderr.contains("is the input file") && o.stderr.contains(&out) && o.stderr.contains(s(&inp)), "{}", o.stderr);
        assert_eq!(std::fs::read_to_string(&inp).unwrap(), INPUT);
    }
    // The parameter file is an input too.
    let params = d.path().join("p.toml");
    std::fs::write(&params, "[geometry]\npin_radius = 0.028\n").unwrap();
    let o = run(&["sweep", "--input", s(&inp), "--params", s(&params), "--output", s(&params)]);
    assert_eq!(o.code, 1, "{}", o.stderr);
    assert!(o.stderr.contains("is the input file"), "{}", o.stderr);
    assert_eq!(std::fs::read_to_string(&params).unwrap(), "[geometry]\npin_radius = 0.028\n");
    // Commands writing into a directory: a parameter file that is one of their outputs.
    let out = d.path().join("out");
    std::fs::create_dir(&out).unwrap();
    for (cmd, name) in [("stribeck", "stribeck.csv"), ("map", "map.csv"), ("cycle", "cycle.csv")] {
        let p = out.join(name);
        std::fs::write(&p, "[geometry]\npin_radius = 0.028\n").unwrap();
        let mut args = vec![cmd, "--params", s(&p), "--output", s(&out)];
        if cmd == "stribeck" {
            args.extend(["--load", "20000"]);
        }
        if cmd == "cycle" {
            args.extend(["--cycles", "1"]);
        }
        let o = run(&args);
        assert_eq!(o.code, 1, "{cmd}: {}", o.stderr);
        assert!(o.stderr.contains("is the input file"), "{cmd}: {}", o.stderr);
        assert_eq!(std::fs::read_to_string(&p).unwrap(), "[geometry]\npin_radius = 0.028\n");
    }
}

#[test]
fn a_private_file_keeps_its_permissions_and_a_symlink_stays_a_link() {
    let (d, inp) = input_dir();
    let private = d.path().join("private.csv");
    std::fs::write(&private, "old").unwrap();
    std::fs::set_permissions(&private, std::fs::Permissions::from_mode(0o600)).unwrap();
    assert_eq!(sweep_to(&inp, s(&private)).code, 0);
    let meta = std::fs::metadata(&private).unwrap();
    assert_eq!(meta.permissions().mode() & 0o7777, 0o600);
    assert!(std::fs::read_to_string(&private).unwrap().starts_with("load,speed,"));

    let target = d.path().join("target.csv");
    std::fs::write(&target, "old").unwrap();
    std::fs::set_permissions(&target, std::fs::Permissions::from_mode(0o640)).unwrap();
    let link = d.path().join("link.csv");
    std::os::unix::fs::symlink("target.csv", &link).unwrap();
    assert_eq!(sweep_to(&inp, s(&link)).code, 0);
    assert!(std::fs::symlink_metadata(&link).unwrap().file_type().is_symlink(), "the link stays a link");
    assert!(std::fs::read_to_string(&target).unwrap().starts_with("load,speed,"));
    assert_eq!(std::fs::metadata(&target).unwrap().permissions().mode() & 0o7777, 0o640);
    // A dangling link: its target is created.
    let dangling = d.path().join("dangling.csv");
    std::os::unix::fs::symlink("new.csv", &dangling).unwrap();
    assert_eq!(sweep_to(&inp, s(&dangling)).code, 0);
    assert!(std::fs::symlink_metadata(&dangling).unwrap().file_type().is_symlink());
    assert!(std::fs::read_to_string(d.path().join("new.csv")).unwrap().starts_with("load,speed,"));
    // No temporary file is left behind.
    let names: Vec<_> = std::fs::read_dir(d.path()).unwrap().map(|e| e.unwrap().file_name().into_string().unwrap()).collect();
    assert!(names.iter().all(|n| !n.ends_with(".part")), "{names:?}");
}

#[test]
fn a_fifo_is_written_in_place_streaming() {
    let (d, inp) = input_dir();
    let fifo = d.path().join("fifo");
    let ok = Command::new("mkfifo").arg(&fifo).status().unwrap().success();
    assert!(ok, "mkfifo");
    let f2 = fifo.clone();
    let reader = std::thread::spawn(move || std::fs::read_to_string(&f2).unwrap());
    let o = sweep_to(&inp, s(&fifo));
    assert_eq!(o.code, 0, "{}", o.stderr);
    let text = reader.join().unwrap();
    assert!(text.starts_with("load,speed,") && text.lines().count() == 3, "{text}");
    assert!(std::fs::symlink_metadata(&fifo).unwrap().file_type().is_fifo(), "still a FIFO");
}

#[test]
fn dev_null_stays_a_character_device() {
    let (_d, inp) = input_dir();
    let o = sweep_to(&inp, "/dev/null");
    assert_eq!(o.code, 0, "{}", o.stderr);
    let m = std::fs::symlink_metadata("/dev/null").unwrap();
    assert!(m.file_type().is_char_device(), "/dev/null was replaced");
    // /dev/stdout (a link to /proc/self/fd/1): written in place, to our pipe.
    let o = sweep_to(&inp, "/dev/stdout");
    assert_eq!(o.code, 0, "{}", o.stderr);
    assert!(o.stdout.starts_with("load,speed,"), "{}", o.stdout);
    // The directory commands into /dev/null's directory would be refused by the OS, not us:
    // a directory output that is a device is an error naming the path.
    fails(&["stribeck", "--load", "20000", "--output", "/dev/null"], &["/dev/null"]);
    assert!(std::fs::symlink_metadata("/dev/null").unwrap().file_type().is_char_device());
}

// ------------------------------------------------------------ no panics (exit 101 before)

#[test]
fn inputs_that_panicked_exit_1_with_a_message() {
    fails(&["point", "--load", "3e8", "--speed", "1", "--fidelity", "table"], &["capacity"]);
    fails(&["point", "--load", "20000", "--speed", "1", "--fidelity", "table", "--envelope-speed", "1e-3:1e300"], &["envelope"]);
    fails(&["cycle", "--load", "1e9", "--cycles", "1", "--output", "/tmp/pinjoint-adv-none"], &["capacity"]);
    let o = run(&["cycle", "--load", "1e-300", "--cycles", "1", "--output", &std::env::temp_dir().join("pj-adv-tiny").display().to_string()]);
    assert!(o.code == 0 || o.code == 1, "{}", o.stderr);
    if o.code == 1 {
        assert!(o.stderr.contains("load"), "{}", o.stderr);
    }
}

#[test]
fn error_messages_print_short_numbers() {
    let o = fails(&["point", "--load", "1e308", "--speed", "1"], &["1e308"]);
    assert!(!o.stderr.contains("00000000000000000000"), "{}", o.stderr);
    let o = fails(&["point", "--load", "1e-308", "--speed", "1e300", "--fidelity", "table"], &[]);
    assert!(!o.stderr.contains("00000000000000000000"), "{}", o.stderr);
}

#[test]
fn a_negative_load_is_its_magnitude() {
    let a = run(&["point", "--load", "20000", "--speed", "0.5", "--json"]);
    let b = run(&["point", "--load", "-20000", "--speed", "0.5", "--json"]);
    assert_eq!((a.code, b.code), (0, 0), "{}", b.stderr);
    assert_eq!(a.stdout, b.stdout);
}

// ------------------------------------------------------------ parameter files

#[test]
fn hostile_parameter_files_are_errors_naming_the_file() {
    let d = tempfile::tempdir().unwrap();
    let cases: &[(&str, &str, &str)] = &[
        ("empty.toml", "", ""),
        ("nan.toml", "[geometry]\npin_radius = nan\n", "pin_radius"),
        ("huge.toml", "[geometry]\npin_radius = 1e308\n", "pin_radius"),
        // A subnormal radius passes the range check (> 0): the load is then beyond the joint's
        // capacity, an error naming both (not the file).
        // The complete model refuses it with the parameters (its journal bearing's L/D = B/(2R)
        // is infinite); the paper's model at the load (beyond the asperities' capacity).
        ("tiny.toml", "[geometry]\npin_radius = 5e-324\n", "L/D"),
        ("type.toml", "[geometry]\npin_radius = \"big\"\n", "pin_radius"),
        ("dup.toml", "[geometry]\npin_radius = 0.028\npin_radius = 0.03\n", "pin_radius"),
        ("unknown.toml", "[nonsense]\nx = 1\n", "nonsense"),
        ("bomb.toml", &format!("a = {}1{}\n", "[".repeat(5000), "]".repeat(5000)), ""),
        ("binary.toml", "\u{0}\u{1}\u{2}\u{ff}", ""),
    ];
    for (name, text, needle) in cases {
        let p = d.path().join(name);
        std::fs::write(&p, text).unwrap();
        for args in [
            vec!["point", "--load", "20000", "--speed", "1", "--params", s(&p)],
            vec!["cycle", "--cycles", "1", "--params", s(&p), "--output", s(d.path())],
        ] {
            let o = run(&args);
            if *name == "empty.toml" {
                assert_eq!(o.code, 0, "{args:?}: {}", o.stderr);
                continue;
            }
            assert_eq!(o.code, 1, "{args:?}: {}", o.stderr);
            let names_file = *name == "tiny.toml" || o.stderr.contains(s(&p));
            assert!(names_file && o.stderr.contains(needle), "{args:?}: {}", o.stderr);
        }
    }
    // A directory, a missing file, an unreadable one (root reads everything: skipped then).
    fails(&["point", "--load", "1", "--speed", "1", "--params", s(d.path())], &[s(d.path())]);
    fails(&["point", "--load", "1", "--speed", "1", "--params", "/no/such/p.toml"], &["/no/such/p.toml"]);
    fails(&["sweep", "--input", s(d.path())], &[s(d.path())]);
    // An endless or huge file is refused after 1 MiB, not read into memory.
    fails(&["point", "--load", "1", "--speed", "1", "--params", "/dev/zero"], &["/dev/zero", "larger than"]);
    fails(&["cycle", "--cycles", "1", "--params", "/dev/zero", "--output", s(d.path())], &["/dev/zero", "larger than"]);
    let odd = d.path().join("odd name ü\n'$.csv");
    std::fs::write(&odd, INPUT).unwrap();
    let out = d.path().join("out ü\t.csv");
    assert_eq!(run(&["sweep", "--input", s(&odd), "--output", s(&out)]).code, 0);
    assert!(std::fs::read_to_string(&out).unwrap().starts_with("load,speed,"));
}

// ------------------------------------------------------------ bounded work

#[test]
fn rig_parameters_that_hung_or_aborted_end_in_bounded_time() {
    let d = tempfile::tempdir().unwrap();
    // rk4: at 50 Hz one stroke is 0.02 s (1.8e6 RK4 steps of 1.1e-8 s, ~25 s); the first
    // segment used to allocate 50 GB whatever the run length.
    let cases = [
        ("rk4.toml", "[rig]\nmethod = \"rk4\"\nrk4_step = 1.1e-8\nsegment_length = 10\n", "50"),
        ("freq.toml", "[rig]\nfrequency = 1e300\n", "1e300"),
    ];
    for (name, text, f) in cases {
        let p = d.path().join(name);
        std::fs::write(&p, text).unwrap();
        let args = ["cycle", "--cycles", "1", "--frequency", f, "--params", s(&p), "--output", s(d.path())];
        let o = run_limited(&args, None, Duration::from_secs(150));
        assert!(o.code == 0 || o.code == 1, "{name}: {}", o.stderr);
    }
}

#[test]
fn grid_sizes_that_panicked_or_exhausted_memory_are_refused() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().display().to_string();
    fails(&["map", "--loads", "18446744073709551615", "--speeds", "2", "--output", &out], &["loads = 18446744073709551615", "1000"]);
    fails(&["map", "--loads", "100000", "--speeds", "100000", "--output", &out], &["loads = 100000"]);
    fails(&["stribeck", "--load", "20000", "--points", "18446744073709551615", "--output", &out], &["points ="]);
}
