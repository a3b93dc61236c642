"""A one-page PDF of a scene's budget: the answer, the table, and a bar chart on a log scale.

LaTeX (pgfplots) through latexmk in a temporary directory; the PDF is moved into place only
when it is complete.  No TeX installation, or a failed run, is a one-line error.
"""
from __future__ import annotations

import math
import os
import shutil
import subprocess
import tempfile
from pathlib import Path

from ..scene import SceneError
from .budget import SECONDS_PER_DAY, Budget

SPECIAL = {"\\": r"\textbackslash{}", "&": r"\&", "%": r"\%", "$": r"\$", "#": r"\#", "_": r"\_",
           "{": r"\{", "}": r"\}", "~": r"\textasciitilde{}", "^": r"\textasciicircum{}"}


DECLARED = "ΔαδλμεπΓ²−–—≤√→"     # the characters the page's preamble declares


def escape(text: str) -> str:
    """Plain text for LaTeX: its special characters escaped; anything outside printable ASCII,
    Latin-1 and DECLARED written as '?' (the scene's name is the user's)."""
    out = []
    for ch in text:
        if ch in SPECIAL:
            out.append(SPECIAL[ch])
        elif ch.isprintable() and (ord(ch) < 0x7f or 0xa0 <= ord(ch) <= 0xff or ch in DECLARED):
            out.append(ch)
        else:
            out.append("?")
    return "".join(out)


def _num(x: float) -> str:
    m, e = f"{x:.3e}".split("e")
    return f"${m}\\times10^{{{int(e)}}}$"


