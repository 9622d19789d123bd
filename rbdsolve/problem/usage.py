"""Which declared parameters the problem uses: a parameter no expression of the scene or
of a question names changes no answer, and is most likely a line left out (a pendulum
whose ``gravity:`` was forgotten has g declared and used nowhere: V = 0, a "neutral"
equilibrium, λ = 0). The solvers warn of it (``model/summary/summary.py``).

Used means named by an expression anywhere but ``parameters:`` themselves, ``values:``
(a value uses nothing) and ``assumptions:`` (a bound on a parameter that nothing else
holds decides nothing): points, bodies, springs, gravity, frames, prescribed motions,
contacts, coordinate ranges and every question's options; and `Omega` where a steady spin's
answers are written in it.
"""

from __future__ import annotations

import dataclasses

from rbdsolve.problem import expr as ex
from rbdsolve.problem.instants import Instant, StateValue
from rbdsolve.problem.quantities.dimensions import lone_parameter, product_names, sum_terms
from rbdsolve.problem.schema import Parameter, Problem, QuestionKind

NOT_USES = frozenset({"parameters", "values", "ranges", "assumptions", "dimensions"})


def unused_parameters(problem: Problem) -> tuple[Parameter, ...]:
    """The declared parameters no expression of the scene or of a question names, in
    the file's order."""
    used: set[str] = set()
    for field in dataclasses.fields(problem):
        if field.name not in NOT_USES:
            _collect(getattr(problem, field.name), used)
    if any(q.kind is QuestionKind.STEADY_SPIN for q in problem.questions):
        used.add(SPIN_SIZE)
    return tuple(p for p in problem.parameters if p.name not in used)


SPIN_SIZE = "Omega"  # a steady spin's size Ω in its answers (solvers/steady_spin), named by no expression


def _collect(value: object, used: set[str]) -> None:
    """Every name in the expressions held by ``value`` (a dataclass of the schema, a
    tuple of them, an expression), added to ``used``."""
    if isinstance(value, ex.Expr):
        used.update(value.names())
    elif isinstance(value, (tuple, list)):
        for item in value:
            _collect(item, used)
    elif dataclasses.is_dataclass(value) and not isinstance(value, type):
        for field in dataclasses.fields(value):
            _collect(getattr(value, field.name), used)


TRIG = frozenset({"sin", "cos", "tan", "cot", "sec", "csc"})

ANGLE_FIELDS = frozenset({"angle", "half_angle", "rest"})  # a body's or line's turn, a shape's, a spring's rest


def angle_terms(problem: Problem) -> frozenset[str]:
    """The parameters that are angles by how the scene writes them: a term of a sine's
    (cosine's, tangent's) argument, up to a number (an incline's sin(alpha),
    cos(theta - alpha), sin(2*beta); not Omega in sin(Omega*t)), or of an ``angle``,
    ``half_angle`` or ``rest``."""
    names = frozenset(p.name for p in problem.parameters)
    sections = [getattr(problem, f.name) for f in dataclasses.fields(problem) if f.name not in NOT_USES]
    return frozenset(p for kind, tree, _ in _angles(sections) if kind == "angle" for term in sum_terms(tree)
                     if (p := lone_parameter(term, names, False)) is not None)


def state_parameters(problem: Problem) -> dict[str, frozenset[str]]:
    """The parameters that stand alone as a coordinate's value in a question's state
    (``from_rest: {theta: theta0}``): each -> those coordinates."""
    found: dict[str, set[str]] = {}
    for question in problem.questions:
        for instant in question_states(question.options):
            for name, expr in instant.coordinates:
                if isinstance(expr.tree, ex.Name):
                    found.setdefault(expr.tree.id, set()).add(name)
    names = {p.name for p in problem.parameters}
    return {k: frozenset(v) for k, v in found.items() if k in names}


