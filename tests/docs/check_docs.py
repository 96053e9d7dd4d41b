#!/usr/bin/env python3
"""Docs that cannot rot: checks README.md, BENCHMARKS.md and docs/*.md against the repository.

    python3 tests/docs/check_docs.py            links, anchors, quoted numbers (no build needed)
    python3 tests/docs/check_docs.py --run      the same, and every example marked runnable
    python3 tests/docs/check_docs.py --api-docs every crate's API front page in target/doc
    python3 tests/docs/check_docs.py --numbers  the tied numbers against the built binary
    python3 tests/docs/check_docs.py --update-numbers  rewrite the tied numbers from it

Checks:
- no generated file (callgrind_*, *.svg) lies at the repository's root: they go to
  benches/results/ (BENCHMARKS.md, checked with the pages, links its pictures there);
- every relative link and image (`[text](path#anchor)`) resolves to a file or folder of the
  repository, and its anchor to a heading of the target page (GitHub's anchor rules: lower
  case, punctuation dropped, spaces to hyphens, `-1`, `-2` for repeats); links to pages
  outside the repository (`../..` past its root) and to absolute paths are refused;
- every fenced block preceded by the line `<!-- runnable -->` runs on the built project and
  exits 0 (`--run`): `sh`/`bash` blocks with bash in a scratch directory, with
  `target/release` and the package's virtualenv first on the PATH and `target` linked into
  the directory; `python` blocks with the package's virtualenv (`.venv-python` or
  $PINJOINT_PY_VENV, as python/run_tests.sh) when they import `pinjoint`, with the FMU
  harness's (`.venv` or $PINJOINT_VENV, as tests/fmu_harness/run.sh) when they import `fmpy`;
- every number in a block between `<!-- numbers from FILE: ... -->` and
  `<!-- end of numbers from FILE -->` is a number that FILE (a generated file, e.g.
  BENCHMARKS.md) contains;
- every number of the pages of numbers_spec.PAGES (docs/cold-day.md, journal-bearing.md,
  validity.md) is tied to the built binary by a tag `<!--=ID-->`, an input of a tied one,
  a citation or marked as not a model output (tied_numbers.py); with --run or --numbers each
  tied number is computed (`target/release/pinjoint`, `target/release/examples/doc_numbers`)
  and compared to the rounding of its quoted digits; --update-numbers rewrites them in place.

The self-test (always run first) feeds each check a broken page and requires it to fail.
Exit status 1 with one line per problem.
"""
import json
import os
import re
import subprocess
import sys
import tempfile
import unicodedata
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
RUNNABLE = "<!-- runnable -->"
TIME_LIMIT_S = 600

