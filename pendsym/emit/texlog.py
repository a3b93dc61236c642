"""Check a LaTeX log for what a reader would see as a defect of the PDF.

``python -m pendsym.emit.texlog [--limit PT] LOG ...`` (run by ``make report`` after each
latexmk) prints one line per problem, ``file:line: what``, and exits 1 if there is any:

- an overfull box (``Overfull \\hbox (12.3pt too wide)``, ``Overfull \\vbox (4pt too high)``)
  wider than ``--limit`` points (5 by default): text or a table running into the margin;
- a missing glyph (``Missing character: There is no … in font …``), which prints nothing;
- a TeX error (a line starting with ``!``).

The file is the source file TeX was reading (tracked through the log's parentheses; the
document itself when unsure), the line is TeX's.
"""
from __future__ import annotations

import argparse
import re
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Sequence

LIMIT_PT = 5.0
WRAP = 79   # TeX wraps its log at max_print_line characters (79 by default)

_OVERFULL = re.compile(r"^Overfull \\([hv])box \(([0-9.]+)pt too (wide|high)\)(.*)$")
_MISSING = re.compile(r"^Missing character: There is no (.+?) in font (.+?)[!.]?$")
_AT_LINES = re.compile(r"lines? (\d+)")
_FILE_OPEN = re.compile(r"\((\.{0,2}/[^\s()]+|[A-Za-z0-9_\-]+\.(?:tex|sty|cls|cfg|def|clo|fd|aux|out|toc|code\.tex))")


@dataclass(frozen=True)
class Problem:
    file: str
    line: int | None
    what: str

    def __str__(self) -> str:
        return f"{self.file}:{self.line if self.line is not None else '?'}: {self.what}"


def unwrap(text: str, width: int = WRAP) -> list[str]:
    """The log's lines with TeX's hard wrapping at ``width`` characters undone (none when a line
    is longer: the log was written with a larger max_print_line)."""
    if any(len(line) > width for line in text.splitlines()):
        return text.splitlines()
    out: list[str] = []
    joining = False
    for raw in text.splitlines():
        if joining and out:
            out[-1] += raw
        else:
            out.append(raw)
        joining = len(raw) == width
    return out


def _source(stack: list[str], default: str) -> str:
    for f in reversed(stack):
        if f.endswith(".tex") and "texmf" not in f and "/usr/" not in f:
            return f
    return default


def problems(text: str, source: str, limit: float = LIMIT_PT) -> list[Problem]:
    """The problems of one log's text; ``source`` names the document (for messages where the
    log does not say which file TeX was reading)."""
    found: list[Problem] = []
    stack: list[str] = []
    lines = unwrap(text)
    for n, line in enumerate(lines):
        m = _OVERFULL.match(line)
        if m:
            kind, amount, how, rest = m.groups()
            at = _AT_LINES.search(rest)
            if float(amount) > limit:
                found.append(Problem(_source(stack, source), int(at.group(1)) if at else None,
                                     f"overfull \\{kind}box, {amount}pt too {how} (limit {limit:g}pt)"))
            continue
        m = _MISSING.match(line)
        if m:
            found.append(Problem(_source(stack, source), None,
                                 f"missing glyph: there is no {m.group(1)} in font {m.group(2).strip()}"))
            continue
        if line.startswith("! "):
            at = next((int(m.group(1)) for ln in lines[n + 1:n + 12] if (m := re.match(r"l\.(\d+)", ln))), None)
            what = line[2:].strip()
            miss = _MISSING.match(what)
            found.append(Problem(_source(stack, source), at,
                                 f"missing glyph: there is no {miss.group(1)} in font {miss.group(2).strip()}"
                                 if miss else f"TeX error: {what}"))
            continue
        _track(line, stack)
    return found


def _track(line: str, stack: list[str]) -> None:
    """Follow the files TeX opens "(file" and closes ")" on a log line (roughly: enough to name
    the file of a message)."""
    i = 0
    while i < len(line):
        if line[i] == "(":
            m = _FILE_OPEN.match(line, i)
            if m:
                stack.append(m.group(1))
                i = m.end()
                continue
            stack.append("")              # a parenthesis of the text, closed by its own ")"
        elif line[i] == ")" and stack:
            stack.pop()
        i += 1


def check_log(log: Path, limit: float = LIMIT_PT) -> list[Problem]:
    """The problems of one .log file."""
    text = Path(log).read_text(encoding="latin-1")
    m = re.search(r"^\*\*\s*(\S+)", text, re.M)          # the file TeX was asked for
    source = m.group(1) if m else Path(log).with_suffix(".tex").name
    return problems(text, source, limit)


def main(argv: Sequence[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m pendsym.emit.texlog", description=__doc__.split("\n\n")[0])
    ap.add_argument("logs", nargs="+", type=Path, help="LaTeX .log files")
    ap.add_argument("--limit", type=float, default=LIMIT_PT, help="largest overfull box tolerated, in pt")
    args = ap.parse_args(argv)
    missing = [p for p in args.logs if not p.is_file()]
    if missing:
        print(f"texlog: no such log: {', '.join(map(str, missing))}", file=sys.stderr)
        return 2
    bad = 0
    for log in args.logs:
        found = check_log(log, args.limit)
        for p in found:
            print(f"{log}: {p}")
        print(f"{log}: " + (f"{len(found)} problem{'s' if len(found) != 1 else ''}" if found else
                            f"clean (no overfull box over {args.limit:g}pt, no missing glyph, no error)"))
        bad += len(found)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
