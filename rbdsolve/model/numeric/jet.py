"""Forward-mode automatic differentiation to second order: the jet of a scalar.

A :class:`Jet` of f(q) at a configuration q₀ carries f(q₀), its gradient ∇f and (at
second order) its Hessian ∇²f with respect to the generalized coordinates. Arithmetic
on jets follows the rules of calculus exactly (no step sizes), so derivatives are as
accurate as the values:

    (a + b)'' = a'' + b''
    (a b)''   = a b'' + b a'' + ∇a ∇bᵀ + ∇b ∇aᵀ
    f(u)''    = f'(u) ∇²u + f''(u) ∇u ∇uᵀ        (the chain rule, second order)

(e.g. Griewank & Walther, *Evaluating Derivatives*, 2nd ed., ch. 13, on univariate
Taylor propagation; here the full gradient and Hessian are carried instead.)

A jet depends on few coordinates as a rule (a link of a chain on the links above it),
so it stores its derivatives only over ``index``, the sorted coordinates it depends
on: adding a jet of one coordinate to a jet of forty then costs one entry, not 40².

An :class:`Arithmetic` says what the numbers are: float64 (FLOAT) or 50-digit mpmath
numbers in numpy object arrays (MP50), so one evaluator gives both the fast answer and
its high-precision reference.
"""

from __future__ import annotations

import contextlib
import math
from dataclasses import dataclass
from fractions import Fraction
from typing import Callable

import mpmath
import numpy as np


# --- numbers --------------------------------------------------------------------------


@dataclass(frozen=True)
class Arithmetic:
    """The numbers a scene is evaluated in: float64 (``digits`` None) or mpmath with
    ``digits`` significant digits, set locally (``mpmath.workdps``) while evaluating."""

    name: str
    digits: int | None

    @property
    def lib(self):
        """The scalar functions: ``math`` for float64, ``mpmath`` for mp numbers."""
        return math if self.digits is None else mpmath

    def precision(self) -> contextlib.AbstractContextManager:
        """The working precision, for the caller's code only while inside the block."""
        return contextlib.nullcontext() if self.digits is None else mpmath.workdps(self.digits)

    def number(self, x):
        """A Python float, Fraction, int or mpf as this arithmetic's scalar (call inside
        :meth:`precision`, so a Fraction is rounded once at the working precision)."""
        if self.digits is None:
            return float(x)
        if isinstance(x, Fraction):
            return mpmath.mpf(x.numerator) / x.denominator
        return mpmath.mpf(x)

    def zeros(self, shape) -> np.ndarray:
        return np.zeros(shape) if self.digits is None else np.zeros(shape, dtype=object)

    def array(self, items) -> np.ndarray:
        """An array of this arithmetic's scalars (exact zeros become scalars too)."""
        if self.digits is None:
            return np.asarray(items, dtype=float)
        return np.asarray(items, dtype=object) + mpmath.mpf(0)

    def is_real(self, x) -> bool:
        """False for what a real function returns outside its domain (a complex number)."""
        return isinstance(x, (float, int)) if self.digits is None else isinstance(x, (mpmath.mpf, int))

    def pi(self):
        return math.pi if self.digits is None else +mpmath.pi


FLOAT = Arithmetic("float64", None)
MP50 = Arithmetic("mp50", 50)


# --- the jet --------------------------------------------------------------------------


