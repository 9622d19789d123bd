"""The shape library against numeric integration of each shape's density.

The expectations here come from the geometry alone (docs/format.md, the module
docstring of :mod:`rbdsolve.model.inertia`), never from its formulas: each shape is
parametrized over its volume, surface or curve, a uniform density is integrated with
``scipy.integrate.nquad`` (adaptive Gauss-Kronrod, epsabs 1e-13, epsrel 1e-12), and the
centre of mass c = ∫ p dm / m and the inertia tensor about it,
J_G = ∫ (|ρ|² 1 − ρ ρᵀ) dm with ρ = p − c (so J_xy = −∫ x y dm), are compared with
``own_properties`` at numeric dimensions (symbols substituted). Quadrature of these
smooth integrands is good to ~1e-12, so the comparisons use rtol 1e-8, with an absolute
floor of 1e-10 · m · (size)² for entries that vanish.

Also checked:

* ``body_properties`` with oblique axes against the integral over the *rotated* solid,
  the rotation built here independently (scipy's rotation vector: the smallest turn
  taking the own axis onto the requested direction, as ``rotation_to`` documents);
* hypothesis properties: J_G symmetric, positive semidefinite, principal moments obey
  J1 + J2 ≥ J3; a rotation keeps the principal moments; ``combine`` adds masses and
  first moments, is a parallel-axis round trip, and a box with a box-shaped hole equals
  the integral over the remaining solid (tensor Gauss-Legendre on cells cut at the hole's
  faces: exact for these piecewise-quadratic integrands, rtol 1e-10).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from itertools import pairwise

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import nquad
from scipy.spatial.transform import Rotation
from scipy.special import roots_legendre

from rbdsolve.model.inertia import (
    OWN_AXIS,
    MassProperties,
    body_properties,
    combine,
    own_properties,
    rotation_to,
)
from rbdsolve.problem.schema import Shape

TWO_PI = 2 * math.pi
QUAD_OPTS = {"epsabs": 1e-13, "epsrel": 1e-12, "limit": 100}
RTOL = 1e-8  # quadrature comparisons
ATOL_SCALE = 1e-10  # absolute floor, times m · size², for entries that are zero


# --------------------------------------------------------------------------------------
# Geometry: each shape as a parametrization (point(u), measure weight(u), ranges of u)
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Geometry:
    """A uniform density: p(u) with the measure weight(u) du over ``ranges``
    (nquad order: innermost variable first; a range may be a callable of the outer ones)."""

    point: Callable[..., tuple[float, float, float]]
    weight: Callable[..., float]
    ranges: list
    size: float  # a typical length, for absolute tolerances


def geometry(shape: Shape, d: dict[str, float]) -> Geometry:
    def one(*u: float) -> float:
        return 1.0

    if shape is Shape.PARTICLE:
        return Geometry(lambda: (0.0, 0.0, 0.0), one, [], 1.0)
    if shape is Shape.ROD:  # arc length x along own x, centred
        L = d["length"]
        return Geometry(lambda x: (x, 0.0, 0.0), one, [(-L / 2, L / 2)], L)
    if shape is Shape.RING:  # ds = r dθ
        r = d["radius"]
        return Geometry(
            lambda t: (r * math.cos(t), r * math.sin(t), 0.0), lambda t: r, [(0, TWO_PI)], r
        )
    if shape is Shape.DISK:  # dA = s ds dθ
        r = d["radius"]
        return Geometry(lambda s, t: (s * math.cos(t), s * math.sin(t), 0.0), lambda s, t: s,
                        [(0, r), (0, TWO_PI)], r)  # fmt: skip
    if shape is Shape.CYLINDRICAL_SHELL:  # dA = r dθ dz
        r, h = d["radius"], d["height"]
        return Geometry(lambda t, z: (r * math.cos(t), r * math.sin(t), z), lambda t, z: r,
                        [(0, TWO_PI), (-h / 2, h / 2)], max(r, h))  # fmt: skip
    if shape in (Shape.CYLINDER, Shape.TUBE):  # dV = s ds dθ dz
        a, b = (
            (0.0, d["radius"])
            if shape is Shape.CYLINDER
            else (d["inner_radius"], d["outer_radius"])
        )
        h = d["height"]
        return Geometry(lambda s, t, z: (s * math.cos(t), s * math.sin(t), z), lambda s, t, z: s,
                        [(a, b), (0, TWO_PI), (-h / 2, h / 2)], max(b, h))  # fmt: skip
    if shape is Shape.SPHERICAL_SHELL:  # polar angle θ, azimuth φ: dA = r² sin θ dθ dφ
        r = d["radius"]
        return Geometry(
            lambda th, ph: (r * math.sin(th) * math.cos(ph), r * math.sin(th) * math.sin(ph), r * math.cos(th)),
            lambda th, ph: r * r * math.sin(th), [(0, math.pi), (0, TWO_PI)], r)  # fmt: skip
    if shape in (Shape.SPHERE, Shape.HEMISPHERE):  # dV = s² sin θ ds dθ dφ
        r = d["radius"]
        top = math.pi if shape is Shape.SPHERE else math.pi / 2  # hemisphere: z ≥ 0
        return Geometry(
            lambda s, th, ph: (s * math.sin(th) * math.cos(ph), s * math.sin(th) * math.sin(ph), s * math.cos(th)),
            lambda s, th, ph: s * s * math.sin(th), [(0, r), (0, top), (0, TWO_PI)], r)  # fmt: skip
    if shape in (Shape.HALF_DISK, Shape.QUARTER_DISK):  # dA = s ds dθ over θ ∈ [0, π] or [0, π/2]
        r = d["radius"]
        top = math.pi if shape is Shape.HALF_DISK else math.pi / 2
        return Geometry(lambda s, t: (s * math.cos(t), s * math.sin(t), 0.0), lambda s, t: s,
                        [(0, r), (0, top)], r)  # fmt: skip
    if shape is Shape.HALF_RING:  # ds = r dθ, θ ∈ [0, π]
        r = d["radius"]
        return Geometry(lambda t: (r * math.cos(t), r * math.sin(t), 0.0), lambda t: r, [(0, math.pi)], r)
    if shape is Shape.HEMISPHERICAL_SHELL:  # dA = r² sin θ dθ dφ, θ ∈ [0, π/2] (z ≥ 0)
        r = d["radius"]
        return Geometry(
            lambda th, ph: (r * math.sin(th) * math.cos(ph), r * math.sin(th) * math.sin(ph), r * math.cos(th)),
            lambda th, ph: r * r * math.sin(th), [(0, math.pi / 2), (0, TWO_PI)], r)  # fmt: skip
    if shape is Shape.CYLINDER_SEGMENT:  # y ≥ r cos α inside the circle: x across, then y, then z
        r, h, a = d["radius"], d["height"], d["half_angle"]
        return Geometry(lambda x, y, z: (x, y, z), one,
                        [lambda y, z: (-math.sqrt(max(r * r - y * y, 0.0)), math.sqrt(max(r * r - y * y, 0.0))),
                         (r * math.cos(a), r), (-h / 2, h / 2)], max(r, h))  # fmt: skip
    if shape is Shape.CONE:  # base disk at z = 0, apex at z = h: radius r (1 − z/h) at height z
        r, h = d["radius"], d["height"]
        return Geometry(lambda s, t, z: (s * math.cos(t), s * math.sin(t), z), lambda s, t, z: s,
                        [lambda t, z: (0, r * (1 - z / h)), (0, TWO_PI), (0, h)], max(r, h))  # fmt: skip
    if shape is Shape.BOX:
        a, b, c = d["width"], d["depth"], d["height"]
        return Geometry(lambda x, y, z: (x, y, z), one, [(-a / 2, a / 2), (-b / 2, b / 2), (-c / 2, c / 2)],
                        max(a, b, c))  # fmt: skip
    if shape is Shape.PLATE:
        a, b = d["width"], d["height"]
        return Geometry(
            lambda x, y: (x, y, 0.0), one, [(-a / 2, a / 2), (-b / 2, b / 2)], max(a, b)
        )
    if shape is Shape.TRIANGLE:  # vertices (0,0), (base,0), (apex,height): at height y the
        # lamina runs from the left edge x = apex·y/height to the right edge
        # x = base + (apex − base)·y/height
        b, h, a = d["base"], d["height"], d["apex"]
        return Geometry(lambda x, y: (x, y, 0.0), one,
                        [lambda y: (a * y / h, b + (a - b) * y / h), (0, h)], max(b, h, abs(a)))  # fmt: skip
    raise AssertionError(f"no test geometry for {shape}")


def integrate(
    geo: Geometry, f: Callable[[tuple[float, float, float]], float], Q: np.ndarray | None = None
) -> float:
    """∫ f(Q p(u)) weight(u) du over the geometry (Q = None: own axes)."""

    point, weight = geo.point, geo.weight  # plain floats: nquad calls this ~10⁵ times
    if Q is None:

        def integrand(*u: float) -> float:
            return f(point(*u)) * weight(*u)

    else:
        (q00, q01, q02), (q10, q11, q12), (q20, q21, q22) = Q.tolist()

        def integrand(*u: float) -> float:
            x, y, z = point(*u)
            rotated = (
                q00 * x + q01 * y + q02 * z,
                q10 * x + q11 * y + q12 * z,
                q20 * x + q21 * y + q22 * z,
            )
            return f(rotated) * weight(*u)

    if not geo.ranges:  # a point: the "integral" of a unit point mass
        return integrand()
    value, _ = nquad(integrand, geo.ranges, opts=QUAD_OPTS)
    return value


def integrated_properties(
    geo: Geometry, m: float, Q: np.ndarray | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """(centre of mass, J about it) of mass m spread uniformly over the geometry."""
    measure = integrate(geo, lambda p: 1.0, Q)
    first = np.array([integrate(geo, lambda p, i=i: p[i], Q) for i in range(3)]) / measure
    second = np.zeros((3, 3))
    for i in range(3):
        for j in range(i, 3):
            second[i, j] = second[j, i] = (
                integrate(geo, lambda p, i=i, j=j: p[i] * p[j], Q) / measure
            )
    S = second - np.outer(first, first)  # ∫ ρ ρᵀ dm / m, ρ from the centre of mass
    J = m * (np.trace(S) * np.eye(3) - S)
    return first, J


# --------------------------------------------------------------------------------------
# own_properties, shape by shape
# --------------------------------------------------------------------------------------

M = 2.3
SAMPLES: dict[str, tuple[Shape, dict[str, float]]] = {
    "particle": (Shape.PARTICLE, {}),
    "rod": (Shape.ROD, {"length": 1.7}),
    "ring": (Shape.RING, {"radius": 0.7}),
    "disk": (Shape.DISK, {"radius": 0.7}),
    "cylindrical_shell": (Shape.CYLINDRICAL_SHELL, {"radius": 0.7, "height": 1.9}),
    "cylinder": (Shape.CYLINDER, {"radius": 0.7, "height": 1.9}),
    "tube": (Shape.TUBE, {"inner_radius": 0.4, "outer_radius": 0.9, "height": 1.9}),
    "spherical_shell": (Shape.SPHERICAL_SHELL, {"radius": 0.7}),
    "sphere": (Shape.SPHERE, {"radius": 0.7}),
    "hemisphere": (Shape.HEMISPHERE, {"radius": 0.7}),
    "hemispherical_shell": (Shape.HEMISPHERICAL_SHELL, {"radius": 0.7}),
    "half_disk": (Shape.HALF_DISK, {"radius": 0.7}),
    "half_ring": (Shape.HALF_RING, {"radius": 0.7}),
    "quarter_disk": (Shape.QUARTER_DISK, {"radius": 0.7}),
    "cylinder_segment": (Shape.CYLINDER_SEGMENT, {"radius": 0.7, "height": 1.9, "half_angle": 1.1}),
    # more than half the cylinder: the chord below the centre
    "cylinder_segment_large": (Shape.CYLINDER_SEGMENT, {"radius": 0.7, "height": 0.5, "half_angle": 2.3}),
    "cone": (Shape.CONE, {"radius": 0.7, "height": 1.9}),
    "box": (Shape.BOX, {"width": 0.8, "depth": 1.3, "height": 2.1}),
    "plate": (Shape.PLATE, {"width": 0.8, "height": 1.3}),
    "triangle": (Shape.TRIANGLE, {"base": 2.0, "height": 1.1, "apex": 0.6}),
    # apex beyond the base: an obtuse triangle leaning right (nonzero J_xy still)
    "triangle_apex_outside": (Shape.TRIANGLE, {"base": 2.0, "height": 1.1, "apex": 2.7}),
}


def test_every_shape_is_sampled() -> None:
    assert {shape for shape, _ in SAMPLES.values()} == set(Shape)
    for shape, dims in SAMPLES.values():
        assert set(dims) == set(shape.dimensions), shape


def symbolic(shape: Shape) -> tuple[sp.Symbol, dict[str, sp.Symbol]]:
    return sp.Symbol("m", positive=True), {n: sp.Symbol(n, positive=True) for n in shape.dimensions}


def numeric(
    props: MassProperties, values: dict[sp.Symbol, float]
) -> tuple[float, np.ndarray, np.ndarray]:
    """Substitute numbers into the sympy results."""

    def num(e: sp.Matrix) -> np.ndarray:
        return np.array(e.subs(values).evalf(30).tolist(), dtype=float)

    return (
        float(sp.sympify(props.mass).subs(values)),
        num(props.centre).reshape(3),
        num(props.inertia),
    )


@pytest.mark.parametrize("case", list(SAMPLES), ids=list(SAMPLES))
def test_own_properties_match_integration(case: str) -> None:
    shape, dims = SAMPLES[case]
    m, syms = symbolic(shape)
    props = own_properties(shape, m, dict(syms))
    values = {m: M, **{syms[n]: v for n, v in dims.items()}}
    mass, centre, J = numeric(props, values)

    geo = geometry(shape, dims)
    c_int, J_int = integrated_properties(geo, M)

    assert mass == pytest.approx(M, rel=1e-14)
    # the library's tensor must be symmetric in exact arithmetic
    assert (props.inertia - props.inertia.T).applyfunc(sp.simplify) == sp.zeros(3, 3)
    np.testing.assert_allclose(centre, c_int, rtol=RTOL, atol=ATOL_SCALE * geo.size,
                               err_msg=f"{case}: centre of mass (rtol {RTOL})")  # fmt: skip
    np.testing.assert_allclose(J, J_int, rtol=RTOL, atol=ATOL_SCALE * M * geo.size**2,
                               err_msg=f"{case}: J about the centre of mass (rtol {RTOL})")  # fmt: skip


# --------------------------------------------------------------------------------------
# body_properties: oblique axes, against the rotated solid
# --------------------------------------------------------------------------------------


def own_axis(shape: Shape) -> np.ndarray:
    return np.array([1.0, 0.0, 0.0]) if shape is Shape.ROD else np.array([0.0, 0.0, 1.0])


def smallest_rotation(own: np.ndarray, axis: np.ndarray) -> np.ndarray:
    """The turn about own × axis by the angle between them (scipy), taking own onto the
    unit axis; for opposite directions a half turn about x (own = z) or z (own = x)."""
    d = axis / np.linalg.norm(axis)
    k = np.cross(own, d)
    angle = math.atan2(np.linalg.norm(k), float(own @ d))
    if np.linalg.norm(k) < 1e-15:
        if own @ d > 0:
            return np.eye(3)
        normal = np.array([1.0, 0, 0]) if own[2] != 0 else np.array([0, 0, 1.0])
        return Rotation.from_rotvec(math.pi * normal).as_matrix()
    return Rotation.from_rotvec(angle * k / np.linalg.norm(k)).as_matrix()


OBLIQUE = {
    "cone-122": ("cone", [1, 2, 2]),
    "box-110": ("box", [1, 1, 0]),
    "triangle-2m12": ("triangle", [2, -1, 2]),
    "rod-034": ("rod", [0, 3, 4]),
    "hemisphere-down": ("hemisphere", [0, 0, -1]),  # opposite to its own axis
}


@pytest.mark.parametrize("key", list(OBLIQUE), ids=list(OBLIQUE))
def test_body_properties_match_rotated_solid(key: str) -> None:
    case, axis_list = OBLIQUE[key]
    shape, dims = SAMPLES[case]
    m, syms = symbolic(shape)
    axis = sp.Matrix(axis_list)
    values = {m: M, **{syms[n]: v for n, v in dims.items()}}
    mass, centre, J = numeric(body_properties(shape, m, dict(syms), axis), values)
    _, centre_own, _ = numeric(own_properties(shape, m, dict(syms)), values)

    d = np.array(axis_list, dtype=float) / np.linalg.norm(axis_list)
    own = own_axis(shape)
    Q = smallest_rotation(own, np.array(axis_list, dtype=float))
    assert Q @ own == pytest.approx(d, abs=1e-14)  # our rotation is right

    # the library's rotation: orthogonal, proper, own axis onto the unit axis direction
    Q_lib = rotation_to(axis, OWN_AXIS.get(shape, sp.Matrix([0, 0, 1])))
    assert (Q_lib * sp.Matrix(own.astype(int)) - axis / sp.sqrt(axis.dot(axis))).applyfunc(
        sp.simplify
    ) == sp.zeros(3, 1)
    assert (Q_lib.T * Q_lib).applyfunc(sp.simplify) == sp.eye(3)
    assert sp.simplify(Q_lib.det()) == 1
    if shape not in (Shape.CONE, Shape.HEMISPHERE):  # not axisymmetric: the turn matters
        np.testing.assert_allclose(np.array(Q_lib.evalf(), dtype=float), Q, atol=1e-14,
                                   err_msg="rotation_to is not the smallest turn")  # fmt: skip

    geo = geometry(shape, dims)
    c_int, J_int = integrated_properties(geo, M, Q)
    assert mass == pytest.approx(M, rel=1e-14)
    np.testing.assert_allclose(centre, Q @ centre_own, rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(centre, c_int, rtol=RTOL, atol=ATOL_SCALE * geo.size,
                               err_msg=f"{key}: centre (rtol {RTOL})")  # fmt: skip
    np.testing.assert_allclose(J, J_int, rtol=RTOL, atol=ATOL_SCALE * M * geo.size**2,
                               err_msg=f"{key}: J of the rotated solid (rtol {RTOL})")  # fmt: skip


# --------------------------------------------------------------------------------------
# Properties (hypothesis)
# --------------------------------------------------------------------------------------

lengths = st.integers(min_value=1, max_value=40).map(lambda k: sp.Rational(k, 8))


@st.composite
def shapes_with_dims(draw) -> tuple[Shape, sp.Expr, dict[str, sp.Expr]]:
    shape = draw(st.sampled_from(list(Shape)))
    dims = {n: draw(lengths) for n in shape.dimensions}
    if shape is Shape.TUBE:
        dims["outer_radius"] = dims["inner_radius"] + draw(lengths)
    if shape is Shape.CYLINDER_SEGMENT:  # an angle, at most π
        dims["half_angle"] = sp.Rational(draw(st.integers(min_value=1, max_value=25)), 8)
    if shape is Shape.TRIANGLE:  # the apex may lie anywhere along the top line
        dims["apex"] = sp.Rational(draw(st.integers(min_value=-40, max_value=80)), 8)
    return shape, draw(lengths), dims


def as_array(e: sp.Matrix) -> np.ndarray:
    return np.array(e.evalf(30).tolist(), dtype=float)


@settings(max_examples=25, deadline=None)
@given(shapes_with_dims())
def test_inertia_is_physical(sample) -> None:
    """Symmetric, positive semidefinite, principal moments obey J1 + J2 ≥ J3."""
    shape, m, dims = sample
    J_exact = own_properties(shape, m, dims).inertia
    assert J_exact == J_exact.T
    J = as_array(J_exact)
    moments = np.linalg.eigvalsh(J)
    tol = 1e-12 * max(1.0, float(np.abs(J).max()))  # planar shapes sit on J1 + J2 = J3
    assert moments.min() >= -tol
    J1, J2, J3 = sorted(moments)
    assert J1 + J2 >= J3 - tol


@settings(max_examples=6, deadline=None)
@given(shapes_with_dims(), st.lists(st.integers(-3, 3), min_size=3, max_size=3).filter(any))
def test_rotation_keeps_principal_moments(sample, axis_list) -> None:
    shape, m, dims = sample
    own = own_properties(shape, m, dims)
    body = body_properties(shape, m, dims, sp.Matrix(axis_list))
    J_own, J_body = as_array(own.inertia), as_array(body.inertia)
    scale = max(1.0, float(np.abs(J_own).max()))
    np.testing.assert_allclose(
        np.linalg.eigvalsh(J_body), np.linalg.eigvalsh(J_own), atol=1e-12 * scale
    )
    np.testing.assert_allclose(J_body, J_body.T, atol=1e-12 * scale)
    assert np.linalg.norm(as_array(body.centre)) == pytest.approx(
        np.linalg.norm(as_array(own.centre)), abs=1e-12
    )


positions = st.lists(
    st.integers(-9, 9).map(lambda k: sp.Rational(k, 4)), min_size=3, max_size=3
).map(sp.Matrix)


def steiner(m: float, J: np.ndarray, c: np.ndarray) -> np.ndarray:
    """J about the origin of a body with J about its centre of mass at c (independent)."""
    return J + m * (float(c @ c) * np.eye(3) - np.outer(c, c))


@settings(max_examples=10, deadline=None)
@given(shapes_with_dims(), positions, shapes_with_dims(), positions)
def test_combine_round_trips(a, pa, b, pb) -> None:
    shape_a, m_a, dims_a = a
    shape_b, m_b, dims_b = b
    A = own_properties(shape_a, m_a, dims_a)
    B = own_properties(shape_b, m_b, dims_b)

    # one part alone: its centre is where it was put, J is unchanged (shift and back)
    alone = combine([(A, pa)])
    assert sp.simplify(alone.mass - m_a) == 0
    assert (alone.centre - pa).applyfunc(sp.simplify) == sp.zeros(3, 1)
    assert (alone.inertia - A.inertia).applyfunc(sp.simplify) == sp.zeros(3, 3)

    # two parts: mass and first moment add; J about the origin is the sum of the parts'
    both = combine([(A, pa), (B, pb)])
    assert sp.simplify(both.mass - (m_a + m_b)) == 0
    assert (both.mass * both.centre - (m_a * pa + m_b * pb)).applyfunc(sp.simplify) == sp.zeros(
        3, 1
    )
    J_origin = steiner(float(both.mass), as_array(both.inertia), as_array(both.centre).reshape(3))
    expected = steiner(float(m_a), as_array(A.inertia), as_array(pa).reshape(3)) + steiner(
        float(m_b), as_array(B.inertia), as_array(pb).reshape(3)
    )
    np.testing.assert_allclose(
        J_origin, expected, rtol=1e-12, atol=1e-12 * max(1.0, np.abs(expected).max())
    )

    # adding B and then a hole shaped like B at the same place gives back A at pa
    hole = MassProperties(-B.mass, B.centre, -B.inertia)
    back = combine([(both, both.centre), (hole, pb)])
    assert sp.simplify(back.mass - m_a) == 0
    assert (back.centre - pa).applyfunc(sp.simplify) == sp.zeros(3, 1)
    assert (back.inertia - A.inertia).applyfunc(sp.simplify) == sp.zeros(3, 3)


@settings(max_examples=10, deadline=None)
@given(st.lists(st.tuples(shapes_with_dims(), positions), min_size=1, max_size=4))
def test_combine_adds_masses(parts) -> None:
    props = [(own_properties(shape, m, dims), p) for (shape, m, dims), p in parts]
    total = combine(props)
    assert total.mass == sum(m for (_, m, _), _ in parts)
    assert total.mass * total.centre == sum((m * p for (_, m, _), p in parts), sp.zeros(3, 1))


GAUSS_X, GAUSS_W = roots_legendre(3)  # exact for polynomials of degree ≤ 5 on each cell


def gauss_over_cells(
    breaks: list[list[float]], f: Callable[[np.ndarray, np.ndarray, np.ndarray], np.ndarray]
) -> float:
    """∫ f over the box cut into cells at ``breaks`` (per axis), tensor Gauss-Legendre."""
    nodes, weights = [], []
    for b in breaks:
        xs, ws = [], []
        for lo, hi in pairwise(b):
            xs.append((lo + hi) / 2 + (hi - lo) / 2 * GAUSS_X)
            ws.append((hi - lo) / 2 * GAUSS_W)
        nodes.append(np.concatenate(xs))
        weights.append(np.concatenate(ws))
    X, Y, Z = np.meshgrid(*nodes, indexing="ij")
    W = np.einsum("i,j,k->ijk", *weights)
    return float(np.sum(W * f(X, Y, Z)))


@st.composite
def box_with_hole(draw):
    outer = [draw(st.integers(3, 12)) for _ in range(3)]
    inner = [draw(st.integers(1, n - 1)) for n in outer]
    # hole centre such that the hole stays inside: |p| ≤ (outer − inner)/2, in halves
    centre = [sp.Rational(draw(st.integers(-(n - k), n - k)), 2) for n, k in zip(outer, inner)]
    return outer, inner, centre, sp.Rational(draw(st.integers(1, 9)), 4)  # density


@settings(max_examples=8, deadline=None)
@given(box_with_hole())
def test_box_with_box_hole_matches_integral_of_remaining_solid(sample) -> None:
    outer, inner, centre, rho = sample
    names = Shape.BOX.dimensions
    V, v = math.prod(outer), math.prod(inner)
    full = own_properties(Shape.BOX, rho * V, dict(zip(names, map(sp.Integer, outer))))
    cut = own_properties(Shape.BOX, rho * v, dict(zip(names, map(sp.Integer, inner))))
    hole = MassProperties(-cut.mass, cut.centre, -cut.inertia)
    result = combine([(full, sp.zeros(3, 1)), (hole, sp.Matrix(centre))])

    # integrate the density of the remaining solid: ρ on the outer box, 0 inside the hole
    c = [float(x) for x in centre]
    breaks = [sorted({-n / 2, ci - k / 2, ci + k / 2, n / 2}) for n, k, ci in zip(outer, inner, c)]

    def solid(X, Y, Z):
        inside = (
            (np.abs(X - c[0]) < inner[0] / 2)
            & (np.abs(Y - c[1]) < inner[1] / 2)
            & (np.abs(Z - c[2]) < inner[2] / 2)
        )
        return float(rho) * (~inside)

    mass = gauss_over_cells(breaks, solid)
    first = np.array([gauss_over_cells(breaks, lambda *P, i=i: solid(*P) * P[i]) for i in range(3)])
    second = np.array([[gauss_over_cells(breaks, lambda *P, i=i, j=j: solid(*P) * P[i] * P[j])
                        for j in range(3)] for i in range(3)])  # fmt: skip
    C = first / mass
    S = second - mass * np.outer(C, C)  # ∫ ρρᵀ dm about the centre of mass
    J = np.trace(S) * np.eye(3) - S

    assert float(result.mass) == pytest.approx(mass, rel=1e-12)
    assert float(result.mass) == pytest.approx(float(rho) * (V - v), rel=1e-14)
    np.testing.assert_allclose(as_array(result.centre).reshape(3), C, rtol=1e-10, atol=1e-10)
    np.testing.assert_allclose(
        as_array(result.inertia), J, rtol=1e-10, atol=1e-10 * np.abs(J).max()
    )


def test_the_cylinder_segment_by_sympy_integration() -> None:
    """The segment's area, first and second moments over its cross-section, integrated
    by sympy in polar coordinates (ρ from r cos α/cos ψ to r, ψ from −α to α) for α
    below π/2, against the library's centre and J_O = J_G + m(|d|² 1 − d dᵀ)."""
    from rbdsolve.model.inertia import parallel_axis

    r, h, m = sp.Rational(7, 10), sp.Rational(19, 10), sp.Rational(23, 10)
    alpha = sp.pi / 3
    rho, psi = sp.symbols("rho psi", real=True)

    def over_section(f):
        inner = sp.integrate(f * rho, (rho, r * sp.cos(alpha) / sp.cos(psi), r))
        return sp.integrate(inner, (psi, -alpha, alpha))

    x, y = rho * sp.sin(psi), rho * sp.cos(psi)
    area = over_section(sp.Integer(1))
    props = own_properties(Shape.CYLINDER_SEGMENT, m, {"radius": r, "height": h, "half_angle": alpha})
    J_O = props.inertia + parallel_axis(m, props.centre)
    expected_centre = over_section(y) / area
    expected = [m * (over_section(y**2) / area + h**2 / 12), m * (over_section(x**2) / area + h**2 / 12),
                m * over_section(rho**2) / area]
    assert sp.N(props.centre[1] - expected_centre, 30) == pytest.approx(0, abs=1e-25)
    for k in range(3):
        assert sp.N(J_O[k, k] - expected[k], 30) == pytest.approx(0, abs=1e-25), k
