"""The text of the helpers that supplied kernel forms call (:mod:`.supplied`), printed once per file: double-double
arithmetic, the low part of a quotient, u/(1 + √(1 + t)) as a double-double, and the cross products of Bessel
functions of orders 0 and 1 (Hankel's expansion for large arguments, else the Taylor series of Bessel's equation in
the gap, in steps of at most half the centre), in C and in Python."""
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

/* One Taylor step of c(x) = Y_a(x0)J_b(x) − J_a(x0)Y_b(x) (a solution of Bessel's equation of order b) over the
 * gap h + lh from the centre xc + xl (double-double), c(xc)/W = f, h·c'(xc)/W = g (double-doubles, W = 2/(πx0)):
 * the series by the recurrence of its coefficients about xc (terms t_m = f_m h^m; h <= xc/2, so that they fall
 * as 2^-m at least) until two terms fall below tol (relative), in double-double; c(xc + h + lh)/W to *sh, *sl and
 * c'(xc + h + lh)/W to *dh, *dl (the low part lh to first order). */
static void pendsym_bessel_step(int b, double xc, double xl, double fh, double fl, double gh, double gl, double h,
                                double lh, double tol, double *rh, double *rl, double *dh, double *dl)
{{
    double th[4] = {{0.0, 0.0, 0.0, 0.0}}, tl[4] = {{0.0, 0.0, 0.0, 0.0}};   /* t_(m-2), t_(m-1), t_m, t_(m+1) */
    double h2, h2l, h3, h3l, h4, h4l, x2, x2l, sh, sl, nh, nl, ph, pl, qh, ql, mh, ml, vh, vl;
    int m, small = 0;
    th[2] = fh; tl[2] = fl; th[3] = gh; tl[3] = gl;
    pendsym_dd_mul(h, 0.0, h, 0.0, &h2, &h2l);
    pendsym_dd_mul(h2, h2l, h, 0.0, &h3, &h3l);
    pendsym_dd_mul(h3, h3l, h, 0.0, &h4, &h4l);
    pendsym_dd_mul(xc, xl, xc, xl, &x2, &x2l);
    pendsym_dd_add(fh, fl, gh, gl, &sh, &sl);
    vh = gh; vl = gl;                                            /* Σ m t_m = h c'(xc + h)/W */
    for (m = 0; m < 600 && small < 2; m++) {{
        const double k = (m + 2.0)*(m + 1.0);
        if (b == 0) {{
            pendsym_dd_mul(th[3], tl[3], (m + 1.0)*(m + 1.0), 0.0, &nh, &nl);
            pendsym_dd_mul(nh, nl, h, 0.0, &nh, &nl);
            pendsym_dd_mul(th[2], tl[2], xc, xl, &ph, &pl);
            pendsym_dd_mul(ph, pl, h2, h2l, &ph, &pl);
            pendsym_dd_add(nh, nl, ph, pl, &nh, &nl);
            pendsym_dd_mul(th[1], tl[1], h3, h3l, &ph, &pl);
            pendsym_dd_add(nh, nl, ph, pl, &nh, &nl);
            pendsym_dd_mul(xc, xl, k, 0.0, &qh, &ql);
        }} else {{
            pendsym_dd_mul(xc, xl, (m + 1.0)*(2.0*m + 1.0), 0.0, &ph, &pl);
            pendsym_dd_mul(ph, pl, h, 0.0, &ph, &pl);
            pendsym_dd_mul(th[3], tl[3], ph, pl, &nh, &nl);
            pendsym_dd_add(x2, x2l, m*(double)m - 1.0, 0.0, &ph, &pl);
            pendsym_dd_mul(ph, pl, h2, h2l, &ph, &pl);
            pendsym_dd_mul(th[2], tl[2], ph, pl, &ph, &pl);
            pendsym_dd_add(nh, nl, ph, pl, &nh, &nl);
            pendsym_dd_mul(th[1], tl[1], 2.0*xc, 2.0*xl, &ph, &pl);
            pendsym_dd_mul(ph, pl, h3, h3l, &ph, &pl);
            pendsym_dd_add(nh, nl, ph, pl, &nh, &nl);
            pendsym_dd_mul(th[0], tl[0], h4, h4l, &ph, &pl);
            pendsym_dd_add(nh, nl, ph, pl, &nh, &nl);
            pendsym_dd_mul(x2, x2l, k, 0.0, &qh, &ql);
        }}
        pendsym_dd_div(-nh, -nl, qh, ql, &nh, &nl);
        pendsym_dd_add(sh, sl, nh, nl, &sh, &sl);
        pendsym_dd_mul(nh, nl, m + 2.0, 0.0, &mh, &ml);
        pendsym_dd_add(vh, vl, mh, ml, &vh, &vl);
        small = fabs(nh) <= tol*(fabs(sh) + fabs(vh)) ? small + 1 : 0;
        th[0] = th[1]; th[1] = th[2]; th[2] = th[3]; th[3] = nh;
        tl[0] = tl[1]; tl[1] = tl[2]; tl[2] = tl[3]; tl[3] = nl;
    }}
    pendsym_dd_div(vh, vl, h, 0.0, dh, dl);
    pendsym_dd_add(sh, sl, lh*(*dh), 0.0, rh, rl);               /* the low part of h, to first order */
}}

