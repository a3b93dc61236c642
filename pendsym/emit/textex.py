"""Text for the LaTeX reports: prose, names and the small markup of the project's strings.

The texts of the Specs and of the evidence (titles, notes, readings, truths) are prose with a
light, informal notation: Unicode letters and signs (θ″, ∈, 𝕄, ½), scripts written the plain way
(``J_{m−2}``, ``4U_1^3``, ``e^(-u)``, ``dw_λ``), primes as apostrophes (``θ''``), identifiers of
the code (``pendsym.suspension.modes``, ``lu_solve``) and Python literals (``{'m': '1'}``).
:func:`tex_text` turns such a text into LaTeX: scripts and primes in math, every character mapped
to a proper LaTeX form (never "?"), identifiers in breakable typewriter type, literals as
``name = value`` lists.  :func:`tex_name` turns a name of the code (``omega_i``, ``rho c/n``,
``dbeta_1``) into math.
"""
from __future__ import annotations

import ast
import re
import unicodedata

# Greek letters by name, as the code spells them (epsilon and phi as the memoirs print them)
GREEK_NAMES = {
    "alpha": r"\alpha", "beta": r"\beta", "gamma": r"\gamma", "delta": r"\delta", "epsilon": r"\varepsilon",
    "varepsilon": r"\varepsilon", "zeta": r"\zeta", "eta": r"\eta", "theta": r"\theta", "vartheta": r"\vartheta",
    "iota": r"\iota", "kappa": r"\kappa", "lambda": r"\lambda", "lam": r"\lambda", "mu": r"\mu", "nu": r"\nu",
    "xi": r"\xi", "pi": r"\pi", "rho": r"\rho", "sigma": r"\sigma", "tau": r"\tau", "upsilon": r"\upsilon",
    "phi": r"\varphi", "varphi": r"\varphi", "chi": r"\chi", "psi": r"\psi", "omega": r"\omega",
    "Gamma": r"\Gamma", "Delta": r"\Delta", "Theta": r"\Theta", "Lambda": r"\Lambda", "Xi": r"\Xi", "Pi": r"\Pi",
    "Sigma": r"\Sigma", "Phi": r"\Phi", "Psi": r"\Psi", "Omega": r"\Omega",
}

