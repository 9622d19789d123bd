"""Inertia tensors, the parallel axis theorem, principal moments and axes.

About the centre of mass G, a body made of parts i (holes: negative mass) has

    J_G = Σ_i [J_i + m_i (|d_i|² 1 − d_i d_iᵀ)],   d_i = r_i − r_G,

and about any point P (Steiner, the parallel axis theorem)

    J_P = J_G + m (|d|² 1 − d dᵀ),   d = r_G − r_P.

In a rotated frame whose unit vectors are the rows of A, J' = A J Aᵀ. Principal moments
are the roots of det(J − λ1) = 0 (closed forms: a common scale m r² is pulled out and
the cubic solved over the rationals, in trigonometric form when it has three real
irrational roots); principal axes are unit vectors spanning each null space of J − λ1,
an orthonormal basis of the plane when a moment is repeated. Products of inertia are
the tensor's off-diagonal entries, J_xy = −∫ x y dm, as in SG2150.
"""

from __future__ import annotations

from dataclasses import replace

import sympy as sp

from rbdsolve.form.printers import to_unicode
from rbdsolve.errors import UnsolvedError
from rbdsolve.form.arrange import common_scale, scaled_matrix
from rbdsolve.form.display import Relation
from rbdsolve.form.stand_ins import stand_ins
from rbdsolve.form.tidy import tidy, tidy_fraction
from rbdsolve.model.build import Model, RigidBody
from rbdsolve.model.inertia import parallel_axis
from rbdsolve.problem.options import InertiaOptions
from rbdsolve.problem.schema import Question
from rbdsolve.report import steps as st
from rbdsolve.report.steps import Route, Solution
from rbdsolve.solvers.inertia.answers import InertiaAnswers, Principal
from rbdsolve.solvers.inertia.configuration import about_point, at_configuration, substitution
from rbdsolve.solvers.inertia.named import point_label
from rbdsolve.solvers.inertia.steps import (
    CONVENTION,
    _centre_steps,
    axis_steps,
    configuration_step,
    characteristic_step,
    decoupled_step,
    diagonal_step,
    frame_step,
    normal_step,
    numeric_characteristic_step,
    numeric_principal_steps,
    principal_steps,
    scene_axes_step,
    shift_steps,
)
from rbdsolve.solvers.routes.labels import labels_for
from rbdsolve.solvers.routes.options import Options
from rbdsolve.model.values.values import sample
from rbdsolve.form.zero import simplifies_to_zero

LAMBDA = sp.Symbol("lamda")  # sympy's spelling: "lambda" is a Python keyword


def solve(question: Question, model: Model, options: Options) -> Solution:
    opts: InertiaOptions = question.options
    at = substitution(opts, model)
    model = at_configuration(model, at)
    body = next(b for b in model.bodies if b.name == opts.body)
    symbols = set(model.symbols.parameters.values())
    steps: list[st.Step] = [configuration_step(at, model)] if at else []
    steps += _centre_steps(body, model, symbols, at)
    J_G = body.inertia_in_scene().applyfunc(tidy)
    if body.rotation != sp.eye(3) and (J_G - body.inertia).applyfunc(tidy_fraction) != sp.zeros(3, 3):
        steps.append(scene_axes_step(J_G, symbols))  # not when turning leaves it as it is (a cube)
    view = body.rotation  # body axes -> the axes J is written in
    J, about, label = J_G, None, "G"
    if opts.about is not None:
        about = about_point(opts, model, at)
        label = point_label(opts)
        J, shift_steps = _shift(body, J_G, about, label, symbols, _mass_shown(body, model))
        steps += shift_steps
    e, J_axis = axis_moment(opts, model, J)
    if e is not None:
        steps += axis_steps(label, e, J_axis)
    elif about is not None and in_plane(opts, model, body, about):
        e, J_axis = sp.Matrix([0, 0, 1]), tidy(J[2, 2])
        steps.append(normal_step(label, body, J_G, about, J_axis))
    if opts.axes is not None:
        A = frame_matrix(opts, model)
        J_G, J = (A * J_G * A.T).applyfunc(tidy), (A * J * A.T).applyfunc(tidy)
        steps.append(frame_step(A, J, symbols))
        view = A * view
    found = _principal_turned(J, view, symbols, model) or principal(J, symbols, model)
    steps += [*found.steps, st.note(CONVENTION)]
    answers = InertiaAnswers(
        body.mass, tuple(tidy(x) for x in body.position),
        tuple(about) if about is not None else None,
        sp.ImmutableMatrix(J_G), sp.ImmutableMatrix(J), found.moments, found.axes, found.repeated,
        {model.state.names[model.q.index(q)]: v for q, v in at.items()} or None,
        tuple(_unit(e)) if e is not None else None, J_axis,
    )
    return Solution("inertia", Route.EXACT, _to_time(answers, model), tuple(steps),
                    warnings=(*found.warnings, *_undefined_axes(found, model)))


