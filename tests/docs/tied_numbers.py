"""Numbers of the manual tied to the built binary (check_docs.py's tied-number check).

A page listed in numbers_spec.PAGES quotes every number in one of these ways:

- **tied**: the number is followed at once by a tag `<!--=ID-->` (invisible when rendered),
  and numbers_spec.PAGES[page][ID] is a Python expression that computes it from the built
  binary: `point(...)` runs `pinjoint point ... --json`, `param("grease.yield_stress")` reads
  `pinjoint params`, `lib("key")` reads the JSON of `target/release/examples/doc_numbers`
  (library quantities the command line does not print), `code(path, regex)` reads a constant
  from the source. The quoted number must equal the computed one to the rounding of its
  quoted digits (half a unit of its last digit), or to the spec's own tolerance.
  `--update-numbers` rewrites every tied number in place from the binary, keeping its
  number of significant digits (or its notation: `1.5e-4`, `−20`) and the prose around it.
- **an input**: the number is a literal of a tied expression of the same paragraph (or
  table) or of the paragraphs just before and after it (`point(kN=20, w=3, C=-20)` makes 20,
  3 and −20 inputs there);
- **unchecked**, with a reason: between `<!-- unchecked: REASON -->` and
  `<!-- end unchecked -->` (literature values, standards' limits, measured times), marked
  right after it (`<!--~lit-->` literature, `<!--~std-->` a standard, `<!--~def-->` a
  definition, `<!--~measured-->`, `<!--~was-->` a past release's output), a citation (`eq. 12`,
  `section 4.4`, `Figure 9`, `Table 1`, a year, a standard's name) or a formula's constant
  (`1 − ε`, `1/T`, `ε/2`);
- **quoted from a file**: between check_docs.py's `<!-- numbers from FILE -->` markers
  (checked there against FILE).

Any other number on such a page is a problem (`page:line: N is neither tied nor marked`).
"""
import json
import math
import re
import subprocess
import tempfile
from pathlib import Path

try:
    import tomllib
except ImportError:  # Python < 3.11: `pinjoint params` is flat enough to read by hand
    tomllib = None


def read_params(text):
    """The sections of a `pinjoint params` file as nested dicts (numbers, booleans)."""
    if tomllib is not None:
        return tomllib.loads(text)
    out, section = {}, {}
    for line in text.splitlines():
        line = line.split("#", 1)[0].strip()
        if line.startswith("[") and line.endswith("]"):
            section = out.setdefault(line[1:-1], {})
        elif "=" in line:
            key, value = (x.strip() for x in line.split("=", 1))
            section[key] = {"true": True, "false": False}.get(value) if value in ("true", "false") else float(value)
    return out


# A number as the pages write it: a minus (ASCII or U+2212), digits, a decimal part, an
# exponent. Not inside a word (x1, h_13, D1478), not after a decimal point.
NUMBER = re.compile(r"(?<![\w.])[-−]?\d+(?:\.\d+)?(?:e[-−+]?\d+)?(?![\w])")
MARKED = re.compile(r"(?<![\w.])[-−]?\d+(?:\.\d+)?(?:e[-−+]?\d+)?<!--~(\w+)-->")
TIED = re.compile(r"((?<![\w.])[-−]?\d+(?:\.\d+)?(?:e[-−+]?\d+)?)<!--=([A-Za-z0-9_.-]+)-->")
UNCHECKED_BEGIN = re.compile(r"<!-- unchecked: ([^>]+?) -->")
UNCHECKED_END = "<!-- end unchecked -->"
# check_docs.py's own quoted blocks: their numbers are checked against FILE there
QUOTED_BEGIN = re.compile(r"<!-- numbers from [^\s:]+")
QUOTED_END = "<!-- end of numbers from "
COMMENT = re.compile(r"<!--.*?-->")
# Citations: their numbers are names, not quantities.
CITATION = re.compile(
    r"\b[Ee]qs?\.\s*\d+(?:(?:,\s*|\s*(?:and|–|-)\s*)\d+)*"
    r"|\b(?:[Ss]ections?|Figures?|Fig\.|Tables?|[Ii]ssues?)\s+\d+(?:\.\d+)*(?:(?:,\s*|\s*(?:and|–|-)\s*)\d+(?:\.\d+)*)*"
    r"|\b(?:MIL-PRF|FED-STD|ASTM D|ISO VG|NLGI|Method|Type)[- ]?\d+[A-Z]?(?:[–-]\d+)?"
    r"|\b[A-Z][\w'’-]+(?:,? (?:et al\.|& [A-Z][\w'’-]+|and [A-Z][\w'’-]+))?,? \(?(?:1[89]|20)\d\d\b"
    r"|\((?:1[89]|20)\d\d[,)]"
    r"|,\s*(?:1[89]|20)\d\d\)"
    r"|\bFMI \d\.\d(?:\s*(?:and|or|/)\s*\d\.\d)?"
    # formula constants: 1 − x, 1 + x, 1/T, 2/x, x/2
    r"|(?<![\w.])1(?=\s*[−+-]\s*[^\s\d])|(?<![\w.])\d(?=/[^\d\s])|(?<=[^\s\d(]/)\d+(?![\w.])"
)