# Not frozen: jets are made by the million in a search, and a frozen __init__ sets each
# field through object.__setattr__ (a tenth of a Newton search's time).
@dataclass(eq=False, slots=True)
class Jet:
    """f(q₀), ∇f and ∇²f (None at first order) over the coordinates in ``index``. Never
    changed once made (each operation makes a new one)."""

    value: object
    index: np.ndarray  # sorted coordinate numbers f depends on
    grad: np.ndarray  # (k,)
    hess: np.ndarray | None  # (k, k)

    __array_ufunc__ = None  # numpy scalars and arrays defer to Jet's own operators

    @staticmethod
    def seed(value, i: int, order: int, arithmetic: Arithmetic) -> Jet:
        """The coordinate q_i itself: ∇q_i = e_i, ∇²q_i = 0."""
        one = arithmetic.array([1])
        hess = arithmetic.zeros((1, 1)) if order == 2 else None
        return Jet(value, np.array([i], dtype=np.intp), one, hess)

    def chain(self, f0, f1, f2) -> Jet:
        """f(self) from f, f′ and f″ at self.value: ∇f = f′ ∇u, ∇²f = f′ ∇²u + f″ ∇u ∇uᵀ."""
        hess = None if self.hess is None else f1 * self.hess + f2 * np.outer(self.grad, self.grad)
        return Jet(f0, self.index, f1 * self.grad, hess)

    def scaled(self, c) -> Jet:
        return Jet(c * self.value, self.index, c * self.grad, None if self.hess is None else c * self.hess)

    def shifted(self, c) -> Jet:
        return Jet(self.value + c, self.index, self.grad, self.hess)

    def __neg__(self) -> Jet:
        return self.scaled(-1)

    def __add__(self, other) -> Jet:
        if not isinstance(other, Jet):
            return self.shifted(other)
        return _sum(self, other)

    __radd__ = __add__

    def __sub__(self, other) -> Jet:
        return self + (-other)

    def __rsub__(self, other) -> Jet:
        return (-self) + other

    def __mul__(self, other) -> Jet:
        if not isinstance(other, Jet):
            return self.scaled(other)
        return _product(self, other)

    __rmul__ = __mul__

    def __truediv__(self, other) -> Jet:
        if not isinstance(other, Jet):
            return self.scaled(1 / other)
        return self * other.reciprocal()

    def __rtruediv__(self, other) -> Jet:
        return self.reciprocal().scaled(other)

    def reciprocal(self) -> Jet:
        """1/u: f′ = −1/u², f″ = 2/u³."""
        r = 1 / self.value
        return self.chain(r, -r * r, 2 * r * r * r)

    def on(self, index: np.ndarray, arithmetic_zeros: Callable) -> tuple[np.ndarray, np.ndarray | None]:
        """The gradient and Hessian spread over a larger ``index`` (zeros elsewhere)."""
        if len(index) == len(self.index):
            return self.grad, self.hess
        at = np.searchsorted(index, self.index)
        grad = arithmetic_zeros(len(index))
        grad[at] = self.grad
        if self.hess is None:
            return grad, None
        hess = arithmetic_zeros((len(index), len(index)))
        hess[np.ix_(at, at)] = self.hess
        return grad, hess


def _zeros_like(a: np.ndarray) -> Callable:
    return lambda shape: np.zeros(shape, dtype=a.dtype)


def _union(a: Jet, b: Jet) -> np.ndarray:
    """The sorted union of the two indices (a's own where they are equal). As Python
    lists: a few coordinates each, where numpy's union1d and array_equal cost more in
    their set-up than in their work (a tenth of a two-coordinate Newton search)."""
    if a.index is b.index:
        return a.index
    ia, ib = a.index.tolist(), b.index.tolist()
    if ia == ib:
        return a.index
    return np.array(sorted(set(ia).union(ib)), dtype=np.intp)


def _sum(a: Jet, b: Jet) -> Jet:
    """a + b: the larger jet spread over both indices, the smaller added into its block
    (only the smaller block costs arithmetic)."""
    if len(a.index) < len(b.index):
        a, b = b, a
    index = _union(a, b)
    if index is a.index and len(b.index) == len(index):  # one index: the arrays added whole
        return Jet(a.value + b.value, index, a.grad + b.grad, None if a.hess is None else a.hess + b.hess)
    grad, hess = a.on(index, _zeros_like(a.grad))
    if grad is a.grad:  # the same index: a's own arrays, which stay a's; else new ones already
        grad, hess = grad.copy(), None if hess is None else hess.copy()
    at = np.searchsorted(index, b.index)
    grad[at] += b.grad
    if hess is not None:
        hess[np.ix_(at, at)] += b.hess
    return Jet(a.value + b.value, index, grad, hess)