def axis_moment(opts: InertiaOptions, model: Model, J: sp.Matrix) -> tuple[sp.Matrix | None, sp.Expr | None]:
    """e = n/|n| for the asked direction n (scene axes) and J_e = eᵀ J e, J about the
    asked point in scene axes: the moment of inertia about that axis through the point."""
    if opts.axis is None:
        return None, None
    n = model.symbols.with_points(model.points).vector(opts.axis).applyfunc(tidy)
    length = sp.sqrt(tidy(sp.expand(n.dot(n))))
    return n, tidy(sp.expand((n.T * J * n)[0, 0] / length**2))


def in_plane(opts: InertiaOptions, model: Model, body: RigidBody, about: sp.Matrix) -> bool:
    """Is the question planar, so that "the moment of inertia about C" means the one about
    the axis through C normal to the plane (z)? A scene with coordinates, no 'axis' asked,
    the body moving in the xy-plane (turning about z only) and the point in a plane
    z = constant (a contact point, a fixed centre)."""
    if opts.axis is not None or not model.q or body.turns_3d or body.given_angular_velocity is not None:
        return False
    q = set(model.q)
    return not (sp.sympify(body.position[2]).free_symbols | sp.sympify(about[2]).free_symbols) & q


def _undefined_axes(found: Principal, model: Model) -> tuple[str, ...]:
    """A warning where a principal axis is a formula in the coordinates that divides by
    something that vanishes at some configurations (sin β, cos α): there it is
    undefined, and the axis must be found at that configuration itself."""
    q = set(model.q)
    if not any(sp.sympify(x).free_symbols & q for axis in found.axes for x in axis):
        return ()  # no coordinate in the axes (asked at a configuration): no divisor to factor out
    divisors = {factor for axis in found.axes for x in axis
                for factor in sp.Mul.make_args(sp.factor(sp.fraction(sp.together(x))[1]))
                if factor.free_symbols & q}
    if not divisors:
        return ()
    shown = ", ".join(sorted(to_unicode(model.readable(d)) for d in divisors))
    return (f"the principal axes depend on the configuration and divide by {shown}: they are undefined "
            "where that is zero; ask at that configuration (values for the coordinates) instead",)


def _mass_shown(body: RigidBody, model: Model) -> sp.Expr:
    """The body's mass as its steps name it: M (the label the sum of its parts was given,
    M = 3 m) for a body of parts, else its mass (m)."""
    parts = body.source.parts
    if len(parts) == 1 and not parts[0].hole:
        return body.mass
    return labels_for(model, "total_mass").symbol("total_mass")


def _shift(body: RigidBody, J_G: sp.Matrix, P: sp.Matrix, label: str, symbols: set, mass: sp.Expr):
    """J_P = J_G + m (|d|² 1 − d dᵀ), d = r_G − r_P."""
    d = (body.position - P).applyfunc(tidy)
    term = parallel_axis(body.mass, d).applyfunc(tidy)
    J = (J_G + term).applyfunc(tidy)
    return J, shift_steps(label, d, J_G, term, J, symbols, mass)


def frame_matrix(opts: InertiaOptions, model: Model) -> sp.Matrix:
    """A: the rows are the asked unit vectors in scene axes, checked orthonormal."""
    names = model.symbols.with_points(model.points)
    rows = [names.vector(e).applyfunc(tidy) for e in opts.axes]
    A = sp.Matrix.hstack(*rows).T
    if not all(simplifies_to_zero(x) for x in A * A.T - sp.eye(3)):
        raise UnsolvedError(f"{opts.axes[0].loc}: the axes must be orthonormal unit vectors (A Aᵀ = 1)")
    return A


