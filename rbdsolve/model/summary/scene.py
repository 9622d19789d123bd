"""What the scene itself makes doubtful, said on the questions it bears on and in the
model section's notes: a body that moves with an angle coordinate without turning
(``Unturned``: its T lacks the rotational part; where it evidently swings, every
question that uses T warns of it), a spring whose length keeps |…| (its sign at the
reference configuration undecided), and a declared parameter that nothing uses (a line
left out, such as ``gravity:``). Read from the model alone; the answers are unchanged."""

from __future__ import annotations

import math
import random
from dataclasses import dataclass

import sympy as sp

from rbdsolve.form.printers import to_unicode, unicode_name
from rbdsolve.form.tidy import tidy
from rbdsolve.model.angles import angle_coordinates, angle_parameters
from rbdsolve.model.build import Model, declared_ranges
from rbdsolve.model.energies.spring_length import polar_distances, reference_outside
from rbdsolve.model.values.values import parameter_sample
from rbdsolve.problem import expr as ex
from rbdsolve.problem.quantities.quantity import ACCELERATION
from rbdsolve.problem.schema import CoordinateKind
from rbdsolve.problem.usage import question_states, unused_parameters
from rbdsolve.report import steps as st


def swing_warnings(model: Model) -> tuple[str, ...]:
    """The warnings for bodies that evidently swing without an angle (``Unturned`` with
    a pivot), for every question that uses T."""
    return tuple(u.text() for u in unturned(model) if u.pivot is not None)


def unused_warnings(model: Model) -> tuple[str, ...]:
    """A warning for each declared parameter that nothing in the scene or the questions
    uses (``problem.usage``): no answer depends on it, so a line is most likely missing;
    for an acceleration of gravity in a scene without ``gravity:``, the line to add."""
    return tuple(_unused_text(p, model) for p in unused_parameters(model.problem))


def radian_warnings(model: Model) -> tuple[str, ...]:
    """A warning for each angle given a bare number past a full turn, 2π: read in
    radians, as every bare angle is, though an exam's ``alpha: 30`` most likely means
    degrees (30 rad is 1719°). A parameter is an angle by how the scene writes it or as
    an angle coordinate's value in a state (``model.angles``); a state's own bare number
    too. Which coordinates are angles is asked only where a value or a state calls for
    it (it makes the bodies' positions, which the numeric route does without)."""
    problem = model.problem
    past = {name: v for name, v in problem.values
            if v.dimension is None and not v.angle and abs(v.approx) > 2 * math.pi}
    states = [expr for q in problem.questions for instant in question_states(q.options)
              for _, expr in instant.coordinates
              if isinstance(expr.tree, ex.Num) and abs(expr.tree.value) > 2 * math.pi]
    if not past and not states:
        return ()  # most files: nothing to look for
    angles = angle_parameters(model, frozenset(past))
    coordinates = angle_coordinates(model) if states else frozenset()
    said = [_in_radians(f"parameter '{name}', an angle,", past[name].text, past[name].approx)
            for name in sorted(angles)]
    said += [_in_radians(f"{expr.loc}: the angle", expr.text, float(expr.tree.value)) for expr in states
             if expr.loc.path and expr.loc.path[-1] in coordinates]
    return tuple(said)


def _in_radians(what: str, text: str, value: float) -> str:
    return (f"{what} is given as {text}, read in radians ({text} rad is {math.degrees(value):.0f}°); "
            f"for degrees write '{text} deg'")


def _unused_text(parameter, model: Model) -> str:
    name = parameter.name
    text = f"parameter '{name}' is declared but used nowhere: no answer depends on it"
    dimension = model.problem.dimension_map().get(name)
    gravity = (name == "g" or "gravit" in parameter.description.lower() or dimension == ACCELERATION)
    if gravity and model.gravity is None:
        return (f"{text}, and the scene has no gravity (no 'gravity:' line), so V holds no weight; if the bodies "
                f"are in gravity, add `gravity: [0, -{name}]` (y up; `[0, 0, -{name}]` in 3D)")
    return f"{text} (is a line that uses it missing?)"


def scene_notes(model: Model) -> list[st.Step]:
    """The model section's notes on the scene: each spring whose length keeps |…|
    (``_two_sided``), each whose |r| is a polar distance taken ≥ 0 (``_polar``), then
    each body that moves with an angle coordinate without turning (a warning where it
    evidently swings: ``unturned``)."""
    swinging = unturned(model)
    return [*_two_sided(model), *_polar(model),
            *(st.note(u.text() if u.pivot is None else f"warning: {u.text()}") for u in swinging)]


