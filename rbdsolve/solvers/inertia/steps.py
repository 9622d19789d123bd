"""The worked solution of an inertia question: J_G from the table or from the parts,
the parallel axis theorem, a change of axes, det(λ1 − J) = 0 and each principal moment
with its unit axis; and the numeric route's tensor and eigenpairs."""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.arrange import descending, scaled_matrix
from rbdsolve.form.display import Label, Relation, Scaled, Terms
from rbdsolve.form.factor import factored
from rbdsolve.form.printers import to_unicode
from rbdsolve.form.tidy import tidy, tidy_fraction
from rbdsolve.model.build import Model, RigidBody, part_properties
from rbdsolve.model.inertia import parallel_axis
from rbdsolve.report import steps as st
from rbdsolve.solvers.routes.labels import labels_for



CONVENTION = ("Products of inertia are the tensor's off-diagonal entries, J_xy = −∫ x y dm "
              "(the SG2150 convention).")


def _show(name: str, J: sp.Matrix, symbols: set) -> Relation:
    return Relation(sp.Symbol(name), scaled_matrix(J, symbols))


def _centre_steps(body: RigidBody, model: Model, symbols: set, at: dict | None = None) -> list[st.Step]:
    """J_G from the shape table (one part), or from the parts by the parallel axis
    theorem (a composite body); ``at``: the coordinates' values asked about."""
    parts = body.source.parts
    if len(parts) == 1 and not parts[0].hole:
        part = parts[0]
        what = f"a {part.shape.value.replace('_', ' ')}" if part.shape else "the given inertia"
        return [st.definition(f"{body.name}: J about its centre of mass G, from the table for {what} "
                              "(body axes):", _show("J_G", body.inertia, symbols))]
    names = model.symbols.with_points(model.points)
    props = [part_properties(p, names) for p in parts]
    centre = body.rotation.T * (body.position - names.vector(body.source.at).xreplace(at or {}))
    steps = [st.definition(
        f"{body.name} is made of {len(parts)} parts (holes count with negative mass); its mass "
        "and centre of mass from its origin:",
        Relation(labels_for(model, "total_mass").symbol("total_mass"), tidy(body.mass)),
        Relation(sp.Symbol("r_G"), sp.ImmutableMatrix(centre.applyfunc(tidy)).T),
    )]
    for part, p in zip(parts, props):
        d = (p.centre - centre).applyfunc(tidy)
        label = part.name if not part.hole or "hole" in part.name else f"{part.name} (a hole)"
        steps.append(st.equation(
            f"{label}: J about its own centre, then shifted by d = r_{part.name} − r_G:",
            _show(f"J_{part.name}", p.inertia, symbols),
            Relation(sp.Symbol("d"), sp.ImmutableMatrix(d).T),
            _show(f"J_{part.name},G", (p.inertia + parallel_axis(p.mass, d)).applyfunc(tidy), symbols),
        ))
    steps.append(st.result("Summing the parts:", _show("J_G", body.inertia, symbols)))
    return steps


def _sum(a: sp.Matrix, b: sp.Matrix, symbols: set):
    return Terms((scaled_matrix(a, symbols), scaled_matrix(b, symbols)))


def _unit_display(direction: sp.Matrix):
    """1/√(290 − 2√145) (0, 12, √145 − 1): a unit vector as its direction over its length."""
    square = direction.dot(direction)
    # sin² + cos² = 1 for an axis that turns; surds as they expand (1/√(290 − 2√145))
    length = sp.sqrt(tidy_fraction(square) if direction.atoms(sp.Function) else sp.expand(square))
    vector = sp.ImmutableMatrix([list(direction)])
    return vector if length == 1 else Scaled(1 / length, vector)


def _cubic(poly: sp.Poly):
    return descending(poly, sp.Symbol("kappa"))


def scene_axes_step(J_G: sp.Matrix, symbols: set) -> st.Step:
    return st.equation("In scene axes, J_G = R J_G,body Rᵀ:", _show("J_G", J_G, symbols))


def shift_steps(label: str, d: sp.Matrix, J_G: sp.Matrix, term: sp.Matrix, J: sp.Matrix,
                symbols: set, mass: sp.Expr) -> list[st.Step]:
    """J_P = J_G + m (|d|² 1 − d dᵀ), d = r_G − r_P, as the exam writes it, m the body's
    own mass as its steps name it (M for a body of parts, M = 3 m: a bare m would read as
    the problem's parameter m)."""
    m, tex = to_unicode(mass), sp.latex(mass)
    m, tex = (f"({m})", rf"\left({tex}\right)") if isinstance(mass, sp.Add) else (m, tex)
    steiner = Label(f"{m} (|d|² 1 − d dᵀ)", tex + r"\,(|d|^2 \mathbf{1} - d\,d^{T})")
    return [
        st.given(f"The centre of mass G relative to {label}:", Relation(sp.Symbol("d"), sp.ImmutableMatrix(d).T)),
        st.equation(f"Parallel axis theorem, J_{label} = J_G + {m} (|d|² 1 − d dᵀ), with",
                    Relation(steiner, scaled_matrix(term, symbols))),
        st.result(f"About {label}:", Relation(sp.Symbol(f"J_{label}"), _sum(J_G, term, symbols),
                                               more=(scaled_matrix(J, symbols),))),
    ]


def frame_step(A: sp.Matrix, J: sp.Matrix, symbols: set) -> st.Step:
    return st.equation("In the frame with unit vectors (rows of A), J' = A J Aᵀ:",
                       Relation(sp.Symbol("A"), sp.ImmutableMatrix(A)), _show("J'", J, symbols))