# Characters set in math (the value is math-mode LaTeX).
MATH_CHARS = {
    # Greek
    "α": r"\alpha", "β": r"\beta", "γ": r"\gamma", "δ": r"\delta", "ε": r"\varepsilon", "ϵ": r"\epsilon",
    "ζ": r"\zeta", "η": r"\eta", "θ": r"\theta", "ϑ": r"\vartheta", "ι": r"\iota", "κ": r"\kappa",
    "λ": r"\lambda", "μ": r"\mu", "µ": r"\mu", "ν": r"\nu", "ξ": r"\xi", "π": r"\pi", "ρ": r"\rho",
    "σ": r"\sigma", "ς": r"\varsigma", "τ": r"\tau", "υ": r"\upsilon", "φ": r"\varphi", "ϕ": r"\phi",
    "χ": r"\chi", "ψ": r"\psi", "ω": r"\omega",
    "Γ": r"\Gamma", "Δ": r"\Delta", "Θ": r"\Theta", "Λ": r"\Lambda", "Ξ": r"\Xi", "Π": r"\Pi",
    "Σ": r"\Sigma", "Υ": r"\Upsilon", "Φ": r"\Phi", "Ψ": r"\Psi", "Ω": r"\Omega",
    # letter-like
    "ħ": r"\hbar", "ℏ": r"\hbar", "ℓ": r"\ell", "𝕄": r"\mathbb{M}", "𝕋": r"\mathbb{T}", "ℝ": r"\mathbb{R}", "ℕ": r"\mathbb{N}",
    "ℤ": r"\mathbb{Z}", "ℂ": r"\mathbb{C}", "∂": r"\partial", "∇": r"\nabla",
    # primes
    "′": "'", "″": "''", "‴": "'''",
    # scripts
    "⁰": "^{0}", "¹": "^{1}", "²": "^{2}", "³": "^{3}", "⁴": "^{4}", "⁵": "^{5}", "⁶": "^{6}", "⁷": "^{7}",
    "⁸": "^{8}", "⁹": "^{9}", "⁺": "^{+}", "⁻": "^{-}", "ⁿ": "^{n}", "ⁱ": "^{i}",
    "₀": "_{0}", "₁": "_{1}", "₂": "_{2}", "₃": "_{3}", "₄": "_{4}", "₅": "_{5}", "₆": "_{6}", "₇": "_{7}",
    "₈": "_{8}", "₉": "_{9}", "₊": "_{+}", "₋": "_{-}",
    # fractions
    "½": r"\tfrac{1}{2}", "⅓": r"\tfrac{1}{3}", "⅔": r"\tfrac{2}{3}", "¼": r"\tfrac{1}{4}", "¾": r"\tfrac{3}{4}",
    "⅛": r"\tfrac{1}{8}",
    # operators and relations
    "−": "-", "±": r"\pm", "∓": r"\mp", "×": r"\times", "·": r"\cdot", "÷": r"\div", "∘": r"\circ",
    "≡": r"\equiv", "≤": r"\le", "≥": r"\ge", "≠": r"\ne", "≈": r"\approx", "≃": r"\simeq", "∼": r"\sim",
    "≪": r"\ll", "≫": r"\gg", "∝": r"\propto", "∈": r"\in", "∉": r"\notin", "⊂": r"\subset", "∩": r"\cap",
    "∪": r"\cup", "⊥": r"\perp", "∥": r"\parallel", "∞": r"\infty", "√": r"\surd", "∫": r"\int", "∬": r"\iint", "∭": r"\iiint", "∮": r"\oint",
    "∑": r"\sum", "∏": r"\prod", "∀": r"\forall", "∃": r"\exists", "∅": r"\emptyset",
    "→": r"\to", "←": r"\leftarrow", "↔": r"\leftrightarrow", "⇄": r"\rightleftarrows", "⇒": r"\Rightarrow",
    "⇔": r"\Leftrightarrow", "↦": r"\mapsto", "⟨": r"\langle", "⟩": r"\rangle", "▶": r"\blacktriangleright",
    "…": r"\ldots", "⋯": r"\cdots", "¬": r"\neg", "∧": r"\wedge", "∨": r"\vee", "∠": r"\angle",
}

# Characters set in text (the value is text-mode LaTeX); T1 + utf8 inputenc set the accented
# Latin letters themselves, listed here so that the map is complete.
TEXT_CHARS = {
    "§": r"\S{}", "¶": r"\P{}", "°": r"\textdegree{}", "«": r"\guillemotleft{}", "»": r"\guillemotright{}",
    "‹": r"\guilsinglleft{}", "›": r"\guilsinglright{}", "–": "--", "—": "---", "‘": "`", "’": "'",
    "“": "``", "”": "''", "„": ",,", "ı": r"\i{}", "ȷ": r"\j{}", "ß": r"\ss{}", "æ": r"\ae{}", "œ": r"\oe{}",
    "Æ": r"\AE{}", "Œ": r"\OE{}", "ø": r"\o{}", "Ø": r"\O{}", "å": r"\aa{}", "Å": r"\AA{}",
    "\u00a0": "~", "\u2009": r"\,", "\u202f": r"\,", "─": "--", "•": r"\textbullet{}", "†": r"\dag{}",
    "‡": r"\ddag{}", "©": r"\textcopyright{}", "№": r"N\textsuperscript{o}",
}
for _ch in "àâäáãçèéêëìíîïñòóôöõùúûüýÿÀÂÄÁÃÇÈÉÊËÌÍÎÏÑÒÓÔÖÕÙÚÛÜÝ":
    TEXT_CHARS[_ch] = _ch
_ACCENTS = {"\u0300": "`", "\u0301": "'", "\u0302": "^", "\u0308": '"', "\u0303": "~", "\u0304": "=",
            "\u0327": "c", "\u030c": "v", "\u0306": "u", "\u0307": "."}