def _product(a: Jet, b: Jet) -> Jet:
    """a b: ∇(ab) = a ∇b + b ∇a, ∇²(ab) = a ∇²b + b ∇²a + ∇a ∇bᵀ + ∇b ∇aᵀ."""
    index = _union(a, b)
    zeros = _zeros_like(a.grad)
    ga, ha = a.on(index, zeros)
    gb, hb = b.on(index, zeros)
    grad = a.value * gb + b.value * ga
    hess = None
    if ha is not None:
        cross = np.outer(ga, gb)
        hess = a.value * hb + b.value * ha + cross + cross.T
    return Jet(a.value * b.value, index, grad, hess)


def full(jet, n: int, arithmetic: Arithmetic, hessian: bool = True) -> tuple[np.ndarray, np.ndarray | None]:
    """The gradient (n,) and Hessian (n, n) of a jet, or of a constant (zeros); the
    Hessian None where ``hessian`` is False."""
    grad = arithmetic.zeros(n)
    hess = arithmetic.zeros((n, n)) if hessian else None
    if isinstance(jet, Jet):
        grad[jet.index] = jet.grad
        if hess is not None and jet.hess is not None:
            hess[np.ix_(jet.index, jet.index)] = jet.hess
    return arithmetic.array(grad), None if hess is None else arithmetic.array(hess)


# --- scalar functions: f, f′, f″ at a point -------------------------------------------


def _sin(lib, x):
    s, c = lib.sin(x), lib.cos(x)
    return s, c, -s


def _cos(lib, x):
    s, c = lib.sin(x), lib.cos(x)
    return c, -s, -c


def _tan(lib, x):
    t = lib.tan(x)
    return t, 1 + t * t, 2 * t * (1 + t * t)


def _cot(lib, x):
    c = 1 / lib.tan(x)
    return c, -(1 + c * c), 2 * c * (1 + c * c)


def _sec(lib, x):
    s, t = 1 / lib.cos(x), lib.tan(x)
    return s, s * t, s * (t * t + s * s)


def _csc(lib, x):
    s, c = 1 / lib.sin(x), 1 / lib.tan(x)
    return s, -s * c, s * (c * c + s * s)


def _asin(lib, x):
    w = 1 - x * x
    return lib.asin(x), 1 / lib.sqrt(w), x / (w * lib.sqrt(w))


def _acos(lib, x):
    w = 1 - x * x
    return lib.acos(x), -1 / lib.sqrt(w), -x / (w * lib.sqrt(w))


def _atan(lib, x):
    w = 1 + x * x
    return lib.atan(x), 1 / w, -2 * x / (w * w)


def _sinh(lib, x):
    s, c = lib.sinh(x), lib.cosh(x)
    return s, c, s


def _cosh(lib, x):
    s, c = lib.sinh(x), lib.cosh(x)
    return c, s, c


def _tanh(lib, x):
    t = lib.tanh(x)
    return t, 1 - t * t, -2 * t * (1 - t * t)


def _exp(lib, x):
    e = lib.exp(x)
    return e, e, e


def _log(lib, x):
    if x <= 0:  # mpmath would answer with a complex logarithm
        raise ValueError(f"log of {x}, which is not positive")
    return lib.log(x), 1 / x, -1 / (x * x)


def _sqrt(lib, x):
    if x < 0:
        raise ValueError(f"sqrt of {x}, which is negative")
    s = lib.sqrt(x)
    return s, 1 / (2 * s), -1 / (4 * s * s * s)


