#!/usr/bin/env python3
"""The comparison half of bench/same_numbers.sh: do two ffrf builds give the same numbers?

bench/same_numbers.sh runs the same ffrf command line with an OLD and a NEW program, each with
`--out` into its own directory and its stdout captured, and lists every run in a manifest. This
file reads the manifest and compares, run by run:

  * every JSON file and every CSV file the two runs wrote (the same files, the same keys and
    columns, the same rows): each number with a relative tolerance (default 1e-12, absolute floor
    1e-300), each text value exactly after masking;
  * the text printed on stdout, after masking, to the last printed digit (exact equality);
  * the exit codes.

Masked, because they legitimately differ between two runs: wall times and everything derived from
them (speed-ups in wall time, real-time factors, the build time of a recorded sea), dates, the
program's version and commit, host names, and the paths of the output directories and of the
scene tree each program ran in. report.md, journal.tsv, the charts' .dat/.gp/.png are not read:
their numbers are the JSON's and CSV's, or timings.

Standard library only (python3 >= 3.11, for tomllib). Subcommands:

  same_numbers.py report MANIFEST OUT_DIR [--rtol R]     the table of a same_numbers.sh run
  same_numbers.py dirs OLD_DIR NEW_DIR [--rtol R]        two --out directories by hand (their stdout:
                                                         OLD_DIR.stdout / NEW_DIR.stdout if present)
  same_numbers.py classify SCENE.toml                    words used by same_numbers.sh: crane hub
                                                         cargo irregular
  same_numbers.py exact-copy SCENE.toml COPY.toml        the scene with wave.kinematics = "exact"
"""

from __future__ import annotations

import csv
import difflib
import json
import math
import re
import sys
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

ABS_FLOOR = 1e-300

# ---------------------------------------------------------------------------------------------
# What legitimately differs between two runs
# ---------------------------------------------------------------------------------------------

# JSON keys and CSV columns that hold timings, dates, versions, hosts (matched on the key itself,
# not on its path). Simulated times (time_s, duration_s, ramp_end_s, ...) are *not* timings.
IGNORED_KEY = re.compile(
    r"wall|real_time|build_time|(^|_)cpu(_|$)|elapsed|timing|^date$|timestamp|time_utc|"
    r"(^|_)version$|(^|_)commit$|(^|_)host(name)?$|^eta(_s)?$", re.IGNORECASE)

NUMBER = re.compile(r"(?<![\w.])[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?(?![\w.])")
_NUM = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
TIMING_CELL = re.compile(rf"(?<![\w.]){_NUM}[×x]?(?![\w.])")  # a number in a timing column: "0.136", "8.8×"

# Timing numbers inside a line of text (stdout, or a JSON string such as the verdict sentence).
TEXT_MASKS = [
    # "4.2× less wall time", "3.1x the wall time", "1.8× less wall time and ..."
    (re.compile(rf"{_NUM}\s*[×x]\s+(?=(?:less |more )?(?:the )?wall)"), "<t>× "),
    # "wall time 4.4× less", "wall time 0.136 s", "wall time   0.121 s (494.4x real time)"
    (re.compile(rf"(wall[ -]time\s+){_NUM}\s*(?:[×x]|s\b)?"), r"\1<t>"),
    (re.compile(rf"{_NUM}\s*[×x]\s+real[ -]time"), "<t>x real time"),
    (re.compile(rf"(built in\s+){_NUM}\s*s\b"), r"\1<t> s"),
    (re.compile(rf"(wall_s\s*[=:]\s*){_NUM}"), r"\1<t>"),
    (re.compile(r"\d{4}-\d\d-\d\d[T ]\d\d:\d\d(?::\d\d(?:\.\d+)?)?Z?(?: UTC)?"), "<date>"),
    (re.compile(r"\bETA\s+\S+"), "ETA <t>"),
]

