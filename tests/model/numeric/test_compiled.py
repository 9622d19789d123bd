"""numpy_function: lambdify's numpy function without ``from numpy import *``."""

from __future__ import annotations

import math

import numpy as np
import sympy as sp

from rbdsolve.model.numeric.compiled import numpy_function

from conftest import fresh_process

x, y = sp.symbols("x y", real=True)


def test_the_values_are_those_of_the_formulas() -> None:
    """A potential's gradient and a Hessian's rows, as the numeric route compiles them,
    checked against the formulas evaluated with Python's math module."""
    f = numpy_function([[x, y]], [sp.sin(x) * sp.sqrt(y) + sp.Abs(x - 1), sp.atan2(x, y) + sp.sign(y),
                                  [sp.cos(x) ** 2, sp.exp(-y) * sp.pi]])
    a, b = 0.3, 2.0
    first, second, (c, d) = f([a, b])
    assert first == math.sin(a) * math.sqrt(b) + abs(a - 1)
    assert second == math.atan2(a, b) + 1.0
    assert c == math.cos(a) ** 2
    assert math.isclose(d, math.exp(-b) * math.pi, rel_tol=1e-15)


def test_arrays_go_through_elementwise() -> None:
    """The variants' use: one call over arrays of parameter values, common
    subexpressions shared (cse)."""
    f = numpy_function([x, y], [sp.sin(x) * y, sp.sin(x) * y ** 2], cse=True)
    xs, ys = np.array([0.0, 0.5, 1.0]), np.array([1.0, 2.0, 3.0])
    first, second = f(xs, ys)
    assert np.array_equal(first, np.sin(xs) * ys)
    assert np.array_equal(second, np.sin(xs) * ys ** 2)


def test_numpy_s_submodules_are_not_imported() -> None:
    """lambdify's "numpy" namespace is ``from numpy import *``, which in numpy 2 imports
    numpy.testing, numpy.f2py, numpy.random and numpy.ma: 0.07–0.10 s of a process."""
    code = ("import sys, sympy as sp\n"
            "from rbdsolve.model.numeric.compiled import numpy_function\n"
            "x = sp.Symbol('x')\n"
            "print(numpy_function([x], sp.sin(x) + sp.sqrt(x))(0.25))\n"
            "print(sorted(m for m in ('numpy.testing', 'numpy.f2py', 'numpy.random', 'numpy.ma') if m in sys.modules))")
    value, loaded = fresh_process(code)
    assert float(value) == math.sin(0.25) + 0.5
    assert loaded == "[]"