def to_float(text):
    return float(text.replace("−", "-").replace(" ", ""))


def quoted_step(text):
    """Half a unit of the last quoted digit of `text` (the rounding it can carry)."""
    t = text.replace("−", "-").lstrip("-+")
    mant, _, exp = t.partition("e")
    decimals = len(mant.partition(".")[2])
    return 0.5 * 10.0 ** (-decimals + (int(exp) if exp else 0))


def significant(text):
    mant = text.replace("−", "-").lstrip("-+").partition("e")[0]
    digits = mant.replace(".", "").lstrip("0")
    return max(1, len(digits))


def formatted(value, quoted, spec=None):
    """`value` written as `quoted` is: the same significant digits, notation and minus sign
    (an upper bound rounded up, a `sig` number to its significant digits)."""
    minus = "−" if "−" in quoted else "-"
    if spec is not None and spec.exact:
        return f"{value:.12g}".replace("-", minus)
    if spec is not None and spec.upper:
        # the next 1, 2 or 5 times a power of ten above value, in the quoted notation
        e = math.floor(math.log10(value)) if value > 0 else 0
        m = next(k for k in (1, 2, 5, 10) if k * 10.0 ** e >= value)
        bound = m * 10.0 ** e
        if "e" in quoted or bound < 1e-3:
            return f"{bound:.0e}".replace("e-0", "e-").replace("e+0", "e").replace("e+", "e")
        return f"{bound:g}"
    if spec is not None and spec.sig is not None and "e" not in quoted and abs(value) >= 10 ** (spec.sig - 1):
        step = 10.0 ** (math.floor(math.log10(abs(value))) - spec.sig + 1)
        return f"{round(value / step) * step:.0f}".replace("-", minus)
    if "e" in quoted:
        decimals = len(quoted.partition("e")[0].partition(".")[2])
        m, _, e = f"{value:.{decimals}e}".partition("e")
        out = f"{m}e{int(e)}"
    else:
        sig = significant(quoted)
        if value == 0:
            decimals = len(quoted.partition(".")[2])
        else:
            decimals = max(0, sig - 1 - math.floor(math.log10(abs(value))))
        out = f"{value:.{decimals}f}"
        # rounding can carry into a new digit (0.0999 -> 0.100): keep the significant count
        if decimals > 0 and significant(out) > sig:
            out = f"{value:.{decimals - 1}f}"
    return out.replace("-", minus)


