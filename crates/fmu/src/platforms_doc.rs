//! The "Platforms" section of both FMUs' `documentation/index.html`: which binaries a
//! release FMU carries, what each needs, and how each was tested (the macOS one is built
//! but not run).

/// HTML of the section, `<h2>` included.
pub const PLATFORMS_HTML: &str = r#"<h2>Platforms</h2>
<p>A release FMU (<code>cargo run --release -p fmu_build -- --platforms all</code>) carries one binary per platform below,
all cross-built on Linux from the same source; the plain <code>fmu_build</code> packs only the build machine's binary.</p>
<table>
<tr><th>folder</th><th>for</th><th>needs</th><th>tested</th></tr>
<tr><td><code>binaries/linux64</code></td><td>Linux x86-64</td>
<td>glibc 2.17 or newer (RHEL/CentOS 7 and later, Ubuntu 14.04+, Debian 8+) and nothing else: no libgcc_s (the unwinder is
linked in), no libstdc++</td>
<td>run: fmpy, the Rust <code>fmi</code> crate, Ecos and C hosts (one under valgrind) on Debian 12</td></tr>
<tr><td><code>binaries/win64</code></td><td>Windows x86-64</td>
<td>Windows 10 or newer; no MinGW runtime DLL (libgcc and winpthreads are linked in)</td>
<td>run under Wine 8 on Linux through a C host, both models: outputs equal the Linux binary's (PinJoint to 1e-12 relative);
not run on Windows itself</td></tr>
<tr><td><code>binaries/darwin64</code></td><td>macOS, one universal binary: x86-64 and arm64 (Apple silicon)</td>
<td>macOS 11 or newer; only <code>libSystem</code></td>
<td><strong>built but not run-tested</strong>: no macOS machine was available; only its exported functions and its load
commands (install name, libraries, minimum OS) are checked</td></tr>
</table>
"#;
