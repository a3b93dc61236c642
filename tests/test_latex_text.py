"""The text and the formulas of the reports: every character mapped, the small markup of the
texts set as math, the code's names never leaking into a formula."""
import re
import shutil
import subprocess

import pytest
import sympy as sp

from pendsym import pipeline, registry
from pendsym.emit import texlog
from pendsym.emit.mathtex import abbreviation_names, display, tex_expr, width
from pendsym.emit.textex import UNKNOWN, literal_points, tex_name, tex_ocr, tex_text

FALLBACK = UNKNOWN.split("%")[0]      # the marker of a character outside the maps


def _strings(x):
    if isinstance(x, str):
        yield x
    elif isinstance(x, dict):
        for k, v in x.items():
            yield from _strings(k)
            yield from _strings(v)
    elif isinstance(x, (list, tuple)):
        for v in x:
            yield from _strings(v)


@pytest.fixture(scope="module")
def texts(generated):
    """Every text of the project a report prints: the Specs' titles, notes, readings and sources,
    the memoirs' titles and headings, and the evidence's strings in results.json."""
    out = set()
    for m in registry.memoirs().values():
        out.add(m.title)
        out |= {h.title for h in m.report_headings()}
        for s in m.specs:
            out |= {s.title, s.note, s.source.ref(), s.source.para}
            for r in s.readings:
                out |= {r.shows, r.read_as}
    for rec in pipeline.load_results_json(generated / "results.json").values():
        out |= {rec["title"], rec["note"], rec["ref"], rec["comparison"]}
        out |= set(_strings(rec["readings"]))
        if rec["evidence"]:
            ev = rec["evidence"]
            out |= {ev["truth"], ev["note"], ev["param"] or ""}
            out |= set(_strings(ev["params"]))
    return sorted(t for t in out if t)


def test_every_character_of_the_texts_is_mapped(texts):
    chars = sorted({ch for t in texts for ch in t if ord(ch) > 127})
    assert "𝕄" in chars and "∈" in chars          # the collection does reach the texts
    for ch in chars:
        tex = tex_text(ch)
        assert tex and "?" not in tex and FALLBACK not in tex, (ch, hex(ord(ch)), tex)
        assert all(ord(c) < 128 or c in "àâäáãçèéêëìíîïñòóôöõùúûüýÿÀÂÄÁÃÇÈÉÊËÌÍÎÏÑÒÓÔÖÕÙÚÛÜÝ" for c in tex), (ch, tex)


def test_no_text_gains_a_question_mark(texts):
    for t in texts:
        for tex in (tex_text(t), tex_ocr(t)):
            assert tex.count("?") == t.count("?"), (t, tex)
            assert FALLBACK not in tex, (t, tex)


@pytest.mark.parametrize("char, tex", [
    ("𝕄", r"$\mathbb{M}$"), ("∈", r"$\in$"), ("§", r"\S{}"), ("¶", r"\P{}"), ("Σ", r"$\Sigma$"),
    ("ħ", r"$\hbar$"), ("ı", r"\i{}"), ("⅔", r"$\tfrac{2}{3}$"), ("ψ", r"$\psi$"), ("θ″", r"$\theta ''$"),
])
def test_the_characters_the_issue_names(char, tex):
    assert tex_text(char) == tex


@pytest.mark.parametrize("text, tex", [
    ("J_{m−2}", "J$_{m-2}$"),
    ("e^(-u)", "e$^{-u}$"),
    ("4U_1^3", "4U$_{1}^{3}$"),
    ("dw_λ", r"dw$_{\lambda}$"),
    ("θ''", r"$\theta ''$"),
    ("x'_0", "x$'_{0}$"),
    ("β′0", r"$\beta '_{0}$"),
    ("v0 and β1", r"v$_{0}$ and $\beta _{1}$"),
    ("(beta_1 of", r"($\beta_{1}$ of"),
    ("Haag's memoir, d'un pendule, l'équation", "Haag's memoir, d'un pendule, l'équation"),
    ("K'U + U_1", "K$'$U + U$_{1}$"),
    ("mpmath lu_solve", r"mpmath \texttt{lu\_\allowbreak{}solve}"),
    ("pendsym.blade", r"\texttt{pendsym.\allowbreak{}blade}"),
    ("100% & $5 #1", r"100\% \& \$5 \#1"),
    ("∫_0^s' φ ds''", r"$\int _{0}^{s'}$ $\varphi$ ds$''$"),      # the prime in the bound, not a 2nd superscript
    ("θ∭ ds", r"$\theta \iiint$ ds"),
    ("m′/m = 10⁻⁸, x₁₂", r"m$'$/m = 10$^{-8}$, x$_{12}$"),       # one script, not ^{-}^{8}
])
def test_markup_of_the_texts_is_set_as_math(text, tex):
    assert tex_text(text) == tex


def test_python_literals_read_as_name_value():
    assert tex_text("with {'m': '1', \"m'\": '0.37', 'lam': mpf('0.29999999999999999')}") == \
        r"with $m = 1$, $m' = 0.37$, $\lambda = 0.3$"
    points = literal_points("{'profile': 'hole', 'i': 0}; {'profile': 'tapered', 'i': 1}")
    assert points == ["profile = hole, $i = 0$", "profile = tapered, $i = 1$"]
    assert literal_points("1.3") is None


