"""Expressions compiled to numpy functions, numpy's names written out in full.

``sympy.lambdify(args, expr, "numpy")`` prints ``sin(x)`` and gives the function a
namespace filled by ``from numpy import *``. numpy 2 lists its submodules (testing,
f2py, random, ma, polynomial, fft) in ``__all__``, so that star import loads them
all: 0.07–0.10 s of a process that takes about a second, for functions that need
sin, cos and sqrt. Printed fully qualified (``numpy.sin(x)``, sympy's NumPyPrinter
with ``fully_qualified_modules``) the same function needs only the name ``numpy``:
the same numpy functions are called on the same numbers, so the values are the same
to the bit.
"""

from __future__ import annotations

import sympy as sp

_SETTINGS = {"fully_qualified_modules": True, "inline": True, "allow_unknown_functions": True}


def numpy_function(args, expr, cse: bool = False):
    """``lambdify(args, expr, "numpy")``'s function, its numpy names qualified
    (``numpy.sin``): nothing imported from numpy but numpy itself. (numpy is imported
    here, on the first call: a file on the exact route imports it not at all.)"""
    import numpy as np
    from sympy.printing.numpy import NumPyPrinter

    return sp.lambdify(args, expr, modules=[{"numpy": np}], printer=NumPyPrinter(_SETTINGS), cse=cse)