SPECIAL = {"\\": r"\textbackslash{}", "&": r"\&", "%": r"\%", "$": r"\$", "#": r"\#", "_": r"\_",
           "{": r"\{", "}": r"\}", "~": r"\textasciitilde{}", "^": r"\textasciicircum{}",
           "<": r"\textless{}", ">": r"\textgreater{}", "|": r"\textbar{}", '"': r"\textquotedbl{}"}
UNKNOWN = r"\textsf{[U+%04X]}"   # never reached by the project's texts (a test keeps it so)


def char_text(ch: str) -> str:
    """One character as text-mode LaTeX (math characters wrapped in $…$)."""
    if ch in SPECIAL:
        return SPECIAL[ch]
    if ord(ch) < 128:
        return ch
    if ch in TEXT_CHARS:
        return TEXT_CHARS[ch]
    if ch in MATH_CHARS:
        return f"${MATH_CHARS[ch]}$"
    return _decomposed(ch)


def char_math(ch: str) -> str:
    """One character as math-mode LaTeX."""
    if ch in MATH_CHARS:
        return MATH_CHARS[ch] + (" " if MATH_CHARS[ch][-1].isalpha() else "")
    if ch in "{}":
        return "\\" + ch
    if ch in "&%$#":
        return "\\" + ch
    if ch == "\\":
        return r"\backslash "
    if ord(ch) < 128:
        return ch
    return r"\text{" + char_text(ch) + "}"


def _decomposed(ch: str) -> str:
    """A character outside the maps: an accented letter by its accent, else its code point."""
    base, *marks = unicodedata.normalize("NFD", ch)
    if marks and ord(base) < 128 and all(m in _ACCENTS for m in marks):
        out = base
        for m in marks:
            out = "\\" + _ACCENTS[m] + "{" + out + "}"
        return out
    return UNKNOWN % ord(ch)


# --------------------------------------------------------------------------- names
_NAME = re.compile(r"([A-Za-z]+)")


def _word_math(word: str) -> str:
    if word in GREEK_NAMES:
        return GREEK_NAMES[word]
    if len(word) > 1 and word[0] == "d" and word[1:] in GREEK_NAMES and word[1:] not in ("elta", "eta"):
        return "d" + GREEK_NAMES[word[1:]]            # dbeta → dβ (a differential)
    if len(word) >= 3 and word.islower():
        return r"\mathrm{" + word + "}"               # amplitude, max
    return word


def tex_name(name: str) -> str:
    """A name of the code as math (no $): ``omega_i`` → ω_i, ``alpha'`` → α', ``rho c/n`` → ρ c/n,
    ``beta_t`` → β_t, ``dbeta_1`` → dβ_1, ``x1ddot`` → ẍ_1."""
    m = re.fullmatch(r"([A-Za-z]+?)(\d*)(ddot|dd|dot)", name)
    if m and (m.group(1) in GREEK_NAMES or len(m.group(1)) == 1):
        acc = r"\dot" if m.group(3) == "dot" else r"\ddot"
        sub = f"_{{{m.group(2)}}}" if m.group(2) else ""
        return f"{acc}{{{_word_math(m.group(1))}}}{sub}"
    head, _, sub = name.partition("_")
    out = _math_words(head).strip()
    if sub:
        out += "_{" + ",".join(_math_words(p).strip() for p in sub.split("_")) + "}"
    return re.sub(r" +", " ", out)


def _math_words(s: str) -> str:
    out, last = [], 0
    for m in _NAME.finditer(s):
        out.append(_math_chars(s[last:m.start()]))
        w = _word_math(m.group(1))
        out.append(w)
        nxt = s[m.end():m.end() + 1]
        if w.startswith("\\") and w[-1].isalpha() and (nxt.isalnum() or nxt in " "):
            out.append(" ")
        last = m.end()
    out.append(_math_chars(s[last:]))
    return "".join(out).replace("  ", " ")


def _math_chars(s: str) -> str:
    return "".join(char_math(ch) for ch in s)


# --------------------------------------------------------------------------- literals
_MPF = re.compile(r"mpf\('([^']*)'\)")
_WORD_KEY = re.compile(r"[a-z]{3,}")