# CSV files whose rows come in order of completion, not of content (docs/operability.md §4:
# cells_finished.csv gets each cell as its last record arrives): rows are paired by these columns.
ROWS_BY_KEY = {"cells_finished.csv": ("hs_m", "tp_s", "heading")}

# Table headers whose column holds a timing: the numbers under them are masked (tables are
# fixed-width, the number ends where its header ends).
TIMING_HEADER = re.compile(r"wall \[s\]|x wall|wall_s|CPU \[s\]|speed-up(?! \(work)")

# A paragraph printed over several lines (the verdict) continues on lines indented this deep; it is
# joined before masking, since a timing number of another width moves the line breaks.
CONTINUATION = re.compile(r"^ {12,}\S")


def mask_line(line: str) -> str:
    for pattern, replacement in TEXT_MASKS:
        line = pattern.sub(replacement, line)
    return line


def mask_text(text: str, substitutions: list[tuple[str, str]]) -> list[str]:
    """Lines of text with paths replaced, wrapped paragraphs joined and timing numbers masked."""
    for old, new in substitutions:
        text = text.replace(old, new)
    joined: list[str] = []
    for line in text.splitlines():
        if joined and joined[-1].strip() and CONTINUATION.match(line):
            joined[-1] += " " + line.strip()
        else:
            joined.append(line)
    lines = []
    spans: list[tuple[int, int]] = []  # character spans of the timing columns of the current table
    for line in joined:
        if not line.strip():
            spans = []
        header = [(m.start(), m.end()) for m in TIMING_HEADER.finditer(line)]
        if header and len(line.split()) >= 3:
            spans = header
        elif spans:
            # a number under a timing header (with a trailing × or x: "8.8×"), and the padding in
            # front of it, becomes " <t>": another width of the number leaves no trace
            pieces, last = [], 0
            for m in TIMING_CELL.finditer(line):
                if any(m.start() <= e and m.end() >= s for s, e in spans):
                    start = len(line[:m.start()].rstrip())
                    if start < last:
                        continue
                    pieces += [line[last:start], " <t>"]
                    last = m.end()
            line = "".join(pieces) + line[last:]
        lines.append(mask_line(line))
    return lines


# ---------------------------------------------------------------------------------------------
# Differences of one run pair
# ---------------------------------------------------------------------------------------------

@dataclass
class Difference:
    where: str
    old: str
    new: str
    rel: float           # relative difference |a − b| / max(|a|, |b|); math.inf for text
    scaled: float = 0.0  # |a − b| / the largest |value| of its CSV column or JSON array


@dataclass
class FileStats:
    numbers: int = 0
    over: int = 0
    max_rel: float = 0.0
    max_rel_where: str = ""
    max_scaled: float = 0.0
    max_scaled_where: str = ""


@dataclass
class PairResult:
    numbers: int = 0            # numbers compared
    ignored: int = 0            # values skipped as timing / date / version
    below: int = 0              # numbers that differ, within the tolerance
    over: list = field(default_factory=list)        # Differences of numbers beyond the tolerance
    texts: list = field(default_factory=list)       # Differences of text values and stdout lines
    structure: list = field(default_factory=list)   # files, keys, columns, rows in one run only
    notes: list = field(default_factory=list)
    files: dict = field(default_factory=dict)       # file name -> FileStats
    total: FileStats = field(default_factory=FileStats)

    def identical(self) -> bool:
        return not (self.over or self.texts or self.structure)


def rel_diff(a: float, b: float) -> float:
    if a == b or (math.isnan(a) and math.isnan(b)):
        return 0.0
    if math.isnan(a) or math.isnan(b) or math.isinf(a) or math.isinf(b):
        return math.inf
    if abs(a - b) <= ABS_FLOOR:
        return 0.0
    return abs(a - b) / max(abs(a), abs(b))


def as_number(text: str):
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def printed_numbers_apart(x: str, y: str) -> float:
    """Largest relative difference of the numbers of two texts that have the same words around
    their numbers; math.inf when the words differ."""
    if NUMBER.sub("#", x) != NUMBER.sub("#", y):
        return math.inf
    return max([rel_diff(float(p), float(q)) for p, q in zip(NUMBER.findall(x), NUMBER.findall(y))] or [0.0])