def _abs(lib, x):
    # d|x|/dx = sign(x) away from 0, and the second derivative is 0 there
    return abs(x), (x > 0) - (x < 0), 0


UNARY: dict[str, Callable] = {
    "sin": _sin, "cos": _cos, "tan": _tan, "cot": _cot, "sec": _sec, "csc": _csc,
    "asin": _asin, "acos": _acos, "atan": _atan,
    "sinh": _sinh, "cosh": _cosh, "tanh": _tanh,
    "exp": _exp, "log": _log, "sqrt": _sqrt, "abs": _abs,
}  # fmt: skip


def power(u, p, arithmetic: Arithmetic):
    """u^p for a constant p (a Python int when the exponent is an integer):
    f′ = p u^(p−1), f″ = p (p−1) u^(p−2), each skipped where its coefficient vanishes,
    so u² at u = 0 has the derivatives of a square, not 0 · 0⁻¹."""
    x = u.value if isinstance(u, Jet) else u
    f0 = x**p
    if not arithmetic.is_real(f0):
        raise ValueError(f"{x} to the power {p} is not a real number")
    if not isinstance(u, Jet):
        return f0
    f1 = p * x ** (p - 1) if p != 0 else 0
    f2 = p * (p - 1) * x ** (p - 2) if p != 0 and p != 1 else 0
    return u.chain(f0, f1, f2)


def apply(name: str, u, arithmetic: Arithmetic):
    """f(u) for a function of expr.SCALAR_FUNCTIONS with one argument, u a jet or number."""
    x = u.value if isinstance(u, Jet) else u
    f0, f1, f2 = UNARY[name](arithmetic.lib, x)
    if not arithmetic.is_real(f0):
        raise ValueError(f"{name}({x}) is not a real number")
    return u.chain(f0, f1, f2) if isinstance(u, Jet) else f0


def atan2(y, x, arithmetic: Arithmetic):
    """atan2(y, x), the angle of the point (x, y): with ρ = x² + y²,
    ∂/∂y = x/ρ, ∂/∂x = −y/ρ, ∂²/∂y² = −2xy/ρ², ∂²/∂x² = 2xy/ρ², ∂²/∂x∂y = (y² − x²)/ρ²."""
    yv = y.value if isinstance(y, Jet) else y
    xv = x.value if isinstance(x, Jet) else x
    f0 = arithmetic.lib.atan2(yv, xv)
    if not isinstance(y, Jet) and not isinstance(x, Jet):
        return f0
    rho = xv * xv + yv * yv
    derivatives = (xv / rho, -yv / rho, -2 * xv * yv / rho**2, 2 * xv * yv / rho**2, (yv * yv - xv * xv) / rho**2)
    return compose2(f0, derivatives, y, x)


def compose2(f0, derivatives, a, b):
    """f(a, b) from f and its derivatives (f_a, f_b, f_aa, f_bb, f_ab) at the point:
    ∇f = f_a ∇a + f_b ∇b,
    ∇²f = f_a ∇²a + f_b ∇²b + f_aa ∇a∇aᵀ + f_bb ∇b∇bᵀ + f_ab (∇a∇bᵀ + ∇b∇aᵀ)."""
    fa, fb, faa, fbb, fab = derivatives
    a = a if isinstance(a, Jet) else None
    b = b if isinstance(b, Jet) else None
    if a is None:
        return b.chain(f0, fb, fbb)
    if b is None:
        return a.chain(f0, fa, faa)
    index = _union(a, b)
    zeros = _zeros_like(a.grad)
    ga, ha = a.on(index, zeros)
    gb, hb = b.on(index, zeros)
    hess = None
    if ha is not None:
        cross = np.outer(ga, gb)
        hess = fa * ha + fb * hb + faa * np.outer(ga, ga) + fbb * np.outer(gb, gb) + fab * (cross + cross.T)
    return Jet(f0, index, fa * ga + fb * gb, hess)