def _polar(model: Model) -> list[st.Step]:
    """A note for each spring length |r| written r because r is a polar distance
    (model/energies/spring_length.py, ``polar_distances``): the answers hold for r ≥ 0."""
    out = []
    for spring in model.springs:
        if spring.source.ends is None or not spring.lengths:
            continue
        a, b = (model.symbols.vector(e) for e in spring.source.ends)
        polar = polar_distances(a - b, model.q)
        for length in spring.lengths:
            if length.sign is not None and length.inside in polar:
                r = to_unicode(model.readable(length.inside))
                out.append(st.note(f"Spring '{spring.name}': its length |{r}| is {r}, a distance from its other end, "
                                   f"taken ≥ 0 (a negative {r} is the same point as {r} > 0 with the direction turned "
                                   f"half a turn); the answers hold for {r} ≥ 0"))
    return out


def _two_sided(model: Model) -> list[st.Step]:
    """A note for each spring length |u| whose sign at the reference configuration is
    not known (model/energies/spring_length.py): the two cases, in words, and what decides them."""
    out = []
    at = ", ".join(f"{unicode_name(n)} = 0" for n in model.coordinate_names())
    for spring in model.springs:
        for length in spring.lengths:
            if length.sign is not None:
                continue
            u = model.readable(length.inside)
            shown = to_unicode(u)
            term = _term_of(model.readable(spring.stretch), sp.Abs(u))  # 4 a |sin(u)|, not |sin(u)| alone
            whole, plus, minus = (to_unicode(tidy(term.xreplace({sp.Abs(u): x}))) for x in (sp.Abs(u), u, -u))
            here = tidy(length.inside.xreplace({q: sp.Integer(0) for q in model.q}))
            outside = _outside_range(length.inside, model)
            why = (f"{outside} lies at an end of the range declared for it or outside, and over that range the "
                   f"parameters do not decide the sign of {shown}: give a range on one side of its zero"
                   f"{_zero_of(u, model)}, or assumptions that decide its sign at the range's ends" if outside else
                   f"it is zero at {at}, where the spring passes through zero length{_one_side(length.inside, model)}"
                   if here == 0 else
                   f"its sign at {at} ({to_unicode(here)}) is not decided by the parameters (state it under "
                   f"'assumptions:', such as {_positive(here)}, to take one side)")
            out.append(st.note(f"Spring '{spring.name}': its length is {whole}, which is {plus} where {shown} > 0 "
                               f"and {minus} where {shown} < 0; {why}, so V, its derivatives and the answers "
                               "keep |…| and sign(…)"))
    return out


def _outside_range(u: sp.Expr, model: Model) -> str:
    """'y = 0' where the reference configuration lies at an end of, or outside, the range
    declared for a coordinate u holds (spring_length.reference_outside), else ''."""
    ranges = declared_ranges(model.problem.coordinates, model.symbols)
    for q, name in zip(model.q, model.coordinate_names()):
        if q in ranges and reference_outside(u, {q: sp.Integer(0)}, {q: ranges[q]}):
            return f"{unicode_name(name)} = 0"
    return ""


def _zero_of(u: sp.Expr, model: Model) -> str:
    """' (y = a/2)': where u, linear in one coordinate, is zero; '' otherwise."""
    found = [q for q in u.free_symbols if q in {model.readable(x) for x in model.q}]
    if len(found) != 1 or sp.diff(u, found[0], 2) != 0 or sp.diff(u, found[0]) == 0:
        return ""
    (q,) = found
    return f" ({to_unicode(q)} = {to_unicode(tidy(sp.solve(u, q)[0]))})"


def _one_side(u: sp.Expr, model: Model) -> str:
    """How to take one side of u = 0 where u is a multiple of one coordinate (a bead on
    a rod through the axis, on a spring from the axis: its length |s|): a range for the
    coordinate on one side of 0 (model/energies/spring_length.py, ``_sign_over``)."""
    held = [(q, c) for q, c in zip(model.q, model.problem.coordinates) if u.has(q)]  # q in the file's order
    if len(held) != 1 or not (u / held[0][0]).is_constant():
        return ""
    declared = held[0][1]
    kind = "angle, periodic: false" if declared.kind is CoordinateKind.ANGLE else "length"
    return (f" (give {declared.name} a range on one side of 0 to take that side, such as "
            f"'{declared.name}: {{kind: {kind}, range: [0, …]}}')")


def _term_of(stretch: sp.Expr, absolute: sp.Expr) -> sp.Expr:
    """The term of the stretch (the length less l₀) that holds |u|: the length's part
    written with it; |u| itself where no single term holds it."""
    held = [t for t in sp.Add.make_args(sp.expand(stretch)) if t.has(absolute)]
    return held[0] if len(held) == 1 else absolute