/* c(x1)/W(x0) times √(x1/x0) for x1 = x0 + l0 + h + lh: from c(x0)/W = 0 or ∓1 and c'(x0)/W (the Wronskian, exact)
 * by Taylor steps of at most half the centre (a singular point of the equation at x = 0: radius xc), the last
 * landing on x1 through the remaining gap (a double-double, never x1 rounded); the terms' tolerance 1e-20 (x0/x1)²
 * (an error of the dominant solution grows at most as (x/x0)² relative to the recessive one, order 1). */
static double pendsym_bessel_taylor(int a, int b, double x0, double l0, double h, double lh)
{{
    double fh = a == b ? 0.0 : (a == 1 ? -1.0 : 1.0), fl = 0.0, dh = 0.0, dl = 0.0, gh, gl;
    double xc = x0, xl = l0, rh = h, rl = lh, sh, sl, ph, pl;
    const double ratio = x0/(x0 + h), tol = 1e-20*ratio*ratio;
    if (a == b) dh = -1.0;
    else if (a == 0) pendsym_dd_div(-1.0, 0.0, x0, l0, &dh, &dl);
    for (;;) {{
        const int last = rh <= {TAYLOR_RATIO!r}*xc;
        const double st = last ? rh : {TAYLOR_RATIO!r}*xc, stl = last ? rl : 0.0;
        pendsym_dd_mul(dh, dl, st, 0.0, &gh, &gl);
        pendsym_bessel_step(b, xc, xl, fh, fl, gh, gl, st, stl, tol, &fh, &fl, &dh, &dl);
        if (last) break;
        pendsym_dd_add(xc, xl, st, 0.0, &xc, &xl);
        pendsym_dd_add(rh, rl, -st, 0.0, &rh, &rl);
    }}
    pendsym_dd_div(h, lh, x0, l0, &sh, &sl);                    /* √(1 + h/x0) = √(x1/x0) */
    pendsym_dd_add(1.0, 0.0, sh, sl, &sh, &sl);
    {{
        const double r = sqrt(sh);
        pendsym_dd_mul(r, 0.0, r, 0.0, &ph, &pl);
        pendsym_dd_add(sh, sl, -ph, -pl, &ph, &pl);
        pendsym_dd_add(r, 0.0, ph/(2.0*r), 0.0, &sh, &sl);
    }}
    pendsym_dd_mul(fh, fl, sh, sl, &fh, &fl);
    return fh;
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
    return pendsym_bessel_taylor(ia, ib, x0, l0, h, lh);
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


def _pendsym_bessel_step(b, xc, xl, f, g, h, lh, tol):
    """One Taylor step of c = Y_a(x0)J_b(x) − J_a(x0)Y_b(x) (Bessel's equation of order b) over the gap h + lh from
    the centre xc + xl, c(xc)/W = f, h·c'(xc)/W = g (double-doubles, W = 2/(πx0)), by the recurrence of the
    coefficients about xc until two terms fall below tol (relative): (c, c') at xc + h + lh over W, double-doubles."""
    t = [(0.0, 0.0), (0.0, 0.0), f, g]
    h2 = _pendsym_dd_mul(h, 0.0, h, 0.0)
    h3 = _pendsym_dd_mul(*h2, h, 0.0)
    h4 = _pendsym_dd_mul(*h3, h, 0.0)
    x2 = _pendsym_dd_mul(xc, xl, xc, xl)
    s = _pendsym_dd_add(*f, *g)
    slope = g                                         # Σ m t_m = h c'(xc + h)/W
    small = 0
    m = 0
    while m < 600 and small < 2:
        k = (m + 2.0) * (m + 1.0)
        if b == 0:
            n = _pendsym_dd_mul(*_pendsym_dd_mul(*t[3], (m + 1.0) * (m + 1.0), 0.0), h, 0.0)
            n = _pendsym_dd_add(*n, *_pendsym_dd_mul(*_pendsym_dd_mul(*t[2], xc, xl), *h2))
            n = _pendsym_dd_add(*n, *_pendsym_dd_mul(*t[1], *h3))
            d = _pendsym_dd_mul(xc, xl, k, 0.0)
        else:
            n = _pendsym_dd_mul(*t[3], *_pendsym_dd_mul(*_pendsym_dd_mul(xc, xl, (m + 1.0) * (2.0 * m + 1.0), 0.0), h, 0.0))
            p = _pendsym_dd_mul(*_pendsym_dd_add(*x2, m * float(m) - 1.0, 0.0), *h2)
            n = _pendsym_dd_add(*n, *_pendsym_dd_mul(*t[2], *p))
            n = _pendsym_dd_add(*n, *_pendsym_dd_mul(*_pendsym_dd_mul(*t[1], 2.0 * xc, 2.0 * xl), *h3))
            n = _pendsym_dd_add(*n, *_pendsym_dd_mul(*t[0], *h4))
            d = _pendsym_dd_mul(*x2, k, 0.0)
        nxt = _pendsym_dd_div(-n[0], -n[1], *d)
        s = _pendsym_dd_add(*s, *nxt)
        slope = _pendsym_dd_add(*slope, *_pendsym_dd_mul(*nxt, m + 2.0, 0.0))
        small = small + 1 if abs(nxt[0]) <= tol * (abs(s[0]) + abs(slope[0])) else 0
        t = [t[1], t[2], t[3], nxt]
        m += 1
    d = _pendsym_dd_div(*slope, h, 0.0)
    return _pendsym_dd_add(*s, lh * d[0], 0.0), d     # the low part of h, to first order


def _pendsym_bessel_taylor(a, b, x0, l0, h, lh):
    """c(x1)/W(x0) times √(x1/x0), x1 = x0 + l0 + h + lh, from c(x0)/W = 0 or ∓1 and c'(x0)/W (the Wronskian) by
    Taylor steps of at most half the centre, the last landing on x1 through the remaining gap (double-double); the
    terms' tolerance 1e-20 (x0/x1)² (an error grows at most as (x/x0)² relative to the solution)."""
    f = (0.0 if a == b else (-1.0 if a == 1 else 1.0), 0.0)
    d = (-1.0, 0.0) if a == b else ((0.0, 0.0) if a == 1 else _pendsym_dd_div(-1.0, 0.0, x0, l0))
    ratio = x0 / (x0 + h)
    tol = 1e-20 * ratio * ratio
    xc, rest = (x0, l0), (h, lh)
    while True:
        last = rest[0] <= {TAYLOR_RATIO!r} * xc[0]
        st, stl = rest if last else ({TAYLOR_RATIO!r} * xc[0], 0.0)
        f, d = _pendsym_bessel_step(b, *xc, f, _pendsym_dd_mul(*d, st, 0.0), st, stl, tol)
        if last:
            break
        xc = _pendsym_dd_add(*xc, st, 0.0)
        rest = _pendsym_dd_add(*rest, -st, 0.0)
    r2 = _pendsym_dd_add(1.0, 0.0, *_pendsym_dd_div(h, lh, x0, l0))
    r = math.sqrt(r2[0])
    e = _pendsym_dd_add(*r2, *(-v for v in _pendsym_two_prod(r, r)))
    return _pendsym_dd_mul(*f, *_pendsym_dd_add(r, 0.0, e[0] / (2.0 * r), 0.0))[0]


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
    return _pendsym_bessel_taylor(ia, ib, x0, l0, h, lh)'''
    return {"dd": DD_PY, "quotient_low": quotient, "root_quotient": ROOT_PY, "bessel_cross": cross}

