"""Principal axes as an exam writes them: a surd's denominator made rational and the
parameters' denominators cleared, before the direction is made a unit vector."""

import sympy as sp

from rbdsolve.solvers.inertia.exact import _integral, _unit_axes


def test_a_surd_axis_clears_to_whole_numbers_and_one_surd():
    # J/(m a²) of a square plate with a rod at its far corner; (1, 1, t) with 2t² + 9t − 4 = 0, by hand
    J = sp.Matrix([[sp.Rational(5, 3), sp.Rational(-5, 4), sp.Rational(-1, 2)],
                   [sp.Rational(-5, 4), sp.Rational(5, 3), sp.Rational(-1, 2)],
                   [sp.Rational(-1, 2), sp.Rational(-1, 2), sp.Rational(8, 3)]])
    root = sp.Rational(37, 24) - sp.sqrt(113) / 8
    (direction,) = _unit_axes(J, root, 1)
    assert direction == sp.Matrix([4, 4, sp.sqrt(113) - 9])


def test_denominators_in_the_parameters_are_cleared_and_the_common_factor_taken_out():
    b, h, P = sp.symbols("b h P", positive=True)
    v = sp.Matrix([126, 42 * sp.sqrt(3), 56 * sp.sqrt(3) * h / b - 56 * sp.sqrt(3) * b / h
                   + 28 * sp.sqrt(3) * sp.sqrt(P) / (b * h)])
    cleared = _integral(v)
    assert cleared == sp.Matrix([9 * b * h, 3 * sp.sqrt(3) * b * h,
                                 sp.expand(2 * sp.sqrt(3) * (2 * h**2 - 2 * b**2 + sp.sqrt(P)))])
    assert sp.simplify(cleared[2] / cleared[0] - v[2] / v[0]) == 0  # the same direction
