"""The part-shapes (half disk, half ring, quarter disk, hemispherical shell) against an
exact derivation: sympy integrates a uniform density over each shape in polar or
spherical coordinates, here, and the centre of mass and J about it must equal
``own_properties`` exactly (simplify(a − b) == 0)."""

from __future__ import annotations

import pytest
import sympy as sp

from rbdsolve.model.inertia import own_properties
from rbdsolve.problem.schema import Shape

m, r = sp.symbols("m r", positive=True)
s, th, ph = sp.symbols("s theta phi", real=True)


def _plane(top, wire: bool):
    """(point, measure, ranges) of a sector of angle ``top`` from the +x axis: a wire
    (ds = r dθ) or a lamina (dA = s ds dθ)."""
    if wire:
        return sp.Matrix([r * sp.cos(th), r * sp.sin(th), 0]), r, [(th, 0, top)]
    return sp.Matrix([s * sp.cos(th), s * sp.sin(th), 0]), s, [(s, 0, r), (th, 0, top)]


def _dome():
    """The hemispherical shell z ≥ 0: dA = r² sin θ dθ dφ."""
    p = sp.Matrix([r * sp.sin(th) * sp.cos(ph), r * sp.sin(th) * sp.sin(ph), r * sp.cos(th)])
    return p, r**2 * sp.sin(th), [(th, 0, sp.pi / 2), (ph, 0, 2 * sp.pi)]


GEOMETRY = {
    Shape.HALF_DISK: lambda: _plane(sp.pi, False),
    Shape.QUARTER_DISK: lambda: _plane(sp.pi / 2, False),
    Shape.HALF_RING: lambda: _plane(sp.pi, True),
    Shape.HEMISPHERICAL_SHELL: _dome,
}


def _integral(f, weight, ranges):
    return sp.integrate(f * weight, *ranges)


@pytest.mark.parametrize("shape", list(GEOMETRY), ids=lambda s: s.value)
def test_centre_and_inertia_by_integration(shape: Shape) -> None:
    p, weight, ranges = GEOMETRY[shape]()
    measure = _integral(1, weight, ranges)
    centre = sp.Matrix([_integral(p[i], weight, ranges) for i in range(3)]) / measure
    rho = p - centre
    J = sp.Matrix(3, 3, lambda i, j: m * _integral((rho.dot(rho) if i == j else 0) - rho[i] * rho[j],
                                                   weight, ranges) / measure)
    props = own_properties(shape, m, {"radius": r})
    assert (props.centre - centre).applyfunc(sp.simplify) == sp.zeros(3, 1)
    assert (props.inertia - J).applyfunc(sp.simplify) == sp.zeros(3, 3)


def test_half_disk_about_its_contact_point() -> None:
    """The rocking half-disk's textbook numbers: J_G = m r² (1/2 − 16/(9π²))."""
    props = own_properties(Shape.HALF_DISK, m, {"radius": r})
    assert sp.simplify(props.inertia[2, 2] - m * r**2 * (sp.Rational(1, 2) - 16 / (9 * sp.pi**2))) == 0
