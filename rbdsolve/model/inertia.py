"""The shape library: mass distribution of each shape, in the shape's own axes.

For each shape: its **origin** (the point a problem file places with ``at:``), the
**centre of mass** relative to that origin, and the **inertia tensor about the centre of
mass**. Table formulas, e.g. Meriam & Kraige, *Engineering Mechanics: Dynamics*,
Appendix B; each is checked in tests/model/test_shape_library.py against numeric
integration of the shape's density.

Own axes: an axisymmetric shape has its axis along its own z (a rod along its own x);
a plate lies in its own xy-plane (``width`` along x, ``height`` along y); a box has
``width``, ``depth``, ``height`` along x, y, z; a triangle lies in its xy-plane with
vertices (0, 0), (base, 0), (apex, height). The part-shapes (``half_disk``,
``half_ring``, ``quarter_disk``, ``hemisphere``, ``hemispherical_shell``) have their
origin at the centre of the full circle or sphere, and their own axis is the symmetry
axis pointing into the material: +y for a half disk or half ring in the xy-plane (y ≥ 0),
the diagonal (1, 1, 0)/√2 for a quarter disk (x, y ≥ 0), +z for a hemisphere (z ≥ 0).

Products of inertia follow the tensor convention J_xy = −∫ x y dm, as in SG2150.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from rbdsolve.problem.schema import Shape

# The shape's own symmetry axis ("its axis"): what ``axis:`` in a problem file points.
OWN_AXIS = {Shape.ROD: sp.Matrix([1, 0, 0]), Shape.HALF_DISK: sp.Matrix([0, 1, 0]),
            Shape.HALF_RING: sp.Matrix([0, 1, 0]), Shape.QUARTER_DISK: sp.Matrix([1, 1, 0]) / sp.sqrt(2),
            Shape.CYLINDER_SEGMENT: sp.Matrix([0, 1, 0])}
_Z = sp.Matrix([0, 0, 1])


@dataclass(frozen=True)
class MassProperties:
    """Mass, centre of mass (from the shape's origin) and J about the centre of mass."""

    mass: sp.Expr
    centre: sp.Matrix
    inertia: sp.Matrix


def own_properties(shape: Shape, m: sp.Expr, dims: dict[str, sp.Expr]) -> MassProperties:
    """The shape's mass properties in its own axes."""
    centre = sp.zeros(3, 1)
    if shape in _PART_SHAPES:
        return _part_shape(shape, m, dims["radius"])
    if shape is Shape.CYLINDER_SEGMENT:
        return _segment(m, dims["radius"], dims["height"], dims["half_angle"])
    if shape is Shape.HEMISPHERE:
        centre = sp.Matrix([0, 0, 3 * dims["radius"] / 8])
    elif shape is Shape.CONE:
        centre = sp.Matrix([0, 0, dims["height"] / 4])
    elif shape is Shape.TRIANGLE:
        centre = sp.Matrix([(dims["base"] + dims["apex"]) / 3, dims["height"] / 3, 0])
    if shape is Shape.TRIANGLE:
        return MassProperties(m, centre, _triangle(m, dims))
    return MassProperties(m, centre, sp.diag(*_moments(shape, m, dims)))


def _part_shape(shape: Shape, m: sp.Expr, r: sp.Expr) -> MassProperties:
    """A part of a disk, ring or spherical shell: J about the centre O of the full
    circle or sphere, then moved to the centre of mass G by Steiner, J_G = J_O − m(|d|² 1 − d dᵀ).

    J_O is the full shape's, per unit mass, wherever the cut respects its symmetry: a half
    or quarter of a disk carries the same share of every second moment ∫ x² dm, ∫ y² dm
    as of the mass, so J_O = diag(m r²/4, m r²/4, m r²/2) for each (a half ring:
    diag(m r²/2, m r²/2, m r²); a hemispherical shell: 2 m r²/3 about every axis). Only the
    quarter disk keeps a product: ∫ x y dA = ∫₀^r ∫₀^{π/2} s³ cos θ sin θ dθ ds = r⁴/8 over
    the area π r²/4, so J_xy = −∫ x y dm = −m r²/(2π).

    Centres (first moments over the measure): half disk ∫ y dA / A = (2r³/3)/(π r²/2) =
    4r/(3π); half ring ∫ y ds / L = 2r²/(π r) = 2r/π; quarter disk 4r/(3π) along x and y;
    hemispherical shell ∫ z dA / A = π r³/(2π r²) = r/2 (Archimedes' hat-box: equal
    areas in equal heights). E.g. Meriam & Kraige, Appendix C (centroids) and B.
    """
    if shape is Shape.HALF_DISK:
        d, J_O = sp.Matrix([0, 4 * r / (3 * sp.pi), 0]), sp.diag(m * r**2 / 4, m * r**2 / 4, m * r**2 / 2)
    elif shape is Shape.HALF_RING:
        d, J_O = sp.Matrix([0, 2 * r / sp.pi, 0]), sp.diag(m * r**2 / 2, m * r**2 / 2, m * r**2)
    elif shape is Shape.QUARTER_DISK:
        a = 4 * r / (3 * sp.pi)
        d = sp.Matrix([a, a, 0])
        J_O = sp.Matrix([[m * r**2 / 4, -m * r**2 / (2 * sp.pi), 0],
                         [-m * r**2 / (2 * sp.pi), m * r**2 / 4, 0], [0, 0, m * r**2 / 2]])
    else:  # hemispherical shell
        d, J_O = sp.Matrix([0, 0, r / 2]), sp.diag(*(3 * [2 * m * r**2 / 3]))
    return MassProperties(m, d, (J_O - parallel_axis(m, d)).applyfunc(_tidy_pi))


def _segment(m: sp.Expr, r: sp.Expr, h: sp.Expr, alpha: sp.Expr) -> MassProperties:
    """A solid cylinder segment: the part y ≥ r cos α of a cylinder of radius r and
    length h (along z, centred on z = 0), the arc spanning 2α about the centre O (α = π/2:
    a half cylinder). Over the cross-section, in polar coordinates from O with ψ from +y,
    ρ from r cos α/cos ψ to r and ψ from −α to α:

        A = r² (α − sin α cos α),           ∫ y dA = (2/3) r³ sin³α,
        ∫ x² dA = (r⁴/4)(α − sin α cos α − (2/3) sin³α cos α),
        ∫ (x² + y²) dA = (r⁴/2)(α − sin α cos³α − (1/3) sin³α cos α)

    (∫ sec⁴ψ dψ = tan ψ + tan³ψ/3; checked against sympy's integration in
    tests/model/test_shape_library.py). So G is ȳ = 2 r sin³α/(3(α − sin α cos α)) from O,
    J_O = m diag(⟨y²⟩ + h²/12, ⟨x²⟩ + h²/12, ⟨x²⟩ + ⟨y²⟩) with ⟨·⟩ = ∫ · dA/A, and
    J_G = J_O − m(|d|² 1 − d dᵀ), each moment over one denominator with the area's
    power kept whole; not simplified: sympy's simplify took 0.5 s at α = π/3 and 3 s with
    α left open, in every model with the shape."""
    s, c = sp.sin(alpha), sp.cos(alpha)
    area = sp.Dummy("A", positive=True)  # A/r² = α − sin α cos α, kept whole until the end
    xx = r**2 * (alpha - s * c - sp.Rational(2, 3) * s**3 * c) / (4 * area)
    rr = r**2 * (alpha - s * c**3 - s**3 * c / 3) / (2 * area)
    yy = rr - xx
    d = sp.Matrix([0, 2 * r * s**3 / (3 * area), 0])
    J_O = sp.diag(m * (yy + h**2 / 12), m * (xx + h**2 / 12), m * rr)
    at = {area: sp.together(alpha - s * c)}
    return MassProperties(m, d.xreplace(at), (J_O - parallel_axis(m, d)).applyfunc(lambda J: _over_area(J, at)))


def _over_area(J: sp.Expr, at: dict) -> sp.Expr:
    """A moment over one denominator, the area's power in it kept as a power (π/3:
    (4π − 3√3)², not a cubic in π expanded), its numerator expanded."""
    numerator, denominator = sp.fraction(sp.together(J))
    numerator, more = sp.fraction(sp.together(sp.expand(numerator.xreplace(at))))
    return sp.factor_terms(numerator) / (more * denominator.xreplace(at))


def _tidy_pi(x: sp.Expr) -> sp.Expr:
    """m r² (9π² − 64)/(36π²), not m r² (3π − 8)(3π + 8)/(36π²)."""
    return sp.factor_terms(sp.together(sp.expand(x)))


_PART_SHAPES = (Shape.HALF_DISK, Shape.HALF_RING, Shape.QUARTER_DISK, Shape.HEMISPHERICAL_SHELL)


def _moments(shape: Shape, m: sp.Expr, d: dict[str, sp.Expr]) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """Principal moments (J_x, J_y, J_z) about the centre of mass, in the shape's axes."""
    r, h = d.get("radius"), d.get("height")
    if shape is Shape.PARTICLE:
        return (sp.Integer(0),) * 3
    if shape is Shape.ROD:  # slender, along x
        L = d["length"]
        return sp.Integer(0), m * L**2 / 12, m * L**2 / 12
    if shape is Shape.RING:  # thin hoop in the xy-plane
        return m * r**2 / 2, m * r**2 / 2, m * r**2
    if shape is Shape.DISK:  # uniform thin disk in the xy-plane
        return m * r**2 / 4, m * r**2 / 4, m * r**2 / 2
    if shape is Shape.CYLINDRICAL_SHELL:  # thin open shell: a stack of rings (seed problem 4)
        return (m * r**2 / 2 + m * h**2 / 12,) * 2 + (m * r**2,)
    if shape is Shape.CYLINDER:  # solid: a stack of disks
        return (m * (3 * r**2 + h**2) / 12,) * 2 + (m * r**2 / 2,)
    if shape is Shape.TUBE:  # thick-walled: cylinder of radius b minus cylinder of radius a
        a, b = d["inner_radius"], d["outer_radius"]
        return (m * (3 * (a**2 + b**2) + h**2) / 12,) * 2 + (m * (a**2 + b**2) / 2,)
    if shape is Shape.SPHERICAL_SHELL:
        return (2 * m * r**2 / 3,) * 3
    if shape is Shape.SPHERE:
        return (2 * m * r**2 / 5,) * 3
    if shape is Shape.HEMISPHERE:  # about its centre of mass, 3r/8 from the flat face
        return (83 * m * r**2 / 320,) * 2 + (2 * m * r**2 / 5,)
    if shape is Shape.CONE:  # about its centre of mass, h/4 above the base
        return (3 * m * r**2 / 20 + 3 * m * h**2 / 80,) * 2 + (3 * m * r**2 / 10,)
    if shape is Shape.BOX:
        a, b, c = d["width"], d["depth"], d["height"]
        return m * (b**2 + c**2) / 12, m * (a**2 + c**2) / 12, m * (a**2 + b**2) / 12
    if shape is Shape.PLATE:  # a (x) by b (y)
        a, b = d["width"], d["height"]
        return m * b**2 / 12, m * a**2 / 12, m * (a**2 + b**2) / 12
    raise ValueError(f"no inertia formula for {shape}")  # pragma: no cover


def _triangle(m: sp.Expr, d: dict[str, sp.Expr]) -> sp.Matrix:
    """A triangular lamina: with vertices vᵢ measured from the centroid, its second
    moment is S = ∫ r rᵀ dm = (m/12) Σ vᵢ vᵢᵀ, and J = tr(S) 1 − S."""
    b, h, a = d["base"], d["height"], d["apex"]
    centroid = sp.Matrix([(b + a) / 3, h / 3, 0])
    vertices = [sp.Matrix([0, 0, 0]), sp.Matrix([b, 0, 0]), sp.Matrix([a, h, 0])]
    S = sum(((v - centroid) * (v - centroid).T for v in vertices), sp.zeros(3, 3)) * m / 12
    return (S.trace() * sp.eye(3) - S).applyfunc(sp.factor)


def rotation_to(axis: sp.Matrix, own: sp.Matrix) -> sp.Matrix:
    """The rotation taking the unit vector ``own`` to the direction of ``axis``
    (Rodrigues, about own × axis; a half turn about x or y when they are opposite)."""
    d = axis / sp.sqrt(axis.dot(axis))
    d = d.applyfunc(sp.radsimp)
    c = own.dot(d)
    if c == 1:
        return sp.eye(3)
    if c == -1:
        flip = sp.Matrix([0, 1, 0]) if own[2] != 0 else sp.Matrix([0, 0, 1])
        return 2 * flip * flip.T - sp.eye(3)
    k = own.cross(d)
    K = sp.Matrix([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return (sp.eye(3) + K + K * K / (1 + c)).applyfunc(sp.radsimp)


def body_properties(shape: Shape, m: sp.Expr, dims: dict[str, sp.Expr], axis: sp.Matrix) -> MassProperties:
    """Mass properties in body axes, with the shape's own axis along ``axis``:
    J_body = Q J_own Qᵀ and centre_body = Q centre_own."""
    own = own_properties(shape, m, dims)
    Q = rotation_to(axis, OWN_AXIS.get(shape, _Z))
    return MassProperties(m, Q * own.centre, (Q * own.inertia * Q.T).applyfunc(sp.expand))


def parallel_axis(m: sp.Expr, d: sp.Matrix) -> sp.Matrix:
    """The shift of an inertia tensor by d (Steiner): m (|d|² 1 − d dᵀ)."""
    return m * (d.dot(d) * sp.eye(3) - d * d.T)


def combine(parts: list[tuple[MassProperties, sp.Matrix]]) -> MassProperties:
    """A composite body from parts (properties, position of each centre of mass);
    a hole is a part of negative mass. J_C = Σ [J_i + m_i (|d_i|² 1 − d_i d_iᵀ)],
    d_i = c_i − C, about the composite's centre of mass C = Σ m_i c_i / Σ m_i."""
    mass = sum((p.mass for p, _ in parts), sp.Integer(0))
    centre = sum((p.mass * c for p, c in parts), sp.zeros(3, 1)) / mass
    centre = centre.applyfunc(sp.factor)
    J = sum((p.inertia + parallel_axis(p.mass, c - centre) for p, c in parts), sp.zeros(3, 3))
    return MassProperties(sp.factor(mass), centre, J.applyfunc(sp.factor))


def explicit_inertia(entries: list[sp.Expr]) -> sp.Matrix:
    """J_G from a problem file: J (planar, about z), [J1, J2, J3], or 3x3 rows."""
    if len(entries) == 1:
        return sp.diag(0, 0, entries[0])
    if len(entries) == 3:
        return sp.diag(*entries)
    return sp.Matrix(3, 3, entries)