def tex_number(v) -> str | None:
    """A number as math (a true minus, 1.1e-5 as 1.1 × 10⁻⁵, rounding noise such as
    0.29999999999999999 removed); None if v is not a number."""
    s = str(v).strip().replace("−", "-")
    try:
        f = float(s)
    except ValueError:
        return None
    if re.fullmatch(r"-?\d+\.\d{12,}", s):
        s = f"{f:.12g}"
    m = re.fullmatch(r"(-?[\d.]+)[eE]([-+]?)0*(\d+)", s)
    if m:
        mant = "" if m.group(1) in ("1", "1.0") else m.group(1) + r"\times "
        return f"{mant}10^{{{'-' if m.group(2) == '-' else ''}{m.group(3)}}}"
    return s


def _value(v) -> tuple[bool, str]:
    """(is math, LaTeX) of a value of a literal."""
    num = tex_number(v)
    return (True, num) if num is not None else (False, tex_text(str(v)))


def key_math(key: str) -> str | None:
    """A key of the code's parameters as math when it is a symbol (alpha, omega_i, l_0, h/l, A_1);
    None for a word (profile, pendulum)."""
    if _WORD_KEY.fullmatch(key) and key not in GREEK_NAMES:
        return None
    return tex_name(key)


def key_value(key: str, value) -> str:
    """``key = value`` as LaTeX, in one math when both are math."""
    k = key_math(str(key))
    vm, v = _value(value)
    if k is not None and vm:
        return f"${k} = {v}$"
    return (f"${k}$" if k is not None else tex_text(str(key))) + " = " + (f"${v}$" if vm else v)


def literal_tex(obj) -> str | None:
    """A dict (or a list of dicts) of the code as ``name = value`` LaTeX; None if it is neither."""
    if isinstance(obj, dict):
        return ", ".join(key_value(k, v) for k, v in obj.items())
    if isinstance(obj, (list, tuple)) and obj and all(isinstance(x, dict) for x in obj):
        return "; ".join(literal_tex(x) for x in obj)
    return None


def _dicts(s: str) -> list[tuple[int, int, dict]]:
    """The Python dict literals in s: (start, end, value)."""
    found = []
    i = 0
    while i < len(s):
        if s[i] == "{" and re.match(r"\{\s*['\"]", s[i:]):
            depth, j = 0, i
            while j < len(s):
                depth += {"{": 1, "}": -1}.get(s[j], 0)
                if depth == 0:
                    break
                j += 1
            try:
                obj = ast.literal_eval(s[i:j + 1])
            except (ValueError, SyntaxError):
                obj = None
            if isinstance(obj, dict):
                found.append((i, j + 1, obj))
                i = j + 1
                continue
        i += 1
    return found


def literal_points(value: str) -> list[str] | None:
    """A parameter value that is a list of points, each a dict ("{'profile': 'hole', …}; {…}"):
    each point as LaTeX; None if the value is anything else."""
    value = _MPF.sub(lambda m: repr(m.group(1)), value)
    found = _dicts(value)
    if not found:
        return None
    rest = value
    for a, b, _ in reversed(found):
        rest = rest[:a] + rest[b:]
    if rest.replace(";", "").strip():
        return None
    return [literal_tex(obj) for _, _, obj in found]


# --------------------------------------------------------------------------- prose
_GREEK_WORD = "|".join(sorted((g for g in GREEK_NAMES if len(g) > 2), key=len, reverse=True))
_TOKEN = re.compile(
    r"(?P<code>(?<![\w.])[A-Za-z_][A-Za-z0-9_]*(?:\.[A-Za-z_][A-Za-z0-9_]+)+(?:\(\))?(?:\[\d+\])?(?![\w]))"
    r"|(?P<ident>(?<![\w])[A-Za-z][A-Za-z0-9]*(?:_[A-Za-z0-9]+)+(?![\w]))"
    rf"|(?P<greek>(?<![A-Za-z])(?:{_GREEK_WORD})(?=[_'^]))"
    r"|(?P<indexed>(?<![A-Za-z0-9_.\\])[A-Za-zα-ωΑ-Ω]\d{1,2}(?![\d])(?!\.\d))"
    r"|(?P<script>[_^])"
    r"|(?P<primes>'+|[′″‴]+)"
    r"|(?P<minus>(?<![\w)\]])-(?=\d))"
)
_INDEX = re.compile(r"\d{1,2}(?![\d])(?!\.\d)")
_GREEK_AT = re.compile(rf"(?:{_GREEK_WORD})(?=[_'^])")
_SCRIPT_WORD = re.compile(r"[A-Za-z0-9]+")
_SUP_WORD = re.compile(r"[-−]?[A-Za-z0-9]+")


