"""The text of the helpers that supplied kernel forms call (:mod:`.supplied`), printed once per file: double-double
arithmetic, the low part of a quotient, u/(1 + √(1 + t)) as a double-double, and the cross products of Bessel
functions of orders 0 and 1 (Hankel's expansion for large arguments, a Taylor series in the gap, or the library's
j0 … y1), in C and in Python."""
from __future__ import annotations

from fractions import Fraction
from typing import Sequence


HANKEL_FROM = 25.0
HANKEL_TERMS = 19
TAYLOR_RATIO = 0.5


def _hankel_coefficients(order: int) -> tuple[tuple[float, ...], tuple[float, ...]]:
    """(P, Q) coefficients of Hankel's expansion of order n in t = 1/x² (Q then times 1/x): a_k(n) =
    Π_{j ≤ k}(4n² − (2j − 1)²)/(k! 8^k), P = Σ(−1)^j a_{2j} x^{−2j}, Q = Σ(−1)^j a_{2j+1} x^{−2j−1} (A–S 9.2.9–9.2.10)."""
    def a(k: int) -> Fraction:
        out = Fraction(1)
        for j in range(1, k + 1):
            out *= Fraction(4 * order * order - (2 * j - 1) ** 2, 8 * j)
        return out
    p = tuple(float((-1) ** (k // 2) * a(k)) for k in range(0, HANKEL_TERMS + 1, 2))
    q = tuple(float((-1) ** (k // 2) * a(k)) for k in range(1, HANKEL_TERMS + 1, 2))
    return p, q


def _horner(coefficients: Sequence[float], var: str) -> str:
    out = repr(coefficients[-1])
    for c in reversed(coefficients[:-1]):
        out = f"({out})*{var} + {c!r}"
    return out


DD_C = '''/* Double-double arithmetic (hi, lo): sums by two-sum, products by fma (Dekker, Knuth). */
static void pendsym_dd_add(double ah, double al, double bh, double bl, double *rh, double *rl)
{
    const double s = ah + bh, bb = s - ah;
    const double e = ((ah - (s - bb)) + (bh - bb)) + (al + bl);
    *rh = s + e;
    *rl = e - (*rh - s);
}

static void pendsym_dd_mul(double ah, double al, double bh, double bl, double *rh, double *rl)
{
    const double p = ah*bh;
    const double e = fma(ah, bh, -p) + (ah*bl + al*bh);
    *rh = p + e;
    *rl = e - (*rh - p);
}

static void pendsym_dd_div(double ah, double al, double bh, double bl, double *rh, double *rl)
{
    const double q1 = ah/bh;
    double ph, pl, dh, dl;
    pendsym_dd_mul(q1, 0.0, bh, bl, &ph, &pl);
    pendsym_dd_add(ah, al, -ph, -pl, &dh, &dl);
    pendsym_dd_add(q1, 0.0, dh/bh, 0.0, rh, rl);
}
'''

ROOT_C = '''/* u/(1 + √(1 + t)) as a double-double: part 0 its high, part 1 its low part (1 + t by two-sum, the root corrected
 * by its exact residual, the quotient by double-double division). */
static double pendsym_root_quotient(double u, double t, double part)
{
    double ah, al, rh, rl, ph, pl, dh, dl;
    pendsym_dd_add(1.0, 0.0, t, 0.0, &ah, &al);
    rh = sqrt(ah);
    pendsym_dd_mul(rh, 0.0, rh, 0.0, &ph, &pl);
    pendsym_dd_add(ah, al, -ph, -pl, &ph, &pl);
    rl = ph/(2.0*rh);
    pendsym_dd_add(1.0, 0.0, rh, rl, &dh, &dl);
    pendsym_dd_div(u, 0.0, dh, dl, &rh, &rl);
    return part == 0 ? rh : rl;
}'''

DD_PY = '''def _pendsym_split(x):
    """Veltkamp's split of x into two 26-bit halves (x = hi + lo exactly; |x| < 1e300)."""
    c = 134217729.0 * x
    hi = c - (c - x)
    return hi, x - hi


def _pendsym_two_prod(a, b):
    """a·b = p + e exactly (Dekker)."""
    p = a * b
    ah, al = _pendsym_split(a)
    bh, bl = _pendsym_split(b)
    return p, ((ah * bh - p) + ah * bl + al * bh) + al * bl


def _pendsym_dd_add(ah, al, bh, bl):
    s = ah + bh
    bb = s - ah
    e = ((ah - (s - bb)) + (bh - bb)) + (al + bl)
    r = s + e
    return r, e - (r - s)


def _pendsym_dd_mul(ah, al, bh, bl):
    p, e = _pendsym_two_prod(ah, bh)
    e += ah * bl + al * bh
    r = p + e
    return r, e - (r - p)


def _pendsym_dd_div(ah, al, bh, bl):
    q1 = ah / bh
    ph, pl = _pendsym_dd_mul(q1, 0.0, bh, bl)
    dh, dl = _pendsym_dd_add(ah, al, -ph, -pl)
    return _pendsym_dd_add(q1, 0.0, dh / bh, 0.0)
'''

ROOT_PY = '''def _pendsym_root_quotient(u, t, part):
    """u/(1 + √(1 + t)) as a double-double: part 0 its high, part 1 its low part."""
    ah, al = _pendsym_dd_add(1.0, 0.0, t, 0.0)
    rh = math.sqrt(ah)
    ph, pl = _pendsym_two_prod(rh, rh)
    e = _pendsym_dd_add(ah, al, -ph, -pl)
    d = _pendsym_dd_add(1.0, 0.0, rh, e[0] / (2.0 * rh))
    return _pendsym_dd_div(u, 0.0, *d)[part != 0]'''



def _c_definitions() -> dict[str, str]:
    (p0, q0), (p1, q1) = _hankel_coefficients(0), _hankel_coefficients(1)
    quotient = """/* (a − b·hi)/b for hi = a/b rounded: the low part of the quotient (the residual is exact by fma). */
static double pendsym_quotient_low(double a, double b, double hi)
{
    return fma(-b, hi, a) / b;
}"""
    cross = f"""/* Hankel's P_n(x) − 1, and Q_n(x) through *q (A–S 9.2.9–9.2.10, {HANKEL_TERMS} terms, x >= {HANKEL_FROM:g}). */
static double pendsym_hankel_pq(int n, double x, double *q)
{{
    const double t = 1.0/(x*x);
    if (n == 0) {{
        *q = ({_horner(q0, "t")})/x;
        return ({_horner(p0[1:], "t")})*t;
    }}
    *q = ({_horner(q1, "t")})/x;
    return ({_horner(p1[1:], "t")})*t;
}}

/* c(x0 + h)/W(x0), W = 2/(πx): c = Y_a(x0)J_b(x) − J_a(x0)Y_b(x) solves Bessel's equation of order b in x, from
 * c(x0)/W = 0 or ∓1 and c'(x0)/W; its Taylor series in h by the recurrence of the coefficients about x0, in
 * double-double (terms t_m = f_m h^m), times √(x1/x0) (double-double), rounded once. */
static double pendsym_bessel_taylor(int a, int b, double x0, double h, double lh)
{{
    double th[4] = {{0.0, 0.0, 0.0, 0.0}}, tl[4] = {{0.0, 0.0, 0.0, 0.0}};   /* t_(m-2), t_(m-1), t_m, t_(m+1) */
    double h2, h2l, h3, h3l, h4, h4l, x2, x2l, sh, sl, nh, nl, ph, pl, dh, dl, fh, fl, slope;
    int m, small = 0;
    th[2] = a == b ? 0.0 : (a == 1 ? -1.0 : 1.0);
    if (a == b) th[3] = -h;
    else if (a == 0) pendsym_dd_div(-h, 0.0, x0, 0.0, &th[3], &tl[3]);
    pendsym_dd_mul(h, 0.0, h, 0.0, &h2, &h2l);
    pendsym_dd_mul(h2, h2l, h, 0.0, &h3, &h3l);
    pendsym_dd_mul(h3, h3l, h, 0.0, &h4, &h4l);
    pendsym_dd_mul(x0, 0.0, x0, 0.0, &x2, &x2l);
    pendsym_dd_add(th[2], tl[2], th[3], tl[3], &sh, &sl);
    slope = th[3];                                              /* Σ m t_m = h c'(x0 + h)/W */
    for (m = 0; m < 400 && small < 2; m++) {{
        const double k = (m + 2.0)*(m + 1.0);
        if (b == 0) {{
            pendsym_dd_mul(th[3], tl[3], (m + 1.0)*(m + 1.0), 0.0, &nh, &nl);
            pendsym_dd_mul(nh, nl, h, 0.0, &nh, &nl);
            pendsym_dd_mul(th[2], tl[2], x0, 0.0, &ph, &pl);
            pendsym_dd_mul(ph, pl, h2, h2l, &ph, &pl);
            pendsym_dd_add(nh, nl, ph, pl, &nh, &nl);
            pendsym_dd_mul(th[1], tl[1], h3, h3l, &ph, &pl);
            pendsym_dd_add(nh, nl, ph, pl, &nh, &nl);
            pendsym_dd_mul(x0, 0.0, k, 0.0, &dh, &dl);
        }} else {{
            pendsym_dd_mul(x0, 0.0, (m + 1.0)*(2.0*m + 1.0), 0.0, &ph, &pl);
            pendsym_dd_mul(ph, pl, h, 0.0, &ph, &pl);
            pendsym_dd_mul(th[3], tl[3], ph, pl, &nh, &nl);
            pendsym_dd_add(x2, x2l, m*(double)m - 1.0, 0.0, &ph, &pl);
            pendsym_dd_mul(ph, pl, h2, h2l, &ph, &pl);
            pendsym_dd_mul(th[2], tl[2], ph, pl, &ph, &pl);
            pendsym_dd_add(nh, nl, ph, pl, &nh, &nl);
            pendsym_dd_mul(th[1], tl[1], 2.0*x0, 0.0, &ph, &pl);
            pendsym_dd_mul(ph, pl, h3, h3l, &ph, &pl);
            pendsym_dd_add(nh, nl, ph, pl, &nh, &nl);
            pendsym_dd_mul(th[0], tl[0], h4, h4l, &ph, &pl);
            pendsym_dd_add(nh, nl, ph, pl, &nh, &nl);
            pendsym_dd_mul(x2, x2l, k, 0.0, &dh, &dl);
        }}
        pendsym_dd_div(-nh, -nl, dh, dl, &nh, &nl);
        pendsym_dd_add(sh, sl, nh, nl, &sh, &sl);
        slope += (m + 2.0)*nh;
        small = fabs(nh) <= 1e-20*fabs(sh) ? small + 1 : 0;
        th[0] = th[1]; th[1] = th[2]; th[2] = th[3]; th[3] = nh;
        tl[0] = tl[1]; tl[1] = tl[2]; tl[2] = tl[3]; tl[3] = nl;
    }}
    pendsym_dd_add(sh, sl, lh*(slope/h), 0.0, &sh, &sl);        /* the low part of h, to first order */
    pendsym_dd_div(h, 0.0, x0, 0.0, &fh, &fl);                  /* √(1 + h/x0) = √(x1/x0) */
    pendsym_dd_add(1.0, 0.0, fh, fl, &fh, &fl);
    {{
        const double r = sqrt(fh);
        pendsym_dd_mul(r, 0.0, r, 0.0, &ph, &pl);
        pendsym_dd_add(fh, fl, -ph, -pl, &ph, &pl);
        pendsym_dd_add(r, 0.0, ph/(2.0*r), 0.0, &fh, &fl);
    }}
    pendsym_dd_mul(sh, sl, fh, fl, &sh, &sl);
    return sh;
}}

/* Y_a(x0)J_b(x1) − J_a(x0)Y_b(x1) times π√(x0 x1)/2, x0 = x0 + l0 (double-double), x1 = x0 + h. */
static double pendsym_bessel_cross(double a, double b, double x0, double l0, double h, double lh)
{{
    const int ia = (int)a, ib = (int)b;
    if (x0 >= {HANKEL_FROM!r}) {{
        const double s0 = sin(h), c0 = cos(h), s = s0 + lh*c0, c = c0 - lh*s0;   /* at h + lh, to first order */
        double qa, qb, pa, pb, sd, cd;
        pa = pendsym_hankel_pq(ia, x0, &qa);              /* P − 1: the sum below is sin or cos Δ plus small terms */
        pb = pendsym_hankel_pq(ib, x0 + h, &qb);
        if (ia == ib) {{ sd = -s; cd = c; }} else if (ia == 1) {{ sd = -c; cd = -s; }} else {{ sd = c; cd = s; }}
        return sd + ((pa + pb + pa*pb + qa*qb)*sd + ((qa - qb) + (qa*pb - pa*qb))*cd);
    }}
    if (h <= {TAYLOR_RATIO!r}*x0) {{
        return pendsym_bessel_taylor(ia, ib, x0, h, lh);
    }}
    {{
        double x1 = x0 + h, bb = x1 - x0, l1 = ((x0 - (x1 - bb)) + (h - bb)) + (l0 + lh);
        double j0a = j0(x0), j1a = j1(x0), y0a = y0(x0), y1a = y1(x0);
        double j0b = j0(x1), j1b = j1(x1), y0b = y0(x1), y1b = y1(x1);
        double ja, ya, jb, yb;
        if (ia == 0) {{ ja = j0a - l0*j1a; ya = y0a - l0*y1a; }}
        else {{ ja = j1a + l0*(j0a - j1a/x0); ya = y1a + l0*(y0a - y1a/x0); }}
        if (ib == 0) {{ jb = j0b - l1*j1b; yb = y0b - l1*y1b; }}
        else {{ jb = j1b + l1*(j0b - j1b/x1); yb = y1b + l1*(y0b - y1b/x1); }}
        return (ya*jb - ja*yb)*(3.14159265358979323846264338327950288*sqrt(x0*x1)/2.0);
    }}
}}"""
    return {"dd": DD_C, "quotient_low": quotient, "root_quotient": ROOT_C, "bessel_cross": cross}


def _py_definitions() -> dict[str, str]:
    (p0, q0), (p1, q1) = _hankel_coefficients(0), _hankel_coefficients(1)
    quotient = '''def _pendsym_quotient_low(a, b, hi):
    """(a − b·hi)/b for hi = a/b rounded: the low part of the quotient (the residual exact by Dekker's product)."""
    p = b * hi
    bh, bl = _pendsym_split(b)
    hh, hl = _pendsym_split(hi)
    e = ((bh * hh - p) + bh * hl + bl * hh) + bl * hl
    return ((a - p) - e) / b'''
    cross = f'''def _pendsym_hankel_pq(n, x):
    """Hankel's (P_n(x) − 1, Q_n(x)) (A–S 9.2.9–9.2.10, {HANKEL_TERMS} terms, x >= {HANKEL_FROM:g})."""
    t = 1.0 / (x * x)
    if n == 0:
        return ({_horner(p0[1:], "t")}) * t, ({_horner(q0, "t")}) / x
    return ({_horner(p1[1:], "t")}) * t, ({_horner(q1, "t")}) / x


def _pendsym_bessel_taylor(a, b, x0, h, lh):
    """c(x0 + h)/W(x0) times √(x1/x0) for c = Y_a(x0)J_b(x) − J_a(x0)Y_b(x) (W = 2/(πx)): the Taylor series of
    Bessel's equation of order b about x0, in double-double, rounded once."""
    t = [(0.0, 0.0), (0.0, 0.0), (0.0 if a == b else (-1.0 if a == 1 else 1.0), 0.0),
         (-h, 0.0) if a == b else ((0.0, 0.0) if a == 1 else _pendsym_dd_div(-h, 0.0, x0, 0.0))]
    h2 = _pendsym_dd_mul(h, 0.0, h, 0.0)
    h3 = _pendsym_dd_mul(*h2, h, 0.0)
    h4 = _pendsym_dd_mul(*h3, h, 0.0)
    x2 = _pendsym_dd_mul(x0, 0.0, x0, 0.0)
    s = _pendsym_dd_add(*t[2], *t[3])
    slope = t[3][0]                                   # Σ m t_m = h c'(x0 + h)/W
    small = 0
    m = 0
    while m < 400 and small < 2:
        k = (m + 2.0) * (m + 1.0)
        if b == 0:
            n = _pendsym_dd_mul(*_pendsym_dd_mul(*t[3], (m + 1.0) * (m + 1.0), 0.0), h, 0.0)
            n = _pendsym_dd_add(*n, *_pendsym_dd_mul(*_pendsym_dd_mul(*t[2], x0, 0.0), *h2))
            n = _pendsym_dd_add(*n, *_pendsym_dd_mul(*t[1], *h3))
            d = _pendsym_dd_mul(x0, 0.0, k, 0.0)
        else:
            n = _pendsym_dd_mul(*t[3], *_pendsym_dd_mul(*_pendsym_dd_mul(x0, 0.0, (m + 1.0) * (2.0 * m + 1.0), 0.0), h, 0.0))
            p = _pendsym_dd_mul(*_pendsym_dd_add(*x2, m * float(m) - 1.0, 0.0), *h2)
            n = _pendsym_dd_add(*n, *_pendsym_dd_mul(*t[2], *p))
            n = _pendsym_dd_add(*n, *_pendsym_dd_mul(*_pendsym_dd_mul(*t[1], 2.0 * x0, 0.0), *h3))
            n = _pendsym_dd_add(*n, *_pendsym_dd_mul(*t[0], *h4))
            d = _pendsym_dd_mul(*x2, k, 0.0)
        nxt = _pendsym_dd_div(-n[0], -n[1], *d)
        s = _pendsym_dd_add(*s, *nxt)
        slope += (m + 2.0) * nxt[0]
        small = small + 1 if abs(nxt[0]) <= 1e-20 * abs(s[0]) else 0
        t = [t[1], t[2], t[3], nxt]
        m += 1
    s = _pendsym_dd_add(*s, lh * (slope / h), 0.0)    # the low part of h, to first order
    f = _pendsym_dd_add(1.0, 0.0, *_pendsym_dd_div(h, 0.0, x0, 0.0))
    r = math.sqrt(f[0])
    e = _pendsym_dd_add(*f, *(-v for v in _pendsym_two_prod(r, r)))
    f = _pendsym_dd_add(r, 0.0, e[0] / (2.0 * r), 0.0)
    return _pendsym_dd_mul(*s, *f)[0]


def _pendsym_bessel_cross(a, b, x0, l0, h, lh):
    """Y_a(x0)J_b(x1) − J_a(x0)Y_b(x1) times π√(x0 x1)/2, x0 = x0 + l0, x1 = x0 + h + lh (double-doubles)."""
    ia, ib = int(a), int(b)
    if x0 >= {HANKEL_FROM!r}:
        pa, qa = _pendsym_hankel_pq(ia, x0)
        pb, qb = _pendsym_hankel_pq(ib, x0 + h)
        s0, c0 = math.sin(h), math.cos(h)
        s, c = s0 + lh * c0, c0 - lh * s0                       # at h + lh, to first order
        sd, cd = (-s, c) if ia == ib else ((-c, -s) if ia == 1 else (c, s))
        return sd + ((pa + pb + pa * pb + qa * qb) * sd + ((qa - qb) + (qa * pb - pa * qb)) * cd)
    if h <= {TAYLOR_RATIO!r} * x0:
        return _pendsym_bessel_taylor(ia, ib, x0, h, lh)
    from scipy.special import jv, yv
    x1 = x0 + h
    bb = x1 - x0
    l1 = ((x0 - (x1 - bb)) + (h - bb)) + (l0 + lh)
    j0a, j1a, y0a, y1a = float(jv(0, x0)), float(jv(1, x0)), float(yv(0, x0)), float(yv(1, x0))
    j0b, j1b, y0b, y1b = float(jv(0, x1)), float(jv(1, x1)), float(yv(0, x1)), float(yv(1, x1))
    if ia == 0:
        ja, ya = j0a - l0 * j1a, y0a - l0 * y1a
    else:
        ja, ya = j1a + l0 * (j0a - j1a / x0), y1a + l0 * (y0a - y1a / x0)
    if ib == 0:
        jb, yb = j0b - l1 * j1b, y0b - l1 * y1b
    else:
        jb, yb = j1b + l1 * (j0b - j1b / x1), y1b + l1 * (y0b - y1b / x1)
    return (ya * jb - ja * yb) * (math.pi * math.sqrt(x0 * x1) / 2.0)'''
    return {"dd": DD_PY, "quotient_low": quotient, "root_quotient": ROOT_PY, "bessel_cross": cross}