def state_rate_parameters(problem: Problem) -> dict[str, frozenset[tuple[str, int]]]:
    """The parameters that stand alone as a rate (1) or an acceleration (2) of a
    coordinate in a question's state (``at: {dot(x): v}``, an impact's ``before: {x: v0}``):
    each -> those (coordinate, order) pairs. Such a parameter has the coordinate's rate's
    dimension (m/s for a length, rad/s for an angle)."""
    found: dict[str, set[tuple[str, int]]] = {}
    names = {p.name for p in problem.parameters}

    def see(coordinate: str, order: int, expr: ex.Expr) -> None:
        if isinstance(expr.tree, ex.Name) and expr.tree.id in names:
            found.setdefault(expr.tree.id, set()).add((coordinate, order))

    for question in problem.questions:
        for field in dataclasses.fields(question.options):
            value = getattr(question.options, field.name)
            if isinstance(value, Instant):
                for name, expr in value.rates:
                    see(name, 1, expr)
            elif field.name == "before" and isinstance(value, tuple):
                for name, expr in value:
                    see(name, 1, expr)
            elif isinstance(value, tuple) and value and all(isinstance(v, StateValue) for v in value):
                for v in value:
                    if v.order:
                        see(v.coordinate, v.order, v.value)
    return {k: frozenset(v) for k, v in found.items()}


def question_states(options: object) -> list[Instant]:
    """A question's states as given (``at:``, ``from_rest:``)."""
    return [getattr(options, f.name) for f in dataclasses.fields(options)
            if isinstance(getattr(options, f.name), Instant)]


def time_rates(pieces: object, names: frozenset[str]) -> dict[str, str]:
    """The parameters (of ``names``) that are rates by how the scene writes them: a
    frame's ``rate: Omega``, or a term ``Omega*t`` (times a number) of an angle — a
    turn's, a body's, a sine's argument (a triad turned by [z, Omega*t], a disk spun by
    [z, s*t], a pivot driven as a*sin(w*t)); not v0*t in a position, a length. Each ->
    where it was seen. ``pieces``: the scene's sections (dataclasses, tuples of them)."""
    found: dict[str, str] = {}
    for kind, tree, where in _angles(pieces):
        if kind == "rate":
            name = lone_parameter(tree, names, False)
            if name is not None:
                found.setdefault(name, f"frames.{where}.rate" if where else "frames.rate")
            continue
        for term in sum_terms(tree):
            factors = product_names(term)
            if factors is not None and len(factors) == 2 and factors.count("t") == 1:
                (name,) = [f for f in factors if f != "t"]
                if name in names:
                    found.setdefault(name, f"{where}: {name}*t, an angle" if where else f"{name}*t, an angle")
    return found


def _angles(value: object, angle: bool = False, where: str = ""):
    """Each angle the scene writes in ``value`` (its sections: dataclasses, tuples of them,
    expressions): ("angle", tree, where) for an ``angle``, ``half_angle`` or ``rest``
    (a body's, a turn's, a line's, a shape's, a spring's) and for a trigonometric call's
    argument anywhere, and ("rate", tree, where) for a frame's ``rate``; ``where``: the
    name of the nearest named piece (a triad, a body, a frame), '' at the top. A question's
    state is not walked (its values are read by ``state_parameters``)."""
    if isinstance(value, ex.Expr):
        yield from _angle_trees(value.tree, angle, where)
    elif isinstance(value, (tuple, list)):
        for item in value:
            yield from _angles(item, angle, where)
    elif dataclasses.is_dataclass(value) and not isinstance(value, type) and not isinstance(value, Instant):
        named = getattr(value, "name", None) or where
        for field in dataclasses.fields(value):
            item = getattr(value, field.name)
            if field.name == "rate" and isinstance(item, ex.Expr):
                yield "rate", item.tree, named
            yield from _angles(item, field.name in ANGLE_FIELDS, named)


def _angle_trees(tree: ex.Tree, angle: bool, where: str):
    """``tree`` itself where it is an angle (``angle``), and each trigonometric call's
    argument anywhere in it."""
    if angle:
        yield "angle", tree, where
    if isinstance(tree, ex.Call):
        for item in tree.args:
            yield from _angle_trees(item, tree.func in TRIG, where)
    elif isinstance(tree, ex.BinOp):
        yield from _angle_trees(tree.left, False, where)
        yield from _angle_trees(tree.right, False, where)
    elif isinstance(tree, ex.Neg):
        yield from _angle_trees(tree.operand, False, where)
    elif isinstance(tree, ex.Vec):
        for item in tree.items:
            yield from _angle_trees(item, False, where)


