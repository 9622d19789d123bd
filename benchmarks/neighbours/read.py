"""Reading rbdsolve's answers (its JSON output, docs/json.md): every exact answer is a
string sympy reads back, coordinates as functions of t. An answer is evaluated at the
oracle's parameter values and state (q, q̇, q̈) in 30 digits; a condition is decided
there, or said to be too near its boundary to decide."""

from __future__ import annotations

from functools import lru_cache

import mpmath
import sympy as sp

_T = sp.Symbol("t")


class NotANumber(ValueError):
    """An answer that divides by zero (or overflows) at the values asked."""


class Reader:
    """Answers of one file: its parameter names (``symbols``) and coordinates."""

    def __init__(self, symbols: list[str], coords: list[str], extra: tuple[str, ...] = ()):
        self.names = {n: sp.Symbol(n) for n in list(symbols) + list(extra)}
        self.coords = list(coords)
        self.funcs = {q: sp.Function(q) for q in coords}
        self.q = {q: sp.Symbol(f"_q_{q}") for q in coords}
        self.qd = {q: sp.Symbol(f"_qd_{q}") for q in coords}
        self.qdd = {q: sp.Symbol(f"_qdd_{q}") for q in coords}
        self.locals = {**self.names, **self.funcs, "t": _T, "lamda": sp.Symbol("lamda")}

    def parse(self, text: str) -> sp.Expr:
        return _parse(text, tuple(sorted(self.names)), tuple(self.coords))

    def value(self, answer, params: dict, q=None, qd=None, qdd=None, extra: dict | None = None, t=None):
        """The number an answer (a string, or a number on the numeric route) is at these values."""
        if answer is None:
            return None
        if isinstance(answer, (int, float)):
            return mpmath.mpf(answer)
        e = self.parse(answer)
        subs = {self.names[k]: sp.Float(mpmath.nstr(v, 35), 35) for k, v in params.items() if k in self.names}
        if extra:
            subs.update({self.names.get(k, sp.Symbol(k)): sp.Float(mpmath.nstr(v, 35), 35) for k, v in extra.items()})
        for i, name in enumerate(self.coords):
            for table, vals in ((self.qdd, qdd), (self.qd, qd), (self.q, q)):
                if vals is not None:
                    subs[table[name]] = sp.Float(mpmath.nstr(vals[i], 35), 35)
        if t is not None:
            subs[_T] = sp.Float(mpmath.nstr(t, 35), 35)
        v = e.xreplace(subs).evalf(30)
        if v.free_symbols:
            raise ValueError(f"answer {answer!r} still holds {sorted(map(str, v.free_symbols))}")
        if v.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
            raise NotANumber(f"answer {answer!r} is not a finite number at these values")
        c = complex(v)
        if abs(c.imag) > 1e-12 * max(1.0, abs(c.real)):
            return mpmath.mpc(c.real, c.imag)
        return mpmath.mpf(sp.re(v)) if v.is_real is not False else mpmath.mpf(c.real)

    def truth(self, condition, params: dict, margin: float = 1e-7, extra: dict | None = None):
        """True/False where a condition (a string sympy reads as a relational, or And/Or
        of them, 'True', 'False', or a JSON boolean) holds at the values; None where a
        side is within ``margin`` of the other (too near the boundary to say)."""
        if isinstance(condition, bool) or condition is None:
            return condition
        return self._truth(self.parse(condition), params, margin, extra)

    def _truth(self, e, params, margin, extra):
        if e is sp.true or e == True:  # noqa: E712 - sympy's true
            return True
        if e is sp.false or e == False:  # noqa: E712
            return False
        if isinstance(e, sp.And):
            parts = [self._truth(a, params, margin, extra) for a in e.args]
            return False if False in parts else (None if None in parts else True)
        if isinstance(e, sp.Or):
            parts = [self._truth(a, params, margin, extra) for a in e.args]
            return True if True in parts else (None if None in parts else False)
        if isinstance(e, sp.Not):
            v = self._truth(e.args[0], params, margin, extra)
            return None if v is None else not v
        if isinstance(e, sp.Rel):
            a = self.value(str(e.lhs), params, extra=extra)
            b = self.value(str(e.rhs), params, extra=extra)
            if isinstance(a, mpmath.mpc) or isinstance(b, mpmath.mpc):
                return False if not isinstance(e, sp.Ne) else True
            if abs(a - b) <= margin * max(1, abs(a), abs(b)):
                return None
            op = type(e)
            return {sp.StrictLessThan: a < b, sp.LessThan: a <= b, sp.StrictGreaterThan: a > b,
                    sp.GreaterThan: a >= b, sp.Equality: False, sp.Unequality: True}[op]
        raise ValueError(f"not a condition: {e}")


@lru_cache(maxsize=4096)
def _parse(text: str, names: tuple[str, ...], coords: tuple[str, ...]) -> sp.Expr:
    reader_names = {n: sp.Symbol(n) for n in names}
    funcs = {q: sp.Function(q) for q in coords}
    e = sp.sympify(text, locals={**reader_names, **funcs, "t": _T, "lamda": sp.Symbol("lamda")})
    if isinstance(e, bool):
        return sp.true if e else sp.false
    if not coords or not hasattr(e, "subs"):
        return e
    rep = {}
    for q in coords:
        f = funcs[q](_T)
        rep[sp.Derivative(f, (_T, 2))] = sp.Symbol(f"_qdd_{q}")
        rep[sp.Derivative(f, _T)] = sp.Symbol(f"_qd_{q}")
    e = e.subs(rep)
    return e.subs({funcs[q](_T): sp.Symbol(f"_q_{q}") for q in coords})