class Binary:
    """The built project's answers, each command run once per check."""

    def __init__(self, root):
        self.root = Path(root).resolve()
        self.exe = self.root / "target/release/pinjoint"
        self.cache = {}
        self.commands = []  # the commands the expression being evaluated ran
        self.tmp = Path(tempfile.mkdtemp(prefix="pinjoint-doc-numbers-"))

    def _run(self, args, what):
        key = tuple(args)
        self.commands.append(what)
        if key not in self.cache:
            r = subprocess.run(args, capture_output=True, text=True, cwd=self.tmp, timeout=600)
            if r.returncode != 0:
                raise RuntimeError(f"`{what}` failed: {(r.stderr or r.stdout).strip().splitlines()[-1:]}")
            self.cache[key] = r.stdout
        return self.cache[key]

    def _params_file(self, over):
        if not over:
            return [], ""
        sections = {}
        for k, v in sorted(over.items()):
            sec, _, name = k.partition(".")
            sections.setdefault(sec, []).append(f"{name} = {json.dumps(v)}")
        text = "".join(f"[{s}]\n" + "\n".join(lines) + "\n" for s, lines in sections.items())
        path = self.tmp / f"p{abs(hash(text))}.toml"
        path.write_text(text)
        shown = "; ".join(f"{k} = {json.dumps(v)}" for k, v in sorted(over.items()))
        return ["--params", str(path)], f" --params <({shown})>"

    def point(self, N=None, kN=None, w=None, rpm=None, C=20.0, paper=False, p=None):
        """`pinjoint point --json` at the load N (or kN), speed w rad/s (or rpm), C °C; `p` a
        dict of parameter overrides ({"grease.supply_exponent": 0.5}), `paper` model.paper."""
        load = N if N is not None else kN * 1e3
        over = dict(p or {})
        if paper:
            over["model.paper"] = True
        kelvin = (100.0 * C + 27315.0) / 100.0
        speed = ["--speed", repr(w)] if w is not None else ["--rpm", repr(rpm)]
        extra, shown = self._params_file(over)
        args = [str(self.exe), "point", "--load", repr(load), *speed, "--temperature", repr(kelvin), "--json", *extra]
        what = f"pinjoint point --load {load:g} {speed[0]} {speed[1]} --temperature {kelvin:g} --json{shown}"
        return json.loads(self._run(args, what))

    def sweep(self, rows, p=None):
        """`pinjoint sweep` over `rows` [(load N, speed rad/s, temperature °C)]: the output rows
        as dicts of numbers (regime and validity as text)."""
        import csv
        import io
        text = "load,speed,temperature\n" + "".join(
            f"{load!r},{w!r},{(100.0 * c + 27315.0) / 100.0!r}\n" for load, w, c in rows)
        path = self.tmp / f"sweep{abs(hash(text))}.csv"
        path.write_text(text)
        extra, shown = self._params_file(dict(p or {}))
        out = self._run([str(self.exe), "sweep", "--input", str(path), *extra],
                        f"pinjoint sweep --input <{len(rows)} rows: load,speed,temperature>{shown}")

        def num(v):
            try:
                return float(v)
            except ValueError:
                return v
        return [{k: num(v) for k, v in r.items()} for r in csv.DictReader(io.StringIO(out))]

    def param(self, key):
        """A value of `pinjoint params` (the defaults), by its dotted key."""
        node = read_params(self._run([str(self.exe), "params"], "pinjoint params"))
        for part in key.split("."):
            node = node[part]
        return float(node)

    def lib(self, key):
        """A value of the doc_numbers example's JSON (library quantities)."""
        exe = self.root / "target/release/examples/doc_numbers"
        if not exe.exists():
            raise RuntimeError(f"{exe.relative_to(self.root)} is missing: "
                               "cargo build --release -p pinjoint --example doc_numbers")
        out = json.loads(self._run([str(exe)], "target/release/examples/doc_numbers"))
        self.commands[-1] = f"target/release/examples/doc_numbers: {key}"
        if key not in out:
            raise RuntimeError(f"target/release/examples/doc_numbers prints no {key!r} (examples/doc_numbers.rs)")
        return out[key]

    def code(self, path, pattern):
        """Group 1 of `pattern` in the source file `path`: a Rust constant expression (its
        names resolved as the file's `const NAME: f64 = ...;`, PI as π)."""
        self.commands.append(f"{path}: /{pattern}/")
        text = (self.root / path).read_text(encoding="utf-8")
        m = re.search(pattern, text, re.M | re.S)
        if m is None:
            raise RuntimeError(f"{path}: no match for /{pattern}/")
        return rust_value(m.group(1), text)

    def const(self, path, name):
        """The value of `const NAME: f64 = ...;` in the source file `path`."""
        return self.code(path, rf"const {name}: f64 = ([^;]+);")

    def column(self, path, name):
        """The numbers of column `name` of the repository's CSV file `path` (a test fixture)."""
        import csv
        self.commands.append(f"{path}: column {name}")
        with open(self.root / path, newline="", encoding="utf-8") as f:
            return [float(r[name]) for r in csv.DictReader(f)]

    def namespace(self, extra=None):
        ns = {k: getattr(math, k) for k in dir(math) if not k.startswith("_")}
        ns.update(point=self.point, sweep=self.sweep, param=self.param, lib=self.lib, code=self.code, const=self.const,
                  column=self.column, abs=abs, max=max, min=min, len=len, sum=sum, range=range)
        ns.update(extra or {})
        return ns