class Comparator:
    def __init__(self, rtol: float, old_subs, new_subs):
        self.rtol = rtol
        self.old_subs = old_subs
        self.new_subs = new_subs
        self.r = PairResult()

    # -- numbers and text -----------------------------------------------------------------------
    def number(self, file: str, where: str, a: float, b: float, scale: float, shown=None):
        stats = self.r.files.setdefault(file, FileStats())
        for s in (stats, self.r.total):
            s.numbers += 1
        self.r.numbers += 1
        d = rel_diff(a, b)
        if d == 0.0:
            return
        scaled = math.inf if math.isinf(d) else abs(a - b) / max(scale, abs(a), abs(b), ABS_FLOOR)
        for s in (stats, self.r.total):
            if d > s.max_rel:
                s.max_rel, s.max_rel_where = d, where
            if scaled > s.max_scaled:
                s.max_scaled, s.max_scaled_where = scaled, where
        if d > self.rtol:
            stats.over += 1
            self.r.total.over += 1
            old, new = shown if shown else (repr(a), repr(b))
            self.r.over.append(Difference(where, old, new, d, scaled))
        else:
            self.r.below += 1

    def text(self, where: str, a: str, b: str):
        ma = "\n".join(mask_text(a, self.old_subs))
        mb = "\n".join(mask_text(b, self.new_subs))
        if ma != mb:
            self.r.texts.append(Difference(where, ma, mb, printed_numbers_apart(ma, mb)))

    # -- JSON -----------------------------------------------------------------------------------
    def json_tree(self, file: str, where: str, a, b, scale: float = 0.0):
        if isinstance(a, dict) and isinstance(b, dict):
            for k in a:
                if k not in b:
                    self.r.structure.append(f"{where}.{k}: only in OLD")
            for k in b:
                if k not in a:
                    self.r.structure.append(f"{where}.{k}: only in NEW")
            for k in a:
                if k not in b:
                    continue
                if IGNORED_KEY.search(k):
                    self.r.ignored += 1
                    continue
                self.json_tree(file, f"{where}.{k}", a[k], b[k])
        elif isinstance(a, list) and isinstance(b, list):
            pairs = list(enumerate(zip(a, b)))
            if len(a) != len(b):
                # Arrays of another length are not paired by position (a RAO on a refined grid: the
                # k-th values are at other frequencies); objects are, by a name they carry.
                key = next((k for k in ("model", "label", "name", "output", "key")
                            if all(isinstance(v, dict) and k in v for v in a + b)), None)
                names_a = [v[key] for v in a] if key else []
                names_b = [v[key] for v in b] if key else []
                if key and len(set(map(str, names_a))) == len(a) and len(set(map(str, names_b))) == len(b):
                    pairs = [(i, (x, b[names_b.index(x[key])])) for i, x in enumerate(a) if x[key] in names_b]
                    note = f"paired by {key}"
                else:
                    pairs = []
                    note = "not compared element by element"
                self.r.structure.append(f"{where}: {len(a)} elements in OLD, {len(b)} in NEW ({note})")
            # an array of numbers (a RAO, a spectrum) is judged against its largest value too
            numbers = [abs(v) for v in a + b if isinstance(v, (int, float)) and not isinstance(v, bool)
                       and math.isfinite(v)]
            scale = max(numbers, default=0.0)
            for i, (x, y) in pairs:
                self.json_tree(file, f"{where}[{i}]", x, y, scale)
        elif isinstance(a, (dict, list)) or isinstance(b, (dict, list)):
            self.r.structure.append(f"{where}: {type(a).__name__} in OLD, {type(b).__name__} in NEW")
        elif isinstance(a, bool) or isinstance(b, bool) or a is None or b is None:
            if a != b:
                self.r.texts.append(Difference(where, json.dumps(a), json.dumps(b), math.inf))
        elif isinstance(a, (int, float)) and isinstance(b, (int, float)):
            self.number(file, where, float(a), float(b), scale)
        elif isinstance(a, str) and isinstance(b, str):
            self.text(where, a, b)
        else:
            self.r.structure.append(f"{where}: {type(a).__name__} in OLD, {type(b).__name__} in NEW")

    def json_file(self, name: str, pa: Path, pb: Path):
        try:
            a, b = json.loads(pa.read_text()), json.loads(pb.read_text())
        except ValueError as e:
            self.r.structure.append(f"{name}: not JSON in one run ({e})")
            return
        self.json_tree(name, name + ":", a, b)

    # -- CSV ------------------------------------------------------------------------------------
    def csv_file(self, name: str, pa: Path, pb: Path):
        ra = list(csv.reader(pa.read_text().splitlines()))
        rb = list(csv.reader(pb.read_text().splitlines()))
        if not ra or not rb:
            if len(ra) != len(rb):
                self.r.structure.append(f"{name}: empty in one run only")
            return
        ha, hb = ra[0], rb[0]
        for c in ha:
            if c not in hb:
                self.r.structure.append(f"{name}: column {c} only in OLD")
        for c in hb:
            if c not in ha:
                self.r.structure.append(f"{name}: column {c} only in NEW")
        columns = [c for c in ha if c in hb]
        ia = {c: ha.index(c) for c in columns}
        ib = {c: hb.index(c) for c in columns}
        rows_a, rows_b = ra[1:], rb[1:]
        key = ROWS_BY_KEY.get(Path(name).name)
        if key and all(k in ia for k in key):
            rows_a = sorted(rows_a, key=lambda row: [row[ia[k]] for k in key])
            rows_b = sorted(rows_b, key=lambda row: [row[ib[k]] for k in key])
            self.r.notes.append(f"{name}: rows in order of completion, paired by {', '.join(key)}")
        pairs = self.row_pairs(name, ha, hb, rows_a, rows_b)

        def cell(row, i):
            return row[i] if i < len(row) else ""

        for c in columns:
            if IGNORED_KEY.search(c):
                self.r.ignored += len(pairs)
                continue
            # the column's largest |value| in either run: the scale of the "diff / column max" measure
            values = [as_number(cell(x, ia[c])) for _, x, _ in pairs] + [as_number(cell(y, ib[c])) for _, _, y in pairs]
            scale = max((abs(v) for v in values if v is not None and math.isfinite(v)), default=0.0)
            for label, x, y in pairs:
                va, vb = cell(x, ia[c]), cell(y, ib[c])
                na, nb = as_number(va), as_number(vb)
                where = f"{name}:{c}[{label}]"
                if na is not None and nb is not None:
                    self.number(name, where, na, nb, scale, (va, vb))
                else:
                    self.text(where, va, vb)

    def row_pairs(self, name, ha, hb, rows_a, rows_b):
        """Rows paired by position; when the row counts differ, by the first column's text (a
        period, a time, a cell) if it is unique in both files, so that the rows both runs have
        are still compared and the others named."""
        if len(rows_a) == len(rows_b):
            return [(f"row {i + 1}", x, y) for i, (x, y) in enumerate(zip(rows_a, rows_b))]
        self.r.structure.append(f"{name}: {len(rows_a)} rows in OLD, {len(rows_b)} in NEW")
        keys_a = [x[0] if x else "" for x in rows_a]
        keys_b = [y[0] if y else "" for y in rows_b]
        if ha and hb and ha[0] == hb[0] and len(set(keys_a)) == len(keys_a) and len(set(keys_b)) == len(keys_b):
            index_b = {k: i for i, k in enumerate(keys_b)}
            set_a = set(keys_a)
            for side, keys, other in (("OLD", keys_a, index_b), ("NEW", keys_b, set_a)):
                only = [k for k in keys if k not in other]
                if only:
                    self.r.structure.append(f"{name}: {len(only)} rows only in {side} ({ha[0]} = "
                                            f"{', '.join(only[:5])}{', ...' if len(only) > 5 else ''})")
            self.r.notes.append(f"{name}: rows paired by {ha[0]}")
            return [(f"{ha[0]}={k}", rows_a[i], rows_b[index_b[k]]) for i, k in enumerate(keys_a) if k in index_b]
        return [(f"row {i + 1}", x, y) for i, (x, y) in enumerate(zip(rows_a, rows_b))]

    # -- a run's directory and its stdout -----------------------------------------------------------
    def directory(self, da: Path, db: Path):
        def files(d: Path):
            if not d.is_dir():
                return set()
            return {str(p.relative_to(d)) for p in d.rglob("*") if p.is_file() and p.suffix in (".json", ".csv")}
        fa, fb = files(da), files(db)
        for f in sorted(fa - fb):
            self.r.structure.append(f"{f}: file only in OLD")
        for f in sorted(fb - fa):
            self.r.structure.append(f"{f}: file only in NEW")
        for f in sorted(fa & fb):
            if f.endswith(".json"):
                self.json_file(f, da / f, db / f)
            else:
                self.csv_file(f, da / f, db / f)

    def stdout(self, ta: str, tb: str):
        la, lb = mask_text(ta, self.old_subs), mask_text(tb, self.new_subs)
        if len(la) != len(lb):
            self.r.structure.append(f"stdout: {len(la)} lines in OLD, {len(lb)} in NEW (wrapped lines joined)")
        matcher = difflib.SequenceMatcher(a=la, b=lb, autojunk=False)
        for tag, i1, i2, j1, j2 in matcher.get_opcodes():
            if tag == "equal":
                continue
            for k in range(max(i2 - i1, j2 - j1)):
                x = la[i1 + k] if i1 + k < i2 else ""
                y = lb[j1 + k] if j1 + k < j2 else ""
                where = f"stdout:line {i1 + k + 1 if i1 + k < i2 else '-'}/{j1 + k + 1 if j1 + k < j2 else '-'}"
                self.r.texts.append(Difference(where, x, y, printed_numbers_apart(x, y) if x and y else math.inf))