MAX_ROOT_OPS = 40  # a closed form longer than this is no help to a reader


def principal(J: sp.Matrix, symbols: set, model: Model) -> Principal:
    """Principal moments (ascending) and unit principal axes of a symmetric tensor:
    closed forms when they are compact; for a tensor that is numeric apart from its
    scale, numpy's symmetric eigensolver otherwise (and a warning says so). Numbers
    with π in them go that way at once, unless an axis decouples (``_in_numbers``)."""
    scale = common_scale(list(J), symbols)
    scale = -scale if scale.could_extract_minus_sign() else scale
    J_hat = (J / scale).applyfunc(tidy)
    if _beyond_radicals(J_hat) and not J_hat.is_diagonal():
        return _in_numbers(J_hat, scale, model)
    if J_hat.is_diagonal():  # its moments are its entries: no cubic to build (of π and √3, seconds)
        poly, steps = None, [diagonal_step()]
    else:
        poly = sp.Poly((LAMBDA * sp.eye(3) - J_hat).det(method="berkowitz"), LAMBDA)
        poly = sp.Poly(sum(tidy(c) * LAMBDA**k for (k,), c in poly.terms()), LAMBDA)  # sin² + cos² = 1
        steps = [characteristic_step(scale, poly)]
    turning = _turning_plane(J_hat, scale, model)
    if turning is not None:
        return replace(turning, steps=(*steps, *turning.steps))
    found = _closed_form(J_hat, poly)
    if found is None:
        moving = [n for n, q in zip(model.state.names, model.q) if J_hat.has(q)]
        if moving:
            raise UnsolvedError("the principal moments have no compact closed form at every configuration; ask at "
                                f"one, 'at: {{{', '.join(f'{n}: …' for n in moving)}}}' (the tensor itself, and the "
                                "moment about an 'axis', are exact at every configuration)")
        in_plane = _decoupled_plane(J_hat, scale, model) if J_hat.free_symbols else None
        if in_plane is not None:  # a flat body, its symbolic sizes: one axis and a quadratic
            return replace(in_plane, steps=(*steps, *in_plane.steps))
        if J_hat.free_symbols:
            raise UnsolvedError("the principal moments have no compact closed form here; give "
                                "parameter values for numeric ones")
        return _numeric_principal(J_hat, scale, steps)
    return _from_roots(J_hat, scale, found, steps, model)


def _from_roots(J_hat: sp.Matrix, scale: sp.Expr, found: dict[sp.Expr, int], steps: list[st.Step],
                model: Model) -> Principal:
    """Each moment J₀ κ, ascending, with its unit axes from the null space of Ĵ − κ1."""
    roots = sorted(((tidy(r), k) for r, k in found.items()), key=lambda rk: _size(rk[0], model))
    moments, axes, repeated = [], [], []
    for root, multiplicity in roots:
        moments += [tidy(scale * root)] * multiplicity
        axes += _unit_axes(J_hat, root, multiplicity)
        if multiplicity > 1:
            repeated.append(tidy(scale * root))
    steps += principal_steps(moments, axes, repeated)
    return Principal(tuple(moments), tuple(_unit(d) for d in axes), tuple(repeated), tuple(steps), ())


def _turning_plane(J_hat: sp.Matrix, scale: sp.Expr, model: Model) -> Principal | None:
    """The principal moments and axes of a tensor that moves with the coordinates and has
    an axis e_k no product couples (a body moving in the plane, about a point of it, that
    does not turn with the body: its contact point). e_k is an axis, with J_kk; the other
    two lie in the plane of the block [[a, c], [c, b]],

        λ± = (a + b)/2 ± √(((a − b)/2)² + c²),   e± at the angle α (and α + π/2) from
        the plane's first axis, α = ½ atan2(2c, a − b),

    forms that stay short where the null space of J − λ1 with the root's square root does
    not. None: J does not move, no axis decouples, or the root is no square root of the
    coordinates (a disk circling O: its axes along OG and across it, from the null space)."""
    if not J_hat.free_symbols & set(model.q):
        return None
    block = _plane_block(J_hat)
    if block is None or not any(p.exp == sp.S.Half and p.base.free_symbols & set(model.q)
                                for p in block[3].atoms(sp.Pow)):
        return None  # rational in the coordinates' sines: the null space gives short axes (OG and across)
    return _in_plane(J_hat, scale, model, block)