LINK = re.compile(r"!?\[(?:[^\]\[]|\[[^\]]*\])*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
HTML_LINK = re.compile(r"""<(?:a|img)\s[^>]*?(?:href|src)=["']([^"']+)["']""")
FENCE = re.compile(r"^(\s*)(```+|~~~+)\s*([\w+-]*)")
NUMBER = re.compile(r"(?<![\w.])[-−]?\d+(?:\.\d+)?(?:e[-−+]?\d+)?(?![\w])")
QUOTE_BEGIN = re.compile(r"<!-- numbers from ([^\s:]+)")
QUOTE_END = "<!-- end of numbers from "


def pages(root):
    out = [root / "README.md", root / "BENCHMARKS.md"]
    out += sorted((root / "docs").glob("*.md"))
    return [p for p in out if p.exists()]


# Generated files that belong in benches/results/, never at the repository's root: the
# callgrind profiles (benches/callgrind.sh) and the pictures (pinjoint-bench's plots).
RESULTS = "benches/results"
ROOT_GENERATED = ("callgrind_*", "*.svg")


def check_clean_root(root):
    """Measurement dumps and pictures at the root: one problem each (they go to benches/results/)."""
    found = sorted({p.name for pattern in ROOT_GENERATED for p in root.glob(pattern) if p.is_file()})
    return [f"{name}: a generated file at the repository's root (its place is {RESULTS}/)" for name in found]


def split_blocks(text):
    """(prose lines with code blocks blanked, fenced blocks as (start line, lang, code))."""
    lines = text.split("\n")
    prose, blocks = [], []
    fence, lang, start, code = None, "", 0, []
    for i, line in enumerate(lines):
        m = FENCE.match(line)
        if fence is None:
            if m:
                fence, lang, start, code = m.group(2), m.group(3), i, []
                prose.append("")
            else:
                prose.append(line)
        else:
            if line.strip().startswith(fence[0] * len(fence)) and line.strip().strip(fence[0]) == "":
                blocks.append((start, lang, "\n".join(code) + "\n"))
                fence = None
            else:
                code.append(line)
            prose.append("")
    return prose, blocks


def strip_inline_code(line):
    return re.sub(r"`[^`]*`", "", line)


def anchor_of(heading):
    """GitHub's heading anchor: the rendered text, lower case, without punctuation."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # links: their text
    text = text.replace("`", "").replace("*", "")
    text = re.sub(r"<[^>]+>", "", text).strip().lower()
    out = []
    for ch in text:
        cat = unicodedata.category(ch)
        if ch in " -_" or cat[0] in "LN" or cat == "Mn":
            out.append("-" if ch == " " else ch)
    return "".join(out)


def anchors(path, cache={}):
    if path not in cache:
        prose, _ = split_blocks(path.read_text(encoding="utf-8"))
        seen, found = {}, set()
        for line in prose:
            m = re.match(r"^(#{1,6})\s+(.*?)\s*#*\s*$", line)
            if not m:
                continue
            base = anchor_of(m.group(2))
            n = seen.get(base, 0)
            seen[base] = n + 1
            found.add(base if n == 0 else f"{base}-{n}")
        for m in re.finditer(r"""<a\s+(?:name|id)=["']([^"']+)["']""", path.read_text(encoding="utf-8")):
            found.add(m.group(1))
        cache[path] = found
    return cache[path]


def check_links(root, files):
    problems = []
    for page in files:
        prose, _ = split_blocks(page.read_text(encoding="utf-8"))
        for n, line in enumerate(prose, 1):
            bare = strip_inline_code(line)
            for target in [m.group(1) for m in LINK.finditer(bare)] + [m.group(1) for m in HTML_LINK.finditer(bare)]:
                where = f"{page.relative_to(root)}:{n}: link {target}"
                if re.match(r"^[a-z][a-z0-9+.-]*:", target):  # http:, https:, mailto:
                    continue
                path_part, _, frag = target.partition("#")
                if path_part.startswith("/"):
                    problems.append(f"{where}: an absolute path (use a path relative to the page)")
                    continue
                dest = (page.parent / path_part).resolve() if path_part else page
                try:
                    dest.relative_to(root)
                except ValueError:
                    problems.append(f"{where}: points outside the repository")
                    continue
                if not dest.exists():
                    problems.append(f"{where}: {dest.relative_to(root)} does not exist")
                    continue
                if frag:
                    if dest.suffix != ".md" or dest.is_dir():
                        problems.append(f"{where}: an anchor into a file that is not a Markdown page")
                    elif frag not in anchors(dest):
                        problems.append(f"{where}: no heading with anchor #{frag} in {dest.relative_to(root)}")
    return problems


def runnable_blocks(root, files):
    """[(page, line, lang, code)] for every block marked runnable; problems for bad markers."""
    out, problems = [], []
    for page in files:
        text = page.read_text(encoding="utf-8")
        lines = text.split("\n")
        _, blocks = split_blocks(text)
        starts = {start: (lang, code) for start, lang, code in blocks}
        for i, line in enumerate(lines):
            if line.strip() != RUNNABLE:
                continue
            where = f"{page.relative_to(root)}:{i + 1}"
            j = i + 1
            while j < len(lines) and lines[j].strip() == "":
                j += 1
            if j not in starts:
                problems.append(f"{where}: {RUNNABLE} is not followed by a fenced code block")
                continue
            lang, code = starts[j]
            if lang not in ("sh", "bash", "python"):
                problems.append(f"{where}: a runnable block must be sh, bash or python, not {lang or 'unlabelled'}")
                continue
            out.append((page, j + 1, lang, code))
    return out, problems


def package_python(root):
    """The package's virtualenv (python/run_tests.sh: .venv-python, or $PINJOINT_PY_VENV)."""
    venv = os.environ.get("PINJOINT_PY_VENV", str(root / ".venv-python"))
    return os.environ.get("PINJOINT_DOCS_PACKAGE_PYTHON", str(Path(venv) / "bin/python"))


def python_for(code, root):
    if re.search(r"^\s*(import|from)\s+pinjoint\b|import .*\bpinjoint\b", code, re.M):
        return package_python(root)
    if re.search(r"^\s*(import|from)\s+fmpy\b", code, re.M):
        venv = os.environ.get("PINJOINT_VENV", str(root / ".venv"))  # tests/fmu_harness/run.sh's
        return os.environ.get("PINJOINT_DOCS_FMPY_PYTHON", str(Path(venv) / "bin/python"))
    return sys.executable


def run_blocks(root, blocks):
    problems = []
    env = dict(os.environ)
    package_bin = Path(package_python(root)).parent
    env["PATH"] = os.pathsep.join([str(root / "target/release"), str(package_bin), env.get("PATH", "")])
    for page, line, lang, code in blocks:
        where = f"{page.relative_to(root)}:{line} ({lang})"
        with tempfile.TemporaryDirectory(prefix="pinjoint-docs-") as tmp:
            (Path(tmp) / "target").symlink_to(root / "target")
            if lang == "python":
                cmd = [python_for(code, root), "-c", code]
            else:
                cmd = ["bash", "-euo", "pipefail", "-c", code]
            try:
                r = subprocess.run(cmd, cwd=tmp, env=env, capture_output=True, text=True, timeout=TIME_LIMIT_S)
            except subprocess.TimeoutExpired:
                problems.append(f"{where}: did not finish in {TIME_LIMIT_S} s")
                continue
            except OSError as e:
                problems.append(f"{where}: could not start {cmd[0]}: {e}")
                continue
            if r.returncode != 0:
                tail = "\n    ".join((r.stdout + r.stderr).strip().split("\n")[-12:])
                problems.append(f"{where}: exit status {r.returncode}\n    {tail}")
            else:
                print(f"ran {where}: ok")
    return problems


def numbers(text):
    return {float(m.group(0).replace("−", "-")) for m in NUMBER.finditer(text)}


def check_quoted_numbers(root, files):
    problems = []
    for page in files:
        lines = page.read_text(encoding="utf-8").split("\n")
        source, have = None, set()
        for n, line in enumerate(lines, 1):
            m = QUOTE_BEGIN.search(strip_inline_code(line))
            if m:
                source = (page.parent / m.group(1)).resolve()
                if not source.exists():
                    problems.append(f"{page.relative_to(root)}:{n}: quoted source {m.group(1)} does not exist")
                    source = None
                else:
                    have = numbers(source.read_text(encoding="utf-8"))
                continue
            if QUOTE_END in strip_inline_code(line):
                source = None
                continue
            if source is None:
                continue
            if n < len(lines) and re.match(r"^\|[-:| ]+\|\s*$", lines[n]):
                continue  # a table's header row
            for m in NUMBER.finditer(strip_inline_code(line)):
                if float(m.group(0).replace("−", "-")) not in have:
                    problems.append(
                        f"{page.relative_to(root)}:{n}: {m.group(0)} is not a number of {source.relative_to(root)}")
    return problems


FMU_VARIABLE = re.compile(r'<ScalarVariable\s+name="([^"]+)"[^>]*causality="(?:input|output)"')


def section(text, heading):
    """The text of the `## heading` section of a page (up to the next `## `)."""
    start = text.find("\n## " + heading)
    if start < 0:
        return None
    end = text.find("\n## ", start + 4)
    return text[start:] if end < 0 else text[start:end]


def check_fmu_page(root):
    """docs/fmu.md names every input and output of both FMUs (from their committed
    modelDescription.xml, which a test keeps equal to the generated one) and their state
    format versions (from the variable tables)."""
    page = root / "docs/fmu.md"
    if not page.exists():
        return [f"{page.relative_to(root)} is missing"]
    text = page.read_text(encoding="utf-8")
    problems = []
    for model, heading, xml, table in [
        ("PinJoint", "PinJoint: variables", "modelDescription/PinJoint.xml", "crates/fmu/src/pin_joint/variables.rs"),
        ("PinJointRig", "The rig as an FMU", "modelDescription/PinJointRig.xml", "crates/fmu/src/pin_joint_rig/variables.rs"),
    ]:
        part = section(text, heading)
        if part is None:
            problems.append(f"docs/fmu.md: no section '## {heading}'")
            continue
        for name in FMU_VARIABLE.findall((root / xml).read_text(encoding="utf-8")):
            if f"`{name}`" not in part:
                problems.append(f"docs/fmu.md, '## {heading}': {model}'s variable `{name}` ({xml}) is not described")
        version = re.search(r"pub const STATE_VERSION: u8 = (\d+);", (root / table).read_text(encoding="utf-8"))
        if version is None:
            problems.append(f"{table}: no STATE_VERSION")
        elif f"{model} {version.group(1)}" not in (section(text, "State format") or ""):
            problems.append(f"docs/fmu.md, '## State format': {model}'s state version is {version.group(1)} ({table})")
    return problems


def check_api_docs(root):
    """Every documented target of the workspace has its front page in target/doc."""
    meta = json.loads(subprocess.check_output(["cargo", "metadata", "--no-deps", "--format-version", "1"], cwd=root))
    problems, owners = [], {}
    for pkg in meta["packages"]:
        for t in pkg["targets"]:
            if not t.get("doc", True) or not {"lib", "rlib", "cdylib", "bin"} & set(t["kind"]):
                continue
            name = t["name"].replace("-", "_")
            if name in owners:  # cargo only warns, and one page overwrites the other
                problems.append(f"{pkg['name']}: target {t['name']} documents into target/doc/{name}/, as {owners[name]} "
                                "does: set `doc = false` on one of them")
            owners[name] = f"{pkg['name']}'s {t['name']}"
            page = root / "target/doc" / name / "index.html"
            if not page.exists():
                problems.append(f"{pkg['name']}: no API front page {page.relative_to(root)}")
    return problems


def check_tied_numbers(root, run=False, update=False):
    """The pages of numbers_spec.PAGES: every number tied, an input or marked (tied_numbers.py);
    with `run`, every tied number against the built binary; with `update`, rewritten from it.
    Returns (problems, {page: count of tied numbers})."""
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    import numbers_spec
    import tied_numbers
    problems, counts = [], {}
    binary = tied_numbers.Binary(root) if (run or update) else None
    if binary is not None:
        if not binary.exe.exists():
            return [f"{binary.exe.relative_to(root)} is missing: cargo build --release -p pinjoint-cli"], counts
        extra = numbers_spec.ns_extra(binary)
        binary.namespace = (lambda ns=binary.namespace: (lambda: ns(extra)))()
    for rel, spec in numbers_spec.PAGES.items():
        if not (root / rel).exists():
            problems.append(f"{rel}: a page of tests/docs/numbers_spec.py that does not exist")
            continue
        got, n, new_text = tied_numbers.check_page(root, rel, spec, binary, update)
        problems += got
        counts[rel] = n
        if update and new_text is not None:
            (root / rel).write_text(new_text, encoding="utf-8")
    return problems, counts


def self_test_tied_numbers():
    """The tied-number check on a page with one of each problem, against a stand-in binary;
    then the update rewrites the page and the check passes."""
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    import tied_numbers as tn

    class Stub:
        commands = []

        def namespace(self):
            def point(N=None, kN=None, w=None, C=20):
                self.commands.append(f"pinjoint point --load {N or kN * 1e3} --speed {w}")
                return {"torque": 0.21966 * (N or kN * 1e3) / 200, "mu": 0.0392262}
            return {"point": point, "abs": abs}

    page = ("# P\n\nAt 200 N, 1 rad/s: 0.231<!--=t--> N·m, μ = 0.039<!--=mu-->, 5.0e-4<!--=small-->.\n\n"
            "A stray 7.5 here, and an unknown 3<!--=nowhere-->; eq. 12, section 4.4, Smith (1999), 1 − ε.\n\n"
            "<!-- unchecked: literature -->\nRaimondi & Boyd give 1.33.\n<!-- end unchecked -->\n"
            "Bound: below 1e-3<!--=bound-->; 20<!--~def--> °C; w = 0<!--=w-->.\n\n"
            "<!-- numbers from GEN.md: checked there -->\n| 9.9 |\n<!-- end of numbers from GEN.md -->\n")
    spec = {"t": "point(N=200, w=1)['torque']", "mu": "point(N=200, w=1)['mu']", "unused": "1",
            "small": "point(N=200, w=1)['mu']/78.4", "bound": tn.Spec("point(N=200, w=1)['mu']/10", upper=True),
            "w": tn.Spec("point(N=200, w=1)['mu']/100", exact=True)}
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp)
        (root / "p.md").write_text(page, encoding="utf-8")
        got, n, _ = tn.check_page(root, "p.md", spec, Stub())
        expected = ["p.md:3: 0.231 quoted, 0.21966 computed (t = point(N=200, w=1)['torque']; from pinjoint point --load 200 --speed 1)",
                    "p.md:5: 7.5 is neither tied", "p.md:5: 3<!--=nowhere--> has no definition",
                    "p.md: tests/docs/numbers_spec.py defines unused", "p.md:10: 1e-3 quoted, 0.00392262 computed",
                    "p.md:10: 0 quoted, 0.000392262 computed"]
        missing = [e for e in expected if not any(g.startswith(e) for g in got)]
        assert not missing and len(got) == len(expected) and n == 6, f"self-test (tied numbers): missing {missing}, got {got}"
        _, _, new = tn.check_page(root, "p.md", spec, Stub(), update=True, log=lambda _: None)
        assert "0.220<!--=t-->" in new and "0.039<!--=mu-->" in new and "5.0e-4<!--=small-->" in new and "5e-3<!--=bound-->" in new and "0.000392262<!--=w-->" in new, new
        (root / "p.md").write_text(new, encoding="utf-8")
        got, _, _ = tn.check_page(root, "p.md", spec, Stub())
        assert all(("7.5" in g or "nowhere" in g or "unused" in g) for g in got), f"self-test (tied numbers) after update: {got}"
    for value, quoted, want in [(0.0999, "0.100", "0.0999"), (2.0, "2.08", "2.00"), (-20.4, "−20", "−20"),
                                (1.5e-4, "1.5e-4", "1.5e-4"), (123456.0, "117", "123456"), (0.001234, "0.0412", "0.00123")]:
        assert tn.formatted(value, quoted) == want, (value, quoted, tn.formatted(value, quoted), want)
    assert tn.formatted(10183.0, "10200", tn.Spec("x", sig=3)) == "10200"


