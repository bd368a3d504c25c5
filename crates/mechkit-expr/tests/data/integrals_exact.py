"""Exact definite values for integrals.tsv (reference, independent of mechkit): reads the
integrand, limits and parameters (tab-separated) from stdin, writes them back with the exact
value by SymPy and its decimal value to 20 digits. Run: python3 integrals_exact.py < list."""
import signal
import sys

import mpmath
import sympy as sp

x = sp.Symbol("x", real=True)
mpmath.mp.dps = 30
print("# integrand\tfrom\tto\tparameters\tvalue\texact (SymPy)")
for line in sys.stdin:
    line = line.rstrip("\n")
    if not line or line.startswith("#"):
        continue
    f, a, b, params = (line.split("\t") + [""])[:4]
    subs = {}
    for p in filter(None, params.split(",")):
        k, v = p.split("=")
        subs[sp.Symbol(k)] = sp.Rational(v)
    expr = sp.sympify(f.replace("^", "**").replace("ln(", "log("), locals={"x": x})
    expr = expr.subs(subs)
    lo, hi = sp.sympify(a), sp.sympify(b)
    signal.alarm(60)
    try:
        exact = sp.simplify(sp.integrate(expr, (x, lo, hi)))
        if exact.has(sp.Integral) and lo >= 0:
            xp = sp.Symbol("xp", positive=True)
            exact = sp.simplify(sp.integrate(expr.subs(x, xp), (xp, lo, hi)))
        if exact.has(sp.Integral):
            exact = sp.simplify(sp.integrate(expr, (x, lo, hi), manual=True))
        if abs(sp.im(sp.N(exact, 30))) < 1e-25:
            exact = sp.simplify(sp.re(sp.expand_complex(exact)))
        if exact.has(sp.Integral):
            raise ValueError("unevaluated")
        value = sp.N(exact, 20)
        check = mpmath.quad(sp.lambdify(x, expr, "mpmath"), [mpmath.mpf(str(sp.N(lo, 30))), mpmath.mpf(str(sp.N(hi, 30)))])
        assert abs(float(value) - float(check)) <= 1e-12 * max(1, abs(float(value))), (f, value, check)
        shown = str(exact)
    except Exception as e:  # noqa: BLE001
        print(f"no exact value for {f}: {e}", file=sys.stderr)
        continue
    finally:
        signal.alarm(0)
    print(f"{f}\t{a}\t{b}\t{params}\t{value}\t{shown}")