def test_ocr_latex_is_set_as_a_formula():
    assert tex_ocr(r"\frac{1}{5u}(U_2^4 + 4U_1^3)") == r"$\frac{1}{5u}(U_2^4 + 4U_1^3)$"
    assert tex_ocr(r"\input{x}") == r"\textbackslash{}input\{x\}"     # not a formula: escaped


@pytest.mark.parametrize("name, tex", [
    ("dbeta_1", r"d\beta_{1}"), ("theta''", r"\theta''"), ("alpha'", r"\alpha'"), ("x1dd", r"\ddot{x}_{1}"),
    ("epsilon", r"\varepsilon"), ("dlambda", r"d\lambda"), ("dR/R", r"\left(dR/R\right)"),
])
def test_code_names_never_leak_into_formulas(name, tex):
    assert tex_expr(sp.Symbol(name)) == tex
    assert "dbeta" not in tex_expr(sp.Symbol("K") * sp.Symbol("dbeta_1"))


def test_plot_axes_read_as_symbols():
    assert tex_name("epsilon") == r"\varepsilon"
    assert tex_name("rho c/n") == r"\rho c/n"
    assert tex_name("omega_i") == r"\omega_{i}"


def test_a_long_sum_is_broken_between_its_terms():
    x = sp.Symbol("x")
    e = sum(sp.Symbol(f"a_{k}") * sp.tanh(x / 2) ** k / (k + 1) for k in range(24))
    lines, where = display("F", e, 38)
    assert len(lines) > 2 and not where
    assert lines[0].startswith("F = ")
    assert all(width(ln) <= 38 for ln in lines)
    assert sp.srepr(e)  # the expression itself is untouched


def test_repeated_large_parts_are_named():
    u, R, a = sp.symbols("u R a", positive=True)
    big = sum(sp.Symbol(f"c_{k}") * sp.tanh(u / 2) ** k * u ** (k % 3) for k in range(12))
    e = sp.sqrt(R ** 2 + big ** 2) / (a - sp.sqrt(R ** 2 + big ** 2) + big)
    lines, where = display("z", e, 38, abbreviation_names())
    assert where and r"\mathsf{A}" in lines[0]
    assert all(width(ln) <= 1.1 * 38 for ln in lines)


@pytest.mark.skipif(shutil.which("pdflatex") is None, reason="TeX Live is not installed (make tex-tools)")
def test_every_text_compiles_without_a_missing_glyph(texts, tmp_path):
    body = "\n\n".join(tex_text(t) for t in texts)
    doc = (r"\documentclass{article}\usepackage[utf8]{inputenc}\usepackage[T1]{fontenc}\usepackage{lmodern,textcomp}"
           r"\usepackage{amsmath,amssymb}\usepackage[margin=2cm]{geometry}\tracinglostchars=2"
           "\n\\begin{document}\\sloppy\n" + body + "\n\\end{document}\n")
    (tmp_path / "t.tex").write_text(doc, encoding="utf-8")
    subprocess.run(["pdflatex", "-interaction=nonstopmode", "t.tex"], cwd=tmp_path, capture_output=True,
                   timeout=300, env={"PATH": "/usr/bin:/bin", "max_print_line": "10000"})
    found = [p for p in texlog.check_log(tmp_path / "t.log", limit=1e9)]
    assert not found, "\n".join(map(str, found))
    assert (tmp_path / "t.pdf").exists()


def test_no_raw_markup_outside_math_in_the_reports(generated):
    """No ^ or _ reaches text mode (a raw ^ breaks the PDF, an escaped one shows markup)."""
    for tex in sorted((generated / "tex").glob("*.tex")):
        text = tex.read_text()
        body = text.split(r"\begin{document}", 1)[1]
        body = re.sub(r"\\\$", "", body)
        body = re.sub(r"\$[^$]*\$", "", body)                       # inline math
        body = re.sub(r"^\\fline\{.*\}$", "", body, flags=re.M)     # formula lines
        body = re.sub(r"\\(texttt|kname|input)\{[^{}]*(?:\{\}[^{}]*)*\}", "", body)
        body = re.sub(r"\{\\resultid [^{}]*\}", "", body)                # a Result's id (\_ is its underscore)
        body = re.sub(r"\\[`'^\"~=]\{[a-zA-Z]\}", "", body)             # an accented letter (\^{j}: ĵ)
        body = re.sub(r"^\\(addplot|begin\{loglogaxis\}|begin\{xltabular\}).*$|^  legend .*$", "", body, flags=re.M)
        body = re.sub(r"xlabel=\{[^}]*\},ylabel=\{[^}]*\}", "", body)
        for bad in ("^", "textasciicircum", r"\_"):
            i = body.find(bad)
            assert i < 0, (tex.name, body[max(0, i - 80):i + 40])
        i = re.search(r"(?<!\\)_", body)
        assert i is None, (tex.name, body[max(0, i.start() - 80):i.start() + 40])


def test_a_primed_subscripted_base_is_braced_before_a_power():
    from pendsym.emit.mathtex import ReportLatex
    y0, z = sp.Symbol("y'_0"), sp.Symbol("z'")
    assert ReportLatex().doprint(y0**2) == "{y'_{0}}^{2}"       # y'_{0}^{2} is a double superscript in TeX
    assert ReportLatex().doprint(z**2) == "z'^{2}"