# ---------------------------------------------------------------------------------------------
# The table of a same_numbers.sh run
# ---------------------------------------------------------------------------------------------

def g(x: float) -> str:
    return "-" if math.isinf(x) else f"{x:.3g}"


def details(r: PairResult, limit: int = 12) -> list[str]:
    out = []
    if r.files:
        out.append("  per file: numbers beyond the tolerance / compared; largest relative difference; "
                   "largest |difference| / column (array) max")
        for name, s in r.files.items():
            if s.over or s.max_rel:
                out.append(f"    {name}: {s.over} / {s.numbers}; rel {g(s.max_rel)} at {s.max_rel_where or '-'}; "
                           f"scaled {g(s.max_scaled)} at {s.max_scaled_where or '-'}")
            else:
                out.append(f"    {name}: identical ({s.numbers} numbers)")
    if r.over:
        out.append(f"  numbers beyond the tolerance: {len(r.over)} of {r.numbers}; the largest relative differences:")
        for d in sorted(r.over, key=lambda d: -d.rel)[:limit]:
            out.append(f"    {g(d.rel):>9}  {d.where}: OLD {d.old}  NEW {d.new}")
        out.append("  ... and the largest against their column's (array's) largest value:")
        for d in sorted(r.over, key=lambda d: -d.scaled)[:limit]:
            out.append(f"    {g(d.scaled):>9}  {d.where}: OLD {d.old}  NEW {d.new}")
    if r.texts:
        out.append(f"  text differing after masking (JSON/CSV values, stdout lines): {len(r.texts)}")
        for d in r.texts[:limit]:
            apart = "words differ" if math.isinf(d.rel) else f"printed numbers {g(d.rel)} apart"
            out.append(f"    {d.where} ({apart}):")
            out.append(f"      OLD: {d.old[:400]}")
            out.append(f"      NEW: {d.new[:400]}")
        if len(r.texts) > limit:
            out.append(f"    ... {len(r.texts) - limit} more")
    if r.structure:
        out.append(f"  structure (exit code; files, keys, columns, rows, lines in one run only): {len(r.structure)}")
        for s in r.structure[:limit]:
            out.append(f"    {s}")
        if len(r.structure) > limit:
            out.append(f"    ... {len(r.structure) - limit} more")
    for n in r.notes[:limit]:
        out.append(f"  note: {n}")
    return out


