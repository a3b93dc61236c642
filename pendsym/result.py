"""The records of the pipeline: a Spec says how to build a Result, a Result is built.

A Spec is pure data plus two pure functions (``printed`` and ``derive``).  The
registry turns Specs into Results lazily, building only the dependency closure
of what is asked for.  Nothing here knows a particular memoir.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable, Mapping

import sympy as sp


@dataclass(frozen=True)
class Source:
    """Where a result stands in its memoir."""

    memoir: str                 # the memoir's key (the first part of every Result id)
    para: str                   # paragraph and sub-item, e.g. "n°21, 5°"
    page: int | None = None     # page of the printed memoir
    eq: str | None = None       # equation number, where the memoir has one
    quote: str = ""             # context for memoirs without numbers

    def ref(self) -> str:
        parts = [self.para]
        if self.eq:
            parts.append(f"eq. {self.eq}")
        if self.page is not None:
            parts.append(f"p. {self.page}")
        return ", ".join(parts)


@dataclass(frozen=True)
class Reading:
    """One OCR reading: what the text shows and how we read it."""

    shows: str
    read_as: str
    certain: bool = True


@dataclass(frozen=True)
class KernelArg:
    """One argument of a generated kernel, with its declared domain."""

    name: str        # the SymPy symbol's name
    lo: float
    hi: float
    log: bool = True  # sample geometrically (True) or linearly
    unit: str = "1"


@dataclass(frozen=True)
class KernelSpec:
    """Ask the emitters for a Python and a C kernel of a Result's derived form."""

    args: tuple[KernelArg, ...]
    doc: str = ""
    unit: str = "1"
    # the obvious double-precision reading of the printed form's symbols (U → th(u/2) …), for
    # measuring the naive transcription against the kernel; the Spec's defs when empty
    naive_defs: tuple[tuple[sp.Symbol, sp.Expr], ...] = ()


@dataclass(frozen=True)
class Evidence:
    """What an independent check found.  Numbers are floats rounded for JSON."""

    kind: str                           # order | quadrature | proof | value | identity
    passed: bool
    truth: str                          # how the truth was computed (the model)
    max_residual: float | None = None
    order: float | None = None
    expected_order: float | None = None
    band: tuple[float, float] | None = None
    param: str | None = None            # the small parameter of an order check
    params: tuple[tuple[str, str], ...] = ()
    series: tuple[tuple[float, float], ...] = ()          # (parameter, |residual| of derived)
    printed_series: tuple[tuple[float, float], ...] = ()  # same, for the printed form
    printed_order: float | None = None
    printed_agrees: bool | None = None
    confirm_digits: float | None = None  # agreement of truth at two precisions
    values: tuple[tuple[float, float, float], ...] = ()     # (parameter, truth, derived formula)
    note: str = ""


@dataclass(frozen=True)
class Spec:
    """How to obtain one Result.

    ``derive(deps)`` receives the built dependencies by id and returns the
    derived SymPy expression; ``printed()`` returns the transcription of the
    memoir's text (None when the memoir prints nothing for it).
    ``check(result, level)`` runs the independent verification.
    """

    id: str
    title: str
    source: Source
    lhs: str                                              # LaTeX of the quantity
    derive: Callable[[Mapping[str, "Result"]], sp.Basic]
    deps: tuple[str, ...] = ()
    printed: Callable[[], sp.Basic] | None = None
    readings: tuple[Reading, ...] = ()
    check: Callable[["Result", str], Evidence] | None = None
    kernel: KernelSpec | None = None
    note: str = ""
    definition: bool = False   # a pure definition: listed, not a claim
    show_values: bool = False  # the report also plots truth and formula against the parameter
    defs: tuple[tuple[sp.Symbol, sp.Expr], ...] = ()  # the memoir's definitions (T = π/k …)
    # substitutions of undefined functions (φ → a test function) under which
    # printed and derived are compared when they hold an arbitrary function
    instances: tuple[tuple[tuple[sp.Basic, sp.Basic], ...], ...] = ()
    # the printed form is an approximate number given to this many decimals ("1,2 environ"):
    # it matches when it is the derived value rounded to them (truncation is said, not matched);
    # for a Tuple, one number of decimals per component
    printed_decimals: int | tuple[int, ...] | None = None

    @property
    def memoir(self) -> str:
        return self.source.memoir


def printed(expr: sp.Basic) -> Callable[[], sp.Basic]:
    """A transcription held as data, in the form a Spec asks for (a function giving it)."""
    return lambda: expr


@dataclass(frozen=True)
class Result:
    """A built Result: its Spec, the printed and the derived expressions."""

    spec: Spec
    derived: sp.Basic
    printed: sp.Basic | None = None
    deps: Mapping[str, "Result"] = field(default_factory=dict, compare=False, repr=False)

    @property
    def id(self) -> str:
        return self.spec.id

    @property
    def printed_value(self) -> sp.Basic | None:
        """The printed form with the memoir's definitions applied (for comparison)."""
        if self.printed is None:
            return None
        return self.printed.subs(dict(self.spec.defs), simultaneous=True)

    @property
    def derived_value(self) -> sp.Basic:
        """The derived form under the same definitions (a domain such as m = 2n+1 included)."""
        return self.derived.subs(dict(self.spec.defs), simultaneous=True)

    def symbols(self) -> tuple[sp.Symbol, ...]:
        """Free symbols of both forms, sorted by name, with their assumptions."""
        free = set(self.derived.free_symbols)
        if self.printed is not None:
            free |= self.printed.free_symbols
        return tuple(sorted(free, key=lambda s: s.name))