def characteristic_step(scale: sp.Expr, poly: sp.Poly) -> st.Step:
    return st.equation("Principal moments: det(λ1 − J) = 0; with λ = J₀ κ, J₀ the common scale:",
                       Relation(sp.Symbol("J_0"), scale), Relation(_cubic(poly), sp.Integer(0)))


def numeric_characteristic_step(scale: sp.Expr, J_hat) -> st.Step:
    """det(κ1 − Ĵ) = κ³ − (tr Ĵ) κ² + … in numbers (numpy.poly of Ĵ's floats): the
    cubic of a tensor whose exact coefficients no reader would follow."""
    import numpy as np

    kappa = sp.Symbol("kappa")
    monic, *rest = np.poly(J_hat)  # 1.0: printed κ³, not 1 κ³
    cubic = sp.Poly([sp.Integer(round(monic)), *(sp.Float(c, 15) for c in rest)], kappa, domain="EX")
    return st.equation("Principal moments: det(λ1 − J) = 0; with λ = J₀ κ, J₀ the common scale, in numbers "
                       "(its exact coefficients are long rational functions of π):",
                       Relation(sp.Symbol("J_0"), scale), Relation(descending(cubic), sp.Integer(0)))


def decoupled_step(axis: str) -> st.Step:
    """An axis no product of inertia couples, the other two from the 2×2 block."""
    x, y = (n for n in "xyz" if n != axis)
    return st.note(f"No product of inertia couples the {axis} axis (J_{x}{axis} = J_{y}{axis} = 0): it is a principal "
                   f"axis, with J_{axis}{axis}; the other two moments are the block [[a, c], [c, b]] = [[J_{x}{x}, "
                   f"J_{x}{y}], [J_{x}{y}, J_{y}{y}]]'s, λ = (a + b)/2 ± √(((a − b)/2)² + c²).")


def diagonal_step() -> st.Step:
    """A diagonal tensor: no characteristic equation, the moments are read off."""
    return st.note("The tensor is diagonal in these axes: they are principal axes, and the principal "
                   "moments are its diagonal entries.")


def principal_steps(moments: list[sp.Expr], axes: list[sp.Matrix], repeated: list[sp.Expr]) -> list[st.Step]:
    """Each moment with its unit axis, then a note on each repeated moment."""
    steps = []
    for i, (moment, axis) in enumerate(zip(moments, axes), start=1):
        steps.append(st.result(f"Principal moment {i} and its axis (a unit vector):",
                               Relation(sp.Symbol(f"J_{i}"), factored(moment)),
                               Relation(sp.Symbol(f"e_{i}"), _unit_display(axis))))
    for value in repeated:
        where = ("every axis is a principal axis" if moments.count(value) == 3 else
                 "every axis in the plane of its two axes above is a principal axis")
        steps.append(st.note(f"A repeated moment: {where},", Relation(sp.Symbol("J"), value)))
    return steps


def numeric_principal_steps(moments, axes) -> list[st.Step]:
    """Moments and axes found by numpy for a tensor with no compact closed form."""
    return [st.result(f"Principal moment {i} and its axis (numeric):",
                      Relation(sp.Symbol(f"J_{i}"), moment),
                      Relation(sp.Symbol(f"e_{i}"), sp.ImmutableMatrix([list(axis)])))
            for i, (moment, axis) in enumerate(zip(moments, axes), start=1)]


def numeric_steps(J, moments, axes) -> tuple[st.Step, ...]:
    """The numeric route: the tensor in floats, then its eigenpairs."""
    return (
        st.equation("The inertia tensor in numbers (assembled exactly, rounded once):",
                    Relation(sp.Symbol("J"), sp.ImmutableMatrix(J).applyfunc(lambda x: sp.Float(x, 15)))),
        st.result("Principal moments and axes, J e = λ e (numpy.linalg.eigh):",
                  *[Relation(sp.Symbol(f"J_{k + 1}"), sp.Float(m, 15), more=()) for k, m in enumerate(moments)],
                  *[Relation(sp.Symbol(f"e_{k + 1}"), sp.ImmutableMatrix([[sp.Float(x, 15) for x in axes[:, k]]]))
                    for k in range(3)]),
    )


def axis_steps(label: str, e: sp.Matrix, J_axis: sp.Expr) -> list[st.Step]:
    """The moment about one axis through the point, J = eᵀ J_P e."""
    return [st.result(f"About the axis through {label} along the unit vector e, J = eᵀ J_{label} e:",
                      Relation(sp.Symbol("e"), _unit_display(e)), Relation(sp.Symbol("J_e"), J_axis))]


def normal_step(label: str, body: RigidBody, J_G: sp.Matrix, about: sp.Matrix, J_axis: sp.Expr) -> st.Step:
    """The moment about the axis through the point normal to the plane of the motion,
    J = J_G,zz + m |G{label}|² (Steiner, in the plane): the exam's "moment of inertia about
    the contact point", a function of the coordinates."""
    d = (body.position - about).applyfunc(tidy)
    distance = tidy(d[0] ** 2 + d[1] ** 2)
    return st.result(f"The moment of inertia about the axis through {label} normal to the plane of the motion (z), "
                     f"J_{label} = J_G + m |G{label}|² (the parallel axis theorem in the plane):",
                     Relation(Label(f"|G{label}|²", rf"|G{label}|^2"), factored(distance)),
                     Relation(Label(f"J_{label},z", f"J_{{{label},z}}"),
                              Terms((tidy(J_G[2, 2]), tidy(body.mass * distance))), more=(factored(J_axis),)))


def configuration_step(at: dict, model: Model) -> st.Step:
    """The configuration asked about, put in before anything else."""
    return st.given("At the configuration asked about (put in first):",
                    *[Relation(model.readable(q), value) for q, value in at.items()])