def _decoupled_plane(J_hat: sp.Matrix, scale: sp.Expr, model: Model) -> Principal | None:
    """``_turning_plane``'s formulas for any tensor with an axis no product couples (a flat
    body: a T of two rods about the end of its crossbar, its sizes symbolic, whose cubic
    has no compact roots but whose block's quadratic has); None where no axis decouples
    or the block is already diagonal (its moments are its entries)."""
    block = _plane_block(J_hat)
    if block is None or J_hat[block[1], block[2]] == 0:
        return None
    return _in_plane(J_hat, scale, model, block)


def _plane_block(J_hat: sp.Matrix) -> tuple[int, int, int, sp.Expr] | None:
    """(k, i, j, √(((a − b)/2)² + c²)): the axis e_k no product couples, the other two,
    and the root of their block [[a, c], [c, b]]; None where no axis decouples."""
    k = _decoupled_axis(J_hat)
    if k is None:
        return None
    i, j = (x for x in range(3) if x != k)
    return k, i, j, sp.sqrt(tidy((J_hat[i, i] - J_hat[j, j]) ** 2 / 4 + J_hat[i, j] ** 2))


def _in_plane(J_hat: sp.Matrix, scale: sp.Expr, model: Model, block: tuple) -> Principal:
    """The moments J_kk and (a + b)/2 ± the block's root, ascending, with their axes e_k
    and e± at α = ½ atan2(2c, a − b) (``_turning_plane``'s formulas), and their steps."""
    k, i, j, root = block
    a, b, c = J_hat[i, i], J_hat[j, j], J_hat[i, j]
    alpha = sp.atan2(tidy(2 * c), tidy(a - b)) / 2
    plus, minus = sp.zeros(3, 1), sp.zeros(3, 1)
    plus[i], plus[j], minus[i], minus[j] = sp.cos(alpha), sp.sin(alpha), -sp.sin(alpha), sp.cos(alpha)
    pairs = [(J_hat[k, k], sp.eye(3)[:, k]), (tidy((a + b) / 2 + root), plus), (tidy((a + b) / 2 - root), minus)]
    pairs.sort(key=lambda p: _size(scale * p[0], model))
    moments = [tidy(scale * m) for m, _ in pairs]
    axes = [axis for _, axis in pairs]
    x, y, z = ("xyz"[n] for n in (i, j, k))
    shown = sp.Symbol("alpha")
    xx, yy, xy = f"J_{x}{x}", f"J_{y}{y}", f"J_{x}{y}"  # (not a, b, c: a body's sizes are often named so)
    note = st.equation(f"No product of inertia couples the {z} axis (J_{x}{z} = J_{y}{z} = 0): it is a "
                       f"principal axis, with J_{z}{z}; the other two lie in the {x}{y}-plane, at the angle α "
                       f"from the {x} axis, λ = ({xx} + {yy})/2 ± √((({xx} − {yy})/2)² + {xy}²) and "
                       f"α = ½ atan2(2 {xy}, {xx} − {yy}):", Relation(shown, alpha))
    steps = (note, *principal_steps(moments, [v.xreplace({alpha: shown}) for v in axes], []))
    return Principal(tuple(moments), tuple(tuple(x) for x in axes), (), steps, ())