def tex(b: Budget, name: str) -> str:
    sc = b.scene
    rows, bars, labels = [], [], []
    for r in b.rows:
        size = r.value if r.status == "kept" else (r.estimate if r.status == "dropped" else None)
        val = "--" if size is None else ("(the base)" if math.isinf(size) else _num(size))
        err = "?" if math.isnan(r.error) else _num(r.error)
        rows.append(f"{escape(r.title)} & {escape(r.source)} & {val} & {err} & {r.status} \\\\")
        if size is not None and size != 0 and math.isfinite(size):
            labels.append(escape(r.key))
            bars.append((len(labels) - 1, abs(size), max(r.error, 1e-30) if math.isfinite(r.error) else None))
    if b.interaction:
        rows.append(f"coupling of the kept effects & (bound) & -- & {_num(b.interaction)} & \\\\")
    size_coords = " ".join(f"({v:.6e},{i})" for i, v, _ in bars)
    err_coords = " ".join(f"({e:.6e},{i})" for i, _, e in bars if e)
    answer = [f"Period: {b.period:.12g} s $\\pm$ {b.error * b.period:.2g} s (relative {b.error:.2g})",
              f"Swing time: {b.swing:.12g} s"]
    if b.sensitivity is not None and "sensitivity" in sc.wanted.quantities:
        answer.append(f"Sensitivity $d\\log T/d\\log g$: {b.sensitivity:+.6g} $\\pm$ {b.sensitivity_error:.2g}")
    if b.temperature is not None:
        answer.append(f"Temperature coefficient $d\\log T/d\\vartheta$: {b.temperature:+.6g} $\\pm$ "
                      f"{b.temperature_error:.2g} per K")
    if b.rate is not None:
        answer.append(f"Rate: {b.rate:+.4g} s/day against {sc.wanted.target_period:g} s "
                      f"($\\pm$ {b.error * SECONDS_PER_DAY:.2g} s/day)")
    verdict = "within" if b.within else "NOT within"
    answer.append(f"Estimated error {b.error:.2g} is {verdict} the tolerance {sc.wanted.tolerance:g}; "
                  f"{b.built} of {b.total} Results built.")
    answer_tex = " \\\\ ".join(answer)
    rows_tex = "\n".join(rows)
    chart = ""
    every = [v for _, v, _ in bars] + [e for _, _, e in bars if e] + [sc.wanted.tolerance]
    xmin = max(min(every) / 10, 1e-18)
    xmax = max(every) * 10
    if bars:
        chart = rf"""
\begin{{tikzpicture}}
\begin{{axis}}[xbar, xmode=log, width=0.85\textwidth, height={2.5 + 1.4 * len(bars):.1f}cm, bar width=7pt,
  xmin={xmin:.1e}, xmax={xmax:.1e}, xticklabel style={{font=\scriptsize}}, log basis x=10,
  ytick={{{",".join(str(i) for i in range(len(labels)))}}}, yticklabels={{{",".join(labels)}}},
  xlabel={{$|\Delta T/T|$ and its estimated error}}, legend pos=outer north east, enlarge y limits=0.3,
  log origin=infty]
\addplot coordinates {{{size_coords}}};
\addplot coordinates {{{err_coords}}};
\legend{{size, error}}
\draw[red, dashed] (axis cs:{sc.wanted.tolerance:.3e},-1) -- (axis cs:{sc.wanted.tolerance:.3e},{len(bars)});
\end{{axis}}
\end{{tikzpicture}}
(dashed: the tolerance)"""
    return rf"""\documentclass[10pt]{{article}}
\usepackage[a4paper,margin=1.6cm]{{geometry}}
\usepackage[T1]{{fontenc}}
\usepackage[utf8]{{inputenc}}
\usepackage{{textcomp,lmodern,pgfplots,tabularx,booktabs}}
\pgfplotsset{{compat=1.16}}
\DeclareUnicodeCharacter{{0394}}{{$\Delta$}}
\DeclareUnicodeCharacter{{03B1}}{{$\alpha$}}
\DeclareUnicodeCharacter{{03B4}}{{$\delta$}}
\DeclareUnicodeCharacter{{03BB}}{{$\lambda$}}
\DeclareUnicodeCharacter{{00B2}}{{$^2$}}
\DeclareUnicodeCharacter{{2212}}{{$-$}}
\DeclareUnicodeCharacter{{2013}}{{--}}
\DeclareUnicodeCharacter{{2014}}{{---}}
\DeclareUnicodeCharacter{{2264}}{{$\leq$}}
\DeclareUnicodeCharacter{{03BC}}{{$\mu$}}
\DeclareUnicodeCharacter{{03B5}}{{$\varepsilon$}}
\DeclareUnicodeCharacter{{03C0}}{{$\pi$}}
\DeclareUnicodeCharacter{{0393}}{{$\Gamma$}}
\DeclareUnicodeCharacter{{221A}}{{$\surd$}}
\DeclareUnicodeCharacter{{2192}}{{$\to$}}
\pagestyle{{empty}}
\begin{{document}}
\section*{{{escape(name)}}}
{answer_tex}

\medskip
Base: {escape(b.base)} = {b.T0:.12g} s.

\medskip
{{\small
\begin{{tabularx}}{{\textwidth}}{{p{{4.6cm}}Xrrl}}
\toprule
effect & source & $\Delta T/T$ & error & status \\
\midrule
{rows_tex}
\bottomrule
\end{{tabularx}}}}

\medskip
{chart}
\end{{document}}
"""


def write(b: Budget, name: str, out: Path | str) -> Path:
    """Compile the page and move it to ``out``; a one-line SceneError if that cannot be done."""
    out = Path(out)
    if shutil.which("latexmk") is None:
        raise SceneError("--pdf needs latexmk and pgfplots (make tex-tools)")
    if not out.parent.is_dir() or not os.access(out.parent, os.W_OK):
        raise SceneError(f"cannot write {out}: its directory is missing or not writable")
    with tempfile.TemporaryDirectory(prefix="pendsym-scene-") as tmp:
        src = Path(tmp) / "scene.tex"
        src.write_text(tex(b, name), encoding="utf-8")
        try:
            p = subprocess.run(["latexmk", "-pdf", "-interaction=nonstopmode", "-halt-on-error", "scene.tex"],
                               cwd=tmp, capture_output=True, text=True, timeout=300)
        except (OSError, subprocess.TimeoutExpired) as exc:
            raise SceneError(f"latexmk could not run: {exc}") from None
        pdf = Path(tmp) / "scene.pdf"
        if p.returncode != 0 or not pdf.is_file():
            last = next((ln for ln in reversed(p.stdout.splitlines()) if ln.startswith("!")), "see the LaTeX log")
            raise SceneError(f"LaTeX failed on the scene's page: {last}")
        try:
            shutil.copyfile(pdf, str(out) + ".part")
            os.replace(str(out) + ".part", out)
        except OSError as exc:
            raise SceneError(f"cannot write {out}: {exc.strerror}") from None
    return out