def compare_pair(rtol, old_dir, new_dir, old_stdout, new_stdout, old_subs, new_subs) -> PairResult:
    c = Comparator(rtol, old_subs, new_subs)
    c.directory(Path(old_dir), Path(new_dir))
    if old_stdout is not None and new_stdout is not None:
        c.stdout(old_stdout, new_stdout)
    return c.r


def read(path: str):
    p = Path(path)
    return p.read_text(errors="replace") if p.is_file() else None


def error_line(path: str) -> str:
    lines = (read(path) or "").strip().splitlines()
    errors = [line for line in lines if "error" in line.lower()]
    return (errors or lines or [""])[-1].strip()


def cmd_report(manifest: str, out_dir: str, rtol: float) -> int:
    rows, lines, failures = [], [], 0
    with open(manifest) as fh:
        entries = [line.rstrip("\n").split("\t") for line in fh if line.strip()]
    for (command, scene, mode, old_dir, new_dir, old_rc, new_rc, old_cmd, new_cmd, repo, new_tree) in entries:
        old_subs = [(old_dir, "<out>"), (repo, "<repo>")]
        new_subs = [(new_dir, "<out>"), (new_tree, "<repo>"), (repo, "<repo>")]
        lines += [f"== {command} {scene} [{mode}]", f"  OLD: {old_cmd}   (exit {old_rc})",
                  f"  NEW: {new_cmd}   (exit {new_rc})"]
        expected = mode.startswith("recorded")
        if old_rc == "2":
            # OLD stopped on the scene or the options before any work: nothing to compare.
            old_error = mask_line(error_line(old_dir + ".stderr"))
            new_error = mask_line(error_line(new_dir + ".stderr"))
            if new_rc == "2":
                result = "both refuse (same message)" if old_error == new_error else "both refuse"
                if old_error != new_error:
                    lines.append(f"  NEW stopped too: {new_error}")
            else:
                result = "OLD refuses the scene"
            lines += [f"  {result}: OLD: {old_error}", ""]
            rows.append((command, scene, mode, result, "-", "-", old_error[:120]))
            continue
        r = compare_pair(rtol, old_dir, new_dir, read(old_dir + ".stdout"), read(new_dir + ".stdout"),
                         old_subs, new_subs)
        if old_rc != new_rc:
            r.structure.insert(0, f"exit code: OLD {old_rc}, NEW {new_rc}")
        t = r.total
        if r.identical():
            result = "identical"
        elif expected:
            result = "expected to differ (recorded sea)"
        else:
            result = "DIFFERS"
            failures += 1
        rel = f"{g(t.max_rel)}" if t.max_rel else "0"
        if not r.identical():
            rel = f"{rel} at {t.max_rel_where}" if t.max_rel else rel
        other = f"{len(r.texts)} text, {len(r.structure)} structure" if (r.texts or r.structure) else "-"
        rows.append((command, scene, mode, result, f"{len(r.over)} / {r.numbers}", rel, other))
        lines.append(f"  {result}: {r.numbers} numbers compared ({r.ignored} timing/date/version values skipped), "
                     f"{len(r.over)} beyond rtol {rtol:g}, {r.below} differ within it")
        lines += details(r)
        lines.append("")

    table = format_table(rows)
    (Path(out_dir) / "details.txt").write_text("\n".join(lines) + "\n")
    (Path(out_dir) / "table.md").write_text(table + "\n")
    print(table)
    print()
    print(f"every difference (per file, the largest first, with both values): {Path(out_dir) / 'details.txt'}")
    if failures:
        print(f"{failures} run(s) differ beyond rtol {rtol:g} (numbers), in masked text, structure or exit code")
        return 1
    print(f"no run differs beyond rtol {rtol:g}")
    return 0