def _principal_turned(J: sp.Matrix, Q: sp.Matrix, symbols: set, model: Model) -> Principal | None:
    """The principal moments and axes of a tensor that turns with the coordinates.

    With Q the rotation from body axes to the axes J is written in, J = Q J_b Qᵀ and
    J_b = Qᵀ J Q. When J_b is free of the coordinates (always about G; about a point
    fixed in the body), the moments are J_b's and each axis is Q e_b, e_b an axis of
    J_b: defined at every configuration, where the cofactors of J itself divide by
    sin β or cos α somewhere. None: J does not turn, or J_b still moves (then J is
    treated as it is, and a warning names the configurations where that fails).
    """
    q = set(model.q)
    if not J.free_symbols & q:
        return None
    J_b = (Q.T * J * Q).applyfunc(tidy_fraction)
    if J_b.free_symbols & q:
        return None
    found = principal(J_b, symbols, model)
    axes = [tuple(tidy(x) for x in Q * sp.Matrix(axis)) for axis in found.axes]
    steps = [st.equation("The tensor turns with the body: in body axes, J_b = Qᵀ J Q (Q: body axes to "
                         "these axes) is constant, so the moments are J_b's and each axis is Q e_b:",
                         Relation(sp.Symbol("J_b"), scaled_matrix(J_b, symbols))),
             found.steps[0], *principal_steps(list(found.moments), [sp.Matrix(a) for a in axes],
                                              list(found.repeated))]
    return replace(found, axes=tuple(axes), steps=tuple(steps))


def _closed_form(J_hat: sp.Matrix, poly: sp.Poly | None) -> dict[sp.Expr, int] | None:
    """{root: multiplicity} in closed form, or None when no compact real form is found
    (an irreducible cubic with irrational coefficients gives Cardano's formula in i)."""
    if J_hat.is_diagonal():
        found: dict[sp.Expr, int] = {}
        for i in range(3):
            found[J_hat[i, i]] = found.get(J_hat[i, i], 0) + 1
        return found
    found = _decoupled(J_hat) or sp.roots(poly, LAMBDA, trig=True)
    return found if _compact(found) else None


def _compact(found: dict[sp.Expr, int]) -> bool:
    """Three real roots, each short enough to help a reader."""
    return sum(found.values()) == 3 and not any(r.has(sp.I) or sp.count_ops(r) > MAX_ROOT_OPS for r in found)


def _beyond_radicals(J_hat: sp.Matrix) -> bool:
    """Is Ĵ a matrix of numbers with π (or another number no radical writes: e, sin 1)
    in them? Then its cubic's coefficients are rational functions of π (a segment's
    centroid, 4 r sin³α/(3 (2α − sin 2α)), puts (4π − 3√3)⁵ in a denominator) and,
    unless an axis decouples, Cardano's roots are pages long: decided from the entries
    alone, before the determinant (seconds) and the roots (minutes) are tried."""
    if J_hat.free_symbols:
        return False
    return bool(J_hat.atoms(sp.NumberSymbol)) or any(f.is_number for f in J_hat.atoms(sp.Function))


def _numbers(J_hat: sp.Matrix):
    import numpy as np

    return np.array(J_hat.evalf(20).tolist(), dtype=float)


def _decoupled(J_hat: sp.Matrix) -> dict[sp.Expr, int] | None:
    """The roots of a tensor with an axis that no product of inertia couples (a body
    moving in the xy-plane, about a point of that plane: J_xz = J_yz = 0): J_kk is one,
    and the other two are the 2×2 block's, λ = (a + b)/2 ± √(((a − b)/2)² + c²), where
    the cubic as a whole may have no compact form (a half disk about its contact point)."""
    k = _decoupled_axis(J_hat)
    return None if k is None else _block_roots(J_hat, k)


def _block_roots(J_hat: sp.Matrix, k: int) -> dict[sp.Expr, int]:
    """J_kk and the roots of the 2×2 block left when e_k decouples (sympy's roots)."""
    rest = [i for i in range(3) if i != k]
    quadratic = sp.Poly((LAMBDA * sp.eye(2) - J_hat.extract(rest, rest)).det(), LAMBDA)
    return _merged([(J_hat[k, k], 1), *sp.roots(quadratic, LAMBDA).items()])


def _decoupled_axis(J_hat: sp.Matrix) -> int | None:
    """k with J_ki = 0 for i ≠ k: e_k is a principal axis."""
    return next((k for k in range(3) if all(tidy(J_hat[k, i]) == 0 for i in range(3) if i != k)), None)