def _is_code(ident: str) -> bool:
    """An identifier of the code (lu_solve, ch1_model) rather than a name with a subscript (beta_1)."""
    return any(len(p) >= 4 and p not in GREEK_NAMES and not p.isdigit() for p in ident.split("_"))


def tex_code(s: str) -> str:
    """An identifier or dotted path in typewriter type, breakable after its dots and underscores."""
    out = []
    for ch in s:
        out.append(SPECIAL.get(ch, ch))
        if ch in "._":
            out.append(r"\allowbreak{}")
    return r"\texttt{" + "".join(out) + "}"


def _script_arg(s: str, i: int, sup: bool) -> tuple[str, int] | None:
    """The argument of a script at s[i]: {…}, (…) after ^, a sign and a word, or one symbol."""
    if i >= len(s):
        return None
    if s[i] == "{" or (sup and s[i] == "("):
        close = "}" if s[i] == "{" else ")"
        depth, j = 0, i
        while j < len(s):
            if s[j] == s[i]:
                depth += 1
            elif s[j] == close:
                depth -= 1
                if depth == 0:
                    return s[i + 1:j], j + 1
            j += 1
        return None
    m = (_SUP_WORD if sup else _SCRIPT_WORD).match(s, i)
    if m and sup:                      # ∫_0^s' : the primes belong to the bound (a prime after ^{s} is a
        primes = re.compile(r"['′″‴]*").match(s, m.end())          # double superscript)
        return m.group() + primes.group(), primes.end()
    if m:
        return m.group(), m.end()
    if s[i] in MATH_CHARS and (MATH_CHARS[s[i]].startswith("\\") or s[i] in "′"):
        return s[i], i + 1
    return None


def _script_math(arg: str) -> str:
    """The content of a script, in math: Greek names as letters, words of 3+ letters upright."""
    out, last = [], 0
    for m in re.finditer(r"[A-Za-z]{2,}", arg):
        out.append(_math_chars(arg[last:m.start()]))
        w = m.group()
        out.append(GREEK_NAMES[w] + " " if w in GREEK_NAMES else (r"\mathrm{" + w + "}" if len(w) >= 3 else w))
        last = m.end()
    out.append(_math_chars(arg[last:]))
    return "".join(out).strip()


def _prime_here(s: str, i: int, after_math: bool) -> bool:
    """Is the single apostrophe at s[i] a prime (θ', K'U, m', x'_0) rather than an apostrophe
    (memoir's, d'un, l'équation, qu'en)?"""
    if i == 0:
        return False
    prev = s[i - 1]
    before = s[i - 2] if i >= 2 else " "
    nxt = s[i + 1] if i + 1 < len(s) else " "
    if after_math or prev in ")]}":
        return True
    if not (prev.isalnum() and ord(prev) < 128):
        return False
    if before.isalpha():
        return False                         # the end of a word: memoir's
    if nxt.isalpha() and nxt.islower():
        return False                         # an elision: d'un, l'équation
    return True


class _Pieces:
    """Text and math pieces; adjacent maths are joined into one $…$."""

    def __init__(self):
        self.items: list[list] = []

    def text(self, s: str):
        if s:
            self.items.append(["t", s])

    def math(self, s: str):
        if not s:
            return
        if self.items and self.items[-1][0] == "m":
            prev = self.items[-1][1]
            script = re.search(r"([\^_])\{([^{}]*)\}$", prev)
            if script and re.fullmatch(r"[\^_]\{[^{}]*\}", s) and s[0] == script.group(1):
                self.items[-1][1] = prev[:-1] + s[2:]          # ⁻⁸: one superscript, not two
                return
            if re.search(r"\\[A-Za-z]+$", prev) and re.match(r"[A-Za-z]", s):
                prev += " "
            self.items[-1][1] = prev + s
        else:
            self.items.append(["m", s])

    @property
    def after_math(self) -> bool:
        return bool(self.items) and self.items[-1][0] == "m"

    def latex(self) -> str:
        return "".join(s if kind == "t" else f"${s.strip()}$" for kind, s in self.items)