def format_table(rows) -> str:
    header = ("command", "scene", "sea / scene used", "result", "numbers beyond rtol / compared",
              "max rel. diff (where: file:key or column[row])", "text, structure differing")
    lines = ["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|"]
    for row in rows:
        lines.append("| " + " | ".join(str(x).replace("|", "\\|") for x in row) + " |")
    return "\n".join(lines)


def cmd_dirs(old_dir: str, new_dir: str, rtol: float) -> int:
    old_dir, new_dir = old_dir.rstrip("/"), new_dir.rstrip("/")
    r = compare_pair(rtol, old_dir, new_dir, read(old_dir + ".stdout"), read(new_dir + ".stdout"),
                     [(old_dir, "<out>")], [(new_dir, "<out>")])
    print(f"{r.numbers} numbers compared ({r.ignored} skipped), {len(r.over)} beyond rtol {rtol:g}, {r.below} within; "
          f"largest relative difference {g(r.total.max_rel)} at {r.total.max_rel_where or '-'}")
    print("\n".join(details(r, limit=40)))
    return 0 if r.identical() else 1


# ---------------------------------------------------------------------------------------------
# Scenes
# ---------------------------------------------------------------------------------------------

def cmd_classify(scene: str) -> int:
    data = tomllib.loads(Path(scene).read_text())
    words = []
    if "hull" in data:
        words.append("crane")
    if "hub" in data:
        words.append("hub")
    if "cargo" in data:
        words.append("cargo")
    if data.get("wave", {}).get("spectrum", "regular") != "regular":
        words.append("irregular")
    print(" ".join(words))
    return 0