def _merged(roots: list[tuple[sp.Expr, int]]) -> dict[sp.Expr, int]:
    """{root: multiplicity}, equal roots (after tidying their difference) merged."""
    found: dict[sp.Expr, int] = {}
    for root, multiplicity in roots:
        same = next((r for r in found if tidy(r - root) == 0), root)
        found[same] = found.get(same, 0) + multiplicity
    return found


def _in_numbers(J_hat: sp.Matrix, scale: sp.Expr, model: Model) -> Principal:
    """The principal moments of a tensor of numbers with π in them. With an axis e_k no
    product couples, J_kk and the 2×2 block's roots, exact where they are compact (a ± |c|
    when a = b, a symmetric body turned about its axis: the quadratic formula would
    square a − b unsimplified, hundreds of operations), the cubic not expanded (its
    coefficients run to pages); otherwise numpy's moments, the cubic written in numbers."""
    k = _decoupled_axis(J_hat)
    if k is not None:
        i, j = (x for x in range(3) if x != k)
        a, b, c = J_hat[i, i], J_hat[j, j], J_hat[i, j]
        if tidy(a - b) == 0:
            found = _merged([(J_hat[k, k], 1), (tidy(a + sp.Abs(c)), 1), (tidy(a - sp.Abs(c)), 1)])
        else:
            found = _block_roots(J_hat, k)
        if _compact(found):
            return _from_roots(J_hat, scale, found, [decoupled_step("xyz"[k])], model)
    return _numeric_principal(J_hat, scale, [numeric_characteristic_step(scale, _numbers(J_hat))])


def _numeric_principal(J_hat: sp.Matrix, scale: sp.Expr, steps: list[st.Step]) -> Principal:
    """numpy.linalg.eigh on Ĵ: ascending moments, orthonormal axes, to about 1e-15."""
    import numpy as np

    values, vectors = np.linalg.eigh(_numbers(J_hat))
    moments = tuple(scale * sp.Float(v, 15) for v in values)
    axes = []
    for k in range(3):
        v = vectors[:, k]
        first = next(x for x in v if abs(x) > 1e-12)
        axes.append(tuple(sp.Float(x if first > 0 else -x, 15) for x in v))
    note = ("No compact closed form for these roots: the principal moments and axes are "
            "numeric (numpy's symmetric eigensolver, relative error about 1e-15).")
    steps += numeric_principal_steps(moments, axes)
    return Principal(moments, tuple(axes), (), tuple(steps), (note,))


def _size(value: sp.Expr, model: Model) -> float:
    return sample(value, model.values).real


def _unit_axes(J_hat: sp.Matrix, root: sp.Expr, multiplicity: int) -> list[sp.Matrix]:
    """Directions spanning the null space of Ĵ − κ1, cleared of denominators, first
    nonzero entry positive: (0, 12, √145 − 1). A repeated moment's plane gets an
    orthogonal pair (Gram–Schmidt). Divide by the length for unit vectors."""
    if multiplicity == 1 and not _surd(root):
        return [_first_positive(_polynomial_direction(_adjugate_column(J_hat, root)))]
    null = (J_hat - root * sp.eye(3)).applyfunc(tidy).nullspace(simplify=True)
    if len(null) != multiplicity:
        raise UnsolvedError(f"could not find the principal axes for the moment {to_unicode(root)}")
    directions: list[sp.Matrix] = []
    for v in null:
        for u in directions:
            v = v - (u.dot(v) / u.dot(u)) * u
        first = next(x for x in v if tidy(x) != 0)
        directions.append(_first_positive(_polynomial_direction(_integral((v / first).applyfunc(_rationalized)))))
    return directions


def _rationalized(x: sp.Expr) -> sp.Expr:
    """Tidied, and a surd's denominator made rational: (2√113 + 30)/(31 + 3√113) =
    (√113 − 9)/2, so that the direction clears to (4, 4, √113 − 9)."""
    x = tidy(x)
    return sp.radsimp(x) if _surd(x) and not x.is_Rational else x