def self_test():
    """Each check must be able to fail: a broken page set must give each expected problem."""
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp).resolve()
        (root / "docs").mkdir()
        (root / "GEN.md").write_text("| a | 1.25 | 3e-5 |\n")
        (root / "README.md").write_text(
            "# Top `code` heading: with punctuation!\n## Twice\n## Twice\n"
            "[ok](docs/a.md#a-page) [ok](#top-code-heading-with-punctuation) [ok](#twice-1)\n"
            "[missing](docs/none.md) [bad anchor](docs/a.md#nowhere) [outside](../x.md)\n"
            "`[in code](docs/none2.md)`\n```sh\n[in a block](docs/none3.md)\n```\n"
            "<!-- runnable -->\nno block here\n"
            "<!-- runnable -->\n```sh\nexit 3\n```\n"
            "<!-- numbers from GEN.md: checked -->\n| 1.25 | 3e-5 | 7.5 |\n<!-- end of numbers from GEN.md -->\n")
        (root / "docs/a.md").write_text("# A page\n")
        (root / "callgrind_sweep.txt").write_text("# profile\n")
        (root / "bench_rig.svg").write_text("<svg></svg>\n")
        files = pages(root)
        got = check_links(root, files) + check_clean_root(root)
        blocks, marker_problems = runnable_blocks(root, files)
        got += marker_problems + run_blocks(root, blocks) + check_quoted_numbers(root, files)
        expected = ["docs/none.md does not exist", "no heading with anchor #nowhere", "points outside the repository",
                    "is not followed by a fenced code block", "exit status 3", "7.5 is not a number of GEN.md",
                    "callgrind_sweep.txt: a generated file at the repository's root",
                    "bench_rig.svg: a generated file at the repository's root"]
        missing = [e for e in expected if not any(e in g for g in got)]
        extra = [g for g in got if not any(e in g for e in expected)]
        assert not missing and len(got) == len(expected), f"self-test: missing {missing}, unexpected {extra}"
    self_test_tied_numbers()
    assert anchor_of("Through the rig simulation: `--model rig`") == "through-the-rig-simulation---model-rig"
    assert anchor_of("The FMU Compliance Checker and Reference-FMUs' fmusim") == "the-fmu-compliance-checker-and-reference-fmus-fmusim"


def main(argv):
    self_test()
    if "--api-docs" in argv:
        problems = check_api_docs(ROOT)
    else:
        files = pages(ROOT)
        problems = check_links(ROOT, files) + check_quoted_numbers(ROOT, files) + check_fmu_page(ROOT) + check_clean_root(ROOT)
        tied, counts = check_tied_numbers(ROOT, run="--run" in argv or "--numbers" in argv,
                                          update="--update-numbers" in argv)
        problems += tied
        print("check_docs: tied numbers " + ", ".join(f"{p} {n}" for p, n in counts.items())
              + ("" if {"--run", "--numbers", "--update-numbers"} & set(argv) else " (not computed)"))
        blocks, marker_problems = runnable_blocks(ROOT, files)
        problems += marker_problems
        if "--run" in argv:
            problems += run_blocks(ROOT, blocks)
        print(f"check_docs: {len(files)} pages, {len(blocks)} runnable examples{'' if '--run' in argv else ' (not run)'}")
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