def cmd_exact_copy(scene: str, copy: str) -> int:
    """The scene with wave.kinematics = "exact". The key takes the place of an existing kinematics
    line, else of the blank line that ends the [wave] section, so that every other line keeps its
    number (the programs' messages cite scene lines)."""
    lines = Path(scene).read_text().splitlines(keepends=True)
    key = 'kinematics = "exact"\n'
    headers = [i for i, line in enumerate(lines) if line.strip().startswith("[")]
    if not any(lines[i].strip() == "[wave]" for i in headers):
        print(f"{scene}: no [wave] section", file=sys.stderr)
        return 2
    start = next(i for i in headers if lines[i].strip() == "[wave]")
    end = next((i for i in headers if i > start), len(lines))
    existing = [i for i in range(start + 1, end) if re.match(r"\s*kinematics\s*=", lines[i])]
    blank = [i for i in range(start + 1, end) if not lines[i].strip()]
    if existing:
        lines[existing[0]] = key
    elif blank:
        lines[blank[-1]] = key
    else:
        lines.insert(end, key)  # no blank line to take: the lines below move by one
    Path(copy).write_text("".join(lines))
    return 0


def main(argv: list[str]) -> int:
    rtol = 1e-12
    if "--rtol" in argv:
        i = argv.index("--rtol")
        rtol = float(argv[i + 1])
        del argv[i:i + 2]
    if len(argv) >= 3 and argv[0] == "report":
        return cmd_report(argv[1], argv[2], rtol)
    if len(argv) >= 3 and argv[0] == "dirs":
        return cmd_dirs(argv[1], argv[2], rtol)
    if len(argv) >= 2 and argv[0] == "classify":
        return cmd_classify(argv[1])
    if len(argv) >= 3 and argv[0] == "exact-copy":
        return cmd_exact_copy(argv[1], argv[2])
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
