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
    found: set[str] = set()
    names = frozenset(p.name for p in problem.parameters)
    for field in dataclasses.fields(problem):
        if field.name not in NOT_USES:
            _angles_in(getattr(problem, field.name), found, names, False)
    return frozenset(found)


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


def _angles_in(value: object, found: set[str], names: frozenset[str], angle: bool) -> None:
    """The angle parameters (of ``names``) in ``value`` (``angle``: ``value`` is itself an angle)."""
    if isinstance(value, ex.Expr):
        _angle_terms(value.tree, found, names, angle)
    elif isinstance(value, (tuple, list)):
        for item in value:
            _angles_in(item, found, names, angle)
    elif dataclasses.is_dataclass(value) and not isinstance(value, type) and not isinstance(value, Instant):
        for field in dataclasses.fields(value):
            _angles_in(getattr(value, field.name), found, names, field.name in ANGLE_FIELDS)


def _angle_terms(tree: ex.Tree, found: set[str], names: frozenset[str], angle: bool) -> None:
    """``angle``: the parameters that are terms of ``tree``, each alone or times (over) a
    number (2*beta, alpha/2; not Omega*t); and, anywhere in it, those of each
    trigonometric call's argument."""
    if angle:
        found.update(p for term in sum_terms(tree) if (p := lone_parameter(term, names, False)) is not None)
    if isinstance(tree, ex.Call):
        for item in tree.args:
            _angle_terms(item, found, names, tree.func in TRIG)
    elif isinstance(tree, ex.BinOp):
        _angle_terms(tree.left, found, names, False)
        _angle_terms(tree.right, found, names, False)
    elif isinstance(tree, ex.Neg):
        _angle_terms(tree.operand, found, names, False)
    elif isinstance(tree, ex.Vec):
        for item in tree.items:
            _angle_terms(item, found, names, False)


def time_rates(pieces: object, names: frozenset[str]) -> dict[str, str]:
    """The parameters (of ``names``) that are rates by how the scene writes them: a
    frame's ``rate: Omega``, or a term ``Omega*t`` (times a number) of an angle — a
    turn's, a body's, a sine's argument (a triad turned by [z, Omega*t], a disk spun by
    [z, s*t], a pivot driven as a*sin(w*t)); not v0*t in a position, a length. Each ->
    where it was seen. ``pieces``: the scene's sections (dataclasses, tuples of them)."""
    found: dict[str, str] = {}
    _rates_in(pieces, found, names, False, "")
    return found


def _rates_in(value: object, found: dict[str, str], names: frozenset[str], angle: bool, where: str) -> None:
    if isinstance(value, ex.Expr):
        _rate_terms(value.tree, found, names, angle, where)
    elif isinstance(value, (tuple, list)):
        for item in value:
            _rates_in(item, found, names, angle, where)
    elif dataclasses.is_dataclass(value) and not isinstance(value, type) and not isinstance(value, Instant):
        for field in dataclasses.fields(value):
            item = getattr(value, field.name)
            if field.name == "rate" and isinstance(item, ex.Expr):
                name, frame = lone_parameter(item.tree, names, False), getattr(value, "name", None)
                if name is not None:
                    found.setdefault(name, f"frames.{frame}.rate" if frame else "frames.rate")
                continue
            _rates_in(item, found, names, field.name in ANGLE_FIELDS or field.name == "turns",
                      getattr(value, "name", None) or where)


def _rate_terms(tree: ex.Tree, found: dict[str, str], names: frozenset[str], angle: bool, where: str) -> None:
    """``angle``: each term of ``tree`` that is one parameter times t (and numbers); and,
    anywhere in it, those of each trigonometric call's argument."""
    if angle:
        for term in sum_terms(tree):
            factors = product_names(term)
            if factors is not None and sorted(factors).count("t") == 1 and len(factors) == 2:
                (name,) = [f for f in factors if f != "t"]
                if name in names:
                    found.setdefault(name, f"{where}: {name}*t, an angle" if where else f"{name}*t, an angle")
    if isinstance(tree, ex.Call):
        for item in tree.args:
            _rate_terms(item, found, names, tree.func in TRIG, where)
    elif isinstance(tree, ex.BinOp):
        _rate_terms(tree.left, found, names, False, where)
        _rate_terms(tree.right, found, names, False, where)
    elif isinstance(tree, ex.Neg):
        _rate_terms(tree.operand, found, names, False, where)
    elif isinstance(tree, ex.Vec):
        for item in tree.items:
            _rate_terms(item, found, names, False, where)