class _Consts(dict):
    def __init__(self, text):
        super().__init__()
        self.text = text

    def __missing__(self, name):
        if name == "PI":
            return math.pi
        m = re.search(rf"const {name}: f64 = ([^;]+);", self.text)
        if m is None:
            raise KeyError(name)
        self[name] = rust_value(m.group(1), self.text)
        return self[name]


def rust_value(expr, text):
    """A Rust f64 constant expression (literals, + - * /, parentheses, the file's constants)."""
    expr = re.sub(r"(?<=\d)_(?=\d)", "", expr.strip())
    expr = re.sub(r"(\d)f64\b", r"\1", expr)
    return float(eval(expr, {"__builtins__": {}}, _Consts(text)))


class Spec:
    """One tied number's definition: an expression and, optionally, a relative tolerance."""

    def __init__(self, expr, rel=None, sig=None, upper=False, exact=False):
        """`rel`: a relative tolerance; `sig`: the quoted number carries `sig` significant
        digits (1900 as 2: ±50); `upper`: the quoted number is an upper bound ("below 1e-9");
        `exact`: the quoted number is the value itself (a parameter's default, a constant of
        the code, a claim such as w = 0), to 1e-12 relative."""
        self.expr, self.rel, self.sig, self.upper, self.exact = expr, rel, sig, upper, exact


def spec_of(value):
    return value if isinstance(value, Spec) else Spec(value)


def literals(expr):
    return {to_float(m.group(0)) for m in re.finditer(r"(?<![\w])-?\d+(?:\.\d+)?(?:e-?\d+)?(?![\w])", expr)}


def paragraphs(lines):
    """For each line index, the (first, last) indices of its paragraph (blank-line separated)."""
    out, start = [None] * len(lines), 0
    for i in range(len(lines) + 1):
        if i == len(lines) or lines[i].strip() == "":
            for j in range(start, i):
                out[j] = (start, i - 1)
            start = i + 1
    return out


def scan(page_text):
    """(tags, untagged): tags [(line, column, quoted text, id)], untagged [(line, text)] of the
    numbers that are neither tied nor inside an unchecked region nor in inline code, comments,
    link targets, fenced blocks or citations (inputs are settled later, with the spec)."""
    lines = page_text.split("\n")
    tags, untagged = [], []
    in_fence, unchecked = None, False
    for n, line in enumerate(lines):
        s = line.strip()
        if re.match(r"^(```+|~~~+)", s):
            in_fence = None if in_fence and s.startswith(in_fence) else (in_fence or s[:3])
            continue
        if in_fence:
            continue
        for m in TIED.finditer(line):
            tags.append((n, m.start(1), m.group(1), m.group(2)))
        if UNCHECKED_BEGIN.search(line) or QUOTED_BEGIN.search(line):
            unchecked = True
        if unchecked:
            if UNCHECKED_END in line or QUOTED_END in line:
                unchecked = False
            continue
        bare = MARKED.sub(" ", TIED.sub(" ", line))
        bare = COMMENT.sub(" ", bare)
        bare = re.sub(r"`[^`]*`", " ", bare)
        bare = re.sub(r"\]\([^)]*\)", "] ", bare)  # link targets
        bare = CITATION.sub(" ", bare)
        for m in NUMBER.finditer(bare):
            untagged.append((n, m.group(0)))
    return tags, untagged, lines