def _unit(direction: sp.Matrix) -> tuple[sp.Expr, ...]:
    """direction/|direction|; tidied when it is made of surds (else left as it is: a
    trigonometric cubic root does not shorten, and expanding it is slow)."""
    length = sp.sqrt(tidy_fraction(direction.dot(direction)) if direction.free_symbols
                     else sp.expand(direction.dot(direction)))
    unit = [x / length for x in direction]
    return tuple(tidy(x) if _surd(x) else x for x in unit)


def _surd(value: sp.Expr) -> bool:
    """Rational, or built from rationals with square roots only (nullspace stays fast)."""
    return all(p.exp.is_Rational and p.exp.q in (1, 2) for p in value.atoms(sp.Pow)) and not value.atoms(
        sp.Function)


def _adjugate_column(J_hat: sp.Matrix, root: sp.Expr) -> sp.Matrix:
    """For a simple root κ, adj(κ1 − Ĵ) has rank one: its largest column is the axis
    (the cofactor method; no symbolic elimination on the cubic's trigonometric roots)."""
    kappa = sp.Dummy("kappa")
    adjugate = (kappa * sp.eye(3) - J_hat).adjugate().applyfunc(sp.expand)
    columns = [adjugate[:, j].xreplace({kappa: root}) for j in range(3)]
    size = [sum(abs(complex(sp.N(x.xreplace({s: 1 for s in x.free_symbols})))) for x in c) for c in columns]
    return columns[max(range(3), key=lambda j: size[j])].applyfunc(sp.expand)


def _polynomial_direction(v: sp.Matrix) -> sp.Matrix:
    """The same direction with no denominator that holds a coordinate: (1, tan θ, 0)
    becomes (cos θ, sin θ, 0), defined at every θ (sin and cos taken as symbols, the
    entries multiplied by their common denominator and divided by their common
    factor). Directions free of functions are left as they are."""
    if not v.atoms(sp.Function):
        return v
    table, back = stand_ins(v.atoms(sp.Function))
    return sp.Matrix([tidy(e.xreplace(back)) for e in _cleared([x.xreplace(table) for x in v])])


def _cleared(entries: list[sp.Expr]) -> list[sp.Expr]:
    """The entries times their common denominator, divided by their common factor: the
    same direction with no denominator."""
    parts = [sp.fraction(sp.cancel(sp.together(x))) for x in entries]
    denominator = sp.lcm([den for _, den in parts])
    entries = [sp.cancel(num * denominator / den) for num, den in parts]
    nonzero = [e for e in entries if e != 0]
    common = sp.gcd(nonzero) if nonzero else 1
    return [sp.cancel(e / common) for e in entries]


def _integral(v: sp.Matrix) -> sp.Matrix:
    """The direction of v with its rational denominators cleared: (0, 1, (√145 − 1)/12)
    becomes (0, 12, √145 − 1); and its denominators in the parameters, the entries then
    divided by their common factor: (126, 42 √3, 56 √3 h/b − 56 √3 b/h + 28 √3 √P/(b h))
    becomes (9 b h, 3 √3 b h, 2 √3 (2 h² − 2 b² + √P))."""
    scale = sp.lcm([r.q for x in v for r in x.atoms(sp.Rational)] or [1])
    v = (v * scale).applyfunc(sp.expand)
    if not v.free_symbols or v.atoms(sp.Function):
        return v
    return sp.Matrix([sp.expand(e) for e in _cleared(list(v))])


def _first_positive(v: sp.Matrix) -> sp.Matrix:
    """The sign convention: the first nonzero component is positive."""
    first = next(x for x in v if x != 0)
    return -v if first.could_extract_minus_sign() else v


def _to_time(answers: InertiaAnswers, model: Model) -> InertiaAnswers:
    """Answers that depend on the configuration show coordinates as functions of t."""
    if not model.q:
        return answers
    convert = model.to_time
    return InertiaAnswers(
        convert(answers.mass), tuple(convert(x) for x in answers.centre),
        tuple(convert(x) for x in answers.about) if answers.about is not None else None,
        convert(answers.J_G), convert(answers.J),
        tuple(convert(x) for x in answers.principal_moments),
        tuple(tuple(convert(x) for x in v) for v in answers.principal_axes),
        tuple(convert(x) for x in answers.repeated),
        answers.at, answers.axis, convert(answers.J_axis) if answers.J_axis is not None else None,
    )