def _positive(value: sp.Expr) -> str:
    """value > 0 as an assumption is written in a file: [l > h] for l − h."""
    terms = sp.Add.make_args(value)
    below = [-x for x in terms if x.could_extract_minus_sign()]
    above = [x for x in terms if not x.could_extract_minus_sign()]
    if above and below:
        return f"[{sp.Add(*above)} > {sp.Add(*below)}]"
    return f"[{value} > 0]"




@dataclass(frozen=True)
class Unturned:
    """A body with rotational inertia that moves with angle coordinates but has no
    ``angle`` or ``orientation``: it translates, and its rotational energy is zero.
    ``pivot``: a point it keeps a constant distance to while it moves (a named one, or
    the centre of the circle its centre moves on), so it evidently swings about it with
    the coordinate ``turns_by`` (a likely mistake); None: it may just slide."""

    body: str
    coordinates: tuple[str, ...]
    pivot: str | None
    turns_by: str = ""  # the coordinate it evidently swings with ('' with no pivot)

    def text(self) -> str:
        moves = ", ".join(self.coordinates)
        if self.pivot is None:
            return (f"Note: {self.body} has no 'angle', so it moves with {moves} without turning "
                    "(no rotational energy). If it turns, give its angle.")
        return (f"body '{self.body}' has no angle: it moves with {moves} without turning (no rotational "
                f"energy), though it keeps its distance to {self.pivot}; if it swings about {self.pivot}, "
                f"add `angle: {self.turns_by}` (or the angle it turns by)")


def unturned(model: Model) -> tuple[Unturned, ...]:
    """The bodies that move with an angle coordinate without turning (see Unturned)."""
    out = []
    for body in model.bodies:
        if body.angle is not None or body.turns_3d or body.inertia == sp.zeros(3, 3) or not body.placed:
            continue
        moves = tuple(n for q, n in zip(model.q, model.coordinate_names())
                      if q in model.angles and body.position.has(q))
        if moves:
            pivot, turns_by = _pivot(model, body.position) or (None, "")
            out.append(Unturned(body.name, moves, pivot, turns_by or moves[0]))
    return tuple(out)


def _pivot(model: Model, position: sp.Matrix) -> tuple[str, str] | None:
    """What G turns about, and with which coordinate: a named point (``_named_pivot``),
    else the centre of the circle G moves on as one angle coordinate turns
    (``_circle_centre``: a rod hung by its end from an unnamed pivot, G = l/2 (sin θ,
    −cos θ)); None if neither."""
    named = _named_pivot(model, position)
    if named is not None:
        return named, ""
    found = _circle_centre(model, position)
    if found is None:
        return None
    centre, q = found
    shown = centre[:2, 0] if centre[2] == 0 else centre
    name = dict(zip(model.q, model.coordinate_names()))[q]
    return f"the point ({', '.join(to_unicode(model.readable(x)) for x in shown)})", name


def _circle_centre(model: Model, position: sp.Matrix) -> tuple[sp.Matrix, sp.Symbol] | None:
    """A + B cos q + C sin q, with A, B, C free of the angle coordinate q, is a circle of
    centre A where B·C = 0 and |B| = |C| ≠ 0: that centre and q, for the last angle q
    (in the file's order: a chain's links from the base out, the body's own joint last)
    that moves G so; else None. Exact: A, B, C are read off with sin q and cos q as
    symbols."""
    c, s = sp.Dummy("c"), sp.Dummy("s")
    for q in reversed(model.q):
        if q not in model.angles or not position.has(q):
            continue
        r = position.applyfunc(sp.expand).xreplace({sp.cos(q): c, sp.sin(q): s})
        if r.has(q):
            continue
        A, B, C = r.xreplace({c: 0, s: 0}), r.diff(c), r.diff(s)
        if any(sp.expand(x) != 0 for x in r - (A + B * c + C * s)) or B.has(c, s) or C.has(c, s):
            continue
        if B == sp.zeros(3, 1) or sp.expand(B.dot(C)) != 0 or sp.expand(B.dot(B) - C.dot(C)) != 0:
            continue
        return A, q
    return None


def _named_pivot(model: Model, position: sp.Matrix) -> str | None:
    """A named point P with |r_G − r_P| the same at random samples of the coordinates
    (the parameters at one sample), while r_G − r_P is not: G turns about P. Sampled, not
    simplified: a constant distance needs sin² + cos² = 1 and its like, which the
    samples see at once."""
    rng = random.Random(26)
    parameters = parameter_sample(model, rng)
    samples = [{**parameters, **{q: sp.Rational(rng.randint(1100, 2900), 1000) for q in model.q}}
               for _ in range(3)]
    for name, point in model.points.items():
        r = position - point
        if not r.free_symbols & set(model.q):
            continue
        d = r.dot(r)
        lengths = {round(float(sp.N(d.xreplace(x), 30)), 9) for x in samples}
        if len(lengths) == 1 and next(iter(lengths)) > 0:
            return name
    return None