def tex_text(s: str) -> str:
    """Prose as LaTeX: every character mapped (never "?"), scripts and primes in math,
    identifiers of the code in breakable typewriter type, dict literals as name = value."""
    s = _MPF.sub(lambda m: repr(m.group(1)), s or "")
    out = _Pieces()
    last = 0
    for a, b, obj in _dicts(s):
        _prose(s[last:a], out)
        out.text(literal_tex(obj))
        last = b
    _prose(s[last:], out)
    return out.latex()


def _prose(s: str, out: _Pieces) -> None:
    i = 0
    while i < len(s):
        m = _TOKEN.match(s, i)
        kind = m.lastgroup if m else None
        if kind == "ident" and not _is_code(m.group()):
            m = _GREEK_AT.match(s, i)        # beta_1, m_i: letters and scripts, one by one
            kind = "greek" if m else None
        if kind is None:
            ch = s[i]
            if ch in MATH_CHARS or ch in "<>|":
                out.math(char_math(ch))
            else:
                out.text(char_text(ch))
            i += 1
            continue
        tok = m.group()
        if kind in ("code", "ident"):
            out.text(tex_code(tok))
        elif kind == "greek":
            out.math(GREEK_NAMES[tok])
        elif kind == "indexed":              # v0, β1, T0: a letter and its index
            base, digits = tok[0], tok[1:]
            if base in MATH_CHARS:
                out.math(char_math(base))
            else:
                out.text(base)
            out.math(f"_{{{digits}}}")
        elif kind == "script":
            arg = _script_arg(s, m.end(), sup=tok == "^")
            if arg is None:
                out.text(char_text(tok))
            else:
                out.math(f"{tok}{{{_script_math(arg[0])}}}")
                i = arg[1]
                continue
        elif kind == "primes":
            n = sum({"'": 1, "′": 1, "″": 2, "‴": 3}[c] for c in tok)
            if n >= 2 or tok != "'" or _prime_here(s, i, out.after_math):
                out.math("'" * n)
                index = _INDEX.match(s, m.end())          # θ'0: the index after the prime
                if index:
                    out.math(f"_{{{index.group()}}}")
                    i = index.end()
                    continue
            else:
                out.text("'")
        elif kind == "minus":
            out.math("-")
        i = m.end()


# --------------------------------------------------------------------------- OCR as LaTeX
_OCR_COMMANDS = {"frac", "tfrac", "dfrac", "sqrt", "bar", "overline", "hat", "tilde", "dot", "ddot", "left", "right",
                 "cdot", "times", "pm", "mp", "prime", "partial", "int", "sum", "infty", "ldots", "cdots", "sin",
                 "cos", "tan", "sinh", "cosh", "tanh", "log", "ln", "exp", "le", "ge", "leq", "geq", "ne", "neq",
                 "approx", "equiv", "quad", "qquad", "mathrm", "text", "operatorname", "limits", "over",
                 *(g[1:] for g in GREEK_NAMES.values())}


def tex_ocr(s: str) -> str:
    """What the OCR shows: when the OCR gave LaTeX (``\\frac{1}{5u}(U_2^4 + …)``), typeset as the
    formula it is; otherwise as prose (:func:`tex_text`)."""
    cmds = re.findall(r"\\([A-Za-z]+)", s)
    balanced = s.count("{") == s.count("}") and "$" not in s and "%" not in s and "#" not in s
    if not cmds or not balanced or any(c not in _OCR_COMMANDS for c in cmds):
        return tex_text(s)
    out = []
    for i, ch in enumerate(s):
        if ch in "{}\\" or ord(ch) < 128:
            out.append(ch)
        else:
            out.append(char_math(ch))
    return "$" + "".join(out) + "$"