def shown(commands, most=3):
    unique = list(dict.fromkeys(commands))
    more = f"; and {len(unique) - most} more" if len(unique) > most else ""
    return "; ".join(unique[:most]) + more


def check_page(root, rel, spec, binary=None, update=False, log=print):
    """Problems of one page; with `binary`, every tied number compared with (or, `update`,
    rewritten from) its computed value. Returns (problems, count of tied numbers, new text)."""
    page = Path(root) / rel
    text = page.read_text(encoding="utf-8")
    tags, untagged, lines = scan(text)
    problems = []
    used = set()
    for n, _, quoted, tid in tags:
        used.add(tid)
        if tid not in spec:
            problems.append(f"{rel}:{n + 1}: {quoted}<!--={tid}--> has no definition in tests/docs/numbers_spec.py")
    for tid in sorted(set(spec) - used):
        problems.append(f"{rel}: tests/docs/numbers_spec.py defines {tid}, which the page does not quote")
    para = paragraphs(lines)
    inputs = {}
    for n, _, _, tid in tags:
        if tid in spec:
            inputs.setdefault(para[n], set()).update(literals(spec_of(spec[tid]).expr))
    # a paragraph's inputs hold in it and in the paragraphs beside it
    starts = sorted(set(para) - {None})
    index = {k: i for i, k in enumerate(starts)}
    def allowed(k):
        i = index[k]
        out = set()
        for j in (i - 1, i, i + 1):
            if 0 <= j < len(starts):
                out |= inputs.get(starts[j], set())
        return out
    for n, t in untagged:
        if to_float(t) not in allowed(para[n]):
            problems.append(f"{rel}:{n + 1}: {t} is neither tied to a command (`<!--=ID-->`), an input of one "
                            "in its paragraph, nor marked `<!-- unchecked: REASON -->`")
    if binary is None:
        return problems, len(tags), None
    values = {}
    for tid in sorted(used & set(spec)):
        s = spec_of(spec[tid])
        binary.commands = []
        try:
            values[tid] = (float(eval(s.expr, binary.namespace())), list(binary.commands), s)
        except Exception as e:  # noqa: BLE001 - reported with the page and the expression
            problems.append(f"{rel}: {tid} = {s.expr}: {e}")
    new_lines = list(lines)
    # right to left within a line, so that earlier columns stay valid
    for n, col, quoted, tid in sorted(tags, key=lambda t: (t[0], -t[1])):
        if tid not in values:
            continue
        value, commands, s = values[tid]
        q = to_float(quoted)
        if s.upper:
            ok = value <= q * (1 + 1e-12)
        elif s.exact:
            ok = abs(q - value) <= 1e-12 * max(abs(q), abs(value), 1e-300)
        else:
            if s.rel is not None:
                tol = abs(value) * s.rel
            elif s.sig is not None:
                tol = 0.5 * 10.0 ** (math.floor(math.log10(abs(q))) - s.sig + 1) if q else 0.0
            else:
                tol = quoted_step(quoted)
            ok = abs(q - value) <= tol * (1 + 1e-9) + 1e-300
        if ok:
            continue
        if update:
            new = formatted(value, quoted, s)
            line = new_lines[n]
            new_lines[n] = line[:col] + new + line[col + len(quoted):]
            log(f"{rel}:{n + 1}: {quoted} -> {new} ({tid})")
        else:
            problems.append(f"{rel}:{n + 1}: {quoted} quoted, {value:.6g} computed ({tid} = {s.expr}; "
                            f"from {shown(commands)})")
    new_text = "\n".join(new_lines)
    return problems, len(tags), (new_text if new_text != text else None)
