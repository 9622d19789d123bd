"""The ``questions:`` section: each question's kind and its options, validated.

A question is a name (``- eom``) or a one-key mapping with options
(``- modes: {about: {theta: 0}}``). Options are checked against what the question
knows about the scene: coordinates for ``modes``, bodies and points for ``inertia``.
"""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

from rbdsolve.errors import InputError, did_you_mean
from rbdsolve.problem import expr as ex
from rbdsolve.problem.context import Reading
from rbdsolve.problem.sections.amplitudes import amplitudes
from rbdsolve.problem.sections.states import instant
from rbdsolve.problem.schema import (
    Body,
    Coordinate,
    EomOptions,
    EquilibriaOptions,
    ModesOptions,
    Point,
    Question,
    QuestionKind,
)
from rbdsolve.problem.surfaces import NOT_INTEGRABLE, SurfaceKind
from rbdsolve.problem.readers import check_keys, describe, expect_mapping, expect_scalar
from rbdsolve.problem.yamlnodes import Map, Node, Scalar, Seq

if TYPE_CHECKING:
    from rbdsolve.problem.options import (EnergyOptions, ImpactOptions, InertiaOptions, KinematicsOptions,
                                          PrecessionOptions, Reaction, ReactionsOptions, SteadyMotionOptions,
                                          SteadySpinOptions)
    from rbdsolve.problem.scene import Contact

OPTIONS = {
    QuestionKind.EOM: ("frames", "at", "from_rest"),
    QuestionKind.EQUILIBRIA: ("frame", "for"),
    QuestionKind.MODES: ("about", "frame", "check_amplitudes", "for"),
    QuestionKind.INERTIA: ("body", "about", "axes", "at", "axis"),
    QuestionKind.STEADY_SPIN: ("body", "precession"),
    QuestionKind.STEADY_MOTION: ("body", "triad", "about", "rolling_at", "reactions", "solve_for", "for"),
    QuestionKind.IMPACT: ("at", "before", "impulses", "collisions", "points", "centre_of_percussion"),
    QuestionKind.KINEMATICS: ("points", "at", "distance", "bodies", "lines"),
    QuestionKind.REACTIONS: ("forces", "at", "from_rest", "to"),
    QuestionKind.ENERGY: ("from_rest", "at", "to", "points"),
}

# the questions that need independent coordinates: a contact on a plane eliminates none
NEED_INDEPENDENT_COORDINATES = (QuestionKind.EOM, QuestionKind.EQUILIBRIA, QuestionKind.MODES, QuestionKind.REACTIONS)


def _point(contact: Contact) -> ex.Expr:
    """A contact's point C as a point expression (the model derives its position)."""
    return ex.Expr(ex.Name(contact.name), ex.Kind.VECTOR, contact.name, contact.loc)


class QuestionReader:
    def __init__(self, reading: Reading, coordinates: tuple[Coordinate, ...], bodies: tuple[Body, ...],
                 points: tuple[Point, ...], frames: tuple[str, ...] = (), contacts: tuple[Contact, ...] = ()):
        self.reading = reading
        self.contacts = contacts
        self.frames = frames
        self.coordinates = coordinates
        self.bodies = bodies
        self.points = points

    def question(self, node: Node) -> Question:
        if isinstance(node, Map) and len(node.entries) == 1:
            key, options = node.entries[0]
        elif isinstance(node, Scalar) and not node.null:
            key, options = node, None
        else:
            raise InputError("expected a question such as 'modes' or '{modes: {...}}', "
                             f"found {describe(node)}", node.loc)
        kinds = [k.value for k in QuestionKind]
        try:
            kind = QuestionKind(key.text)
        except ValueError:
            hint = did_you_mean(key.text, kinds) or f" (questions: {', '.join(kinds)})"
            raise InputError(f"unknown question '{key.text}'{hint}", key.loc) from None
        if kind.needs_coordinates and not self.coordinates:
            raise InputError(f"'{kind.value}' needs generalized coordinates: add 'coordinates:'", key.loc)
        if kind.needs_positions:
            self.require_positions(kind, key)
        if kind in NEED_INDEPENDENT_COORDINATES:
            self.refuse_plane_rolling(kind, key)
        opts = None
        if options is not None and not (isinstance(options, Scalar) and options.null):
            if not OPTIONS[kind]:
                raise InputError(f"'{kind.value}' takes no options", options.loc)
            opts = expect_mapping(options, f"options of '{kind.value}'")
            check_keys(opts, (), OPTIONS[kind], f"question '{kind.value}'")
        get = opts.get if opts else (lambda _: None)
        if kind is QuestionKind.EOM:
            frames = self.frame_list(get("frames")) if get("frames") is not None else ()
            return Question(kind, EomOptions(frames, instant(self.reading, opts)), key.loc)
        if kind is QuestionKind.EQUILIBRIA:
            return Question(kind, EquilibriaOptions(self.frame(get("frame")), self.parameter(get("for"))), key.loc)
        if kind is QuestionKind.MODES:
            about = get("about")
            each = isinstance(about, Scalar) and about.text.strip() == "each"
            if each and get("check_amplitudes") is not None:
                raise InputError("'check_amplitudes' takes one equilibrium; with 'about: each' ask it in a "
                                 "question of its own", get("check_amplitudes").loc)
            number = self.equilibrium_number(about) if about and not each else None
            point, steady = self.steady_state(about) if about and number is None and not each else (None, ())
            if steady and get("check_amplitudes") is not None:
                raise InputError("'check_amplitudes' simulates the scene's own equations about an equilibrium; it is "
                                 "not available about a steady spin (a rate dot(q) in 'about')",
                                 get("check_amplitudes").loc)
            return Question(kind, ModesOptions(point, self.frame(get("frame")),
                                               amplitudes(get("check_amplitudes"), get("frame")), equilibrium=number,
                                               each=each, loc=about.loc if about else None, steady=steady,
                                               for_parameter=self.parameter(get("for"))), key.loc)
        return Question(kind, self.other_options(kind, opts, key), key.loc)

    def other_options(self, kind: QuestionKind, opts: Map | None, key: Scalar) -> (
            InertiaOptions | SteadySpinOptions | SteadyMotionOptions | ImpactOptions | KinematicsOptions
            | ReactionsOptions | EnergyOptions):
        """The options of a question beyond eom, equilibria and modes. Their classes
        (problem/options.py) and the section modules that read some of them are imported
        where a file asks such a question: a file that asks none creates none of those
        classes (Python generates each frozen dataclass's methods at import)."""
        if kind is QuestionKind.INERTIA:
            return self.inertia(opts, key)
        if kind is QuestionKind.STEADY_MOTION:
            return self.steady_motion(opts, key)
        if kind is QuestionKind.STEADY_SPIN:
            from rbdsolve.problem.options import SteadySpinOptions

            node = opts.get("precession") if opts else None
            return SteadySpinOptions(self.body(opts, key, kind), self.precession(node) if node is not None else None)
        if kind is QuestionKind.IMPACT:
            from rbdsolve.problem.sections.impact import ImpactReader

            return ImpactReader(self.reading, self.points).options(opts, key)
        if kind is QuestionKind.KINEMATICS:
            from rbdsolve.problem.sections.kinematics import KinematicsReader

            return KinematicsReader(self.reading, self.points, self.bodies).options(opts, key)
        from rbdsolve.problem.sections.forces import energy_options, reactions_options

        if kind is QuestionKind.REACTIONS:
            return reactions_options(self.reading, opts, key, self.bodies, self.contacts)
        return energy_options(self.reading, opts, key, tuple(p.name for p in self.points))

    def frame(self, node: Node | None) -> str | None:
        if node is None:
            return None
        name = expect_scalar(node, "a frame name").text.strip()
        if name not in self.frames:
            known = f" (frames: {', '.join(self.frames)})" if self.frames else " (declare it under 'frames:')"
            raise InputError(f"no frame '{name}'{did_you_mean(name, list(self.frames)) or known}", node.loc)
        return name

    def parameter(self, node: Node | None) -> str | None:
        """'for: k': the parameter whose critical values the conditions are written in."""
        if node is None:
            return None
        name = expect_scalar(node, "a parameter name").text.strip()
        declared = [n for n, what in self.reading.taken.items() if what == "parameter"]
        if name not in declared:
            what = self.reading.taken.get(name)
            hint = (f" ('{name}' is a {what}; conditions are written in a parameter)" if what
                    else did_you_mean(name, declared) or f" (parameters: {', '.join(declared) or 'none'})")
            raise InputError(f"no parameter '{name}'{hint}", node.loc)
        return name

    def frame_list(self, node: Node) -> tuple[str, ...]:
        if not isinstance(node, Seq):
            raise InputError(f"expected a list of frame names, found {describe(node)}", node.loc)
        return tuple(self.frame(item) for item in node.items)

    def require_positions(self, kind: QuestionKind, key: Scalar) -> None:
        """Equations of motion, equilibria and modes need the motion, not one instant."""
        given = [f"body '{b.name}'" for b in self.bodies if b.velocity is not None]
        given += [f"point '{p.name}'" for p in self.points if p.position is None]
        if given:
            raise InputError(f"'{kind.value}' needs positions, but {given[0]} is given by its velocity "
                             "at one instant (such a scene answers 'impact' questions)", key.loc)

    def equilibrium_number(self, node: Node) -> int | None:
        """'about: {equilibrium: N}' (unless a coordinate is named 'equilibrium'): N ≥ 1."""
        if not isinstance(node, Map) or node.keys() != ["equilibrium"] or "equilibrium" in self.coordinates:
            return None
        ((_, value),) = node.entries
        text = expect_scalar(value, "an equilibrium's number").text.strip()
        if not text.isdigit() or int(text) < 1 or len(text) > 6:
            raise InputError(f"'equilibrium' takes the number 'equilibria' prints (1, 2, …), not '{text[:40]}'",
                             value.loc)
        return int(text)

    def equilibrium(self, node: Node) -> tuple[tuple[str, ex.Expr], ...]:
        return self.reading.coordinate_values(node, "an equilibrium", complete=True)

    def steady_state(self, node: Node) -> tuple[tuple[tuple[str, ex.Expr], ...], tuple[tuple[str, ex.Expr], ...]]:
        """'about': a value for every coordinate, except a cyclic one (a spin angle) that
        may be given by its steady rate instead, dot(phi): s: (values, rates). Without a
        rate, read as an equilibrium (every coordinate, its messages unchanged)."""
        if not isinstance(node, Map) or not any(k.text.strip().startswith("dot") for k, _ in node.entries):
            return self.equilibrium(node), ()
        given = self.reading.state(node, "an equilibrium or a steady spin", (0, 1))
        values = tuple((v.coordinate, v.value) for v in given if v.order == 0)
        rates = tuple((v.coordinate, v.value) for v in given if v.order == 1)
        held = {name for name, _ in (*values, *rates)}
        missing = [name for name in self.reading.coordinates if name not in held]
        if missing:
            raise InputError(f"give a value for every coordinate; missing {', '.join(missing)} (a cyclic "
                             "coordinate, such as a top's spin angle, may be given by its steady rate instead, "
                             f"dot({missing[0]}): RATE)", node.loc)
        kept = {name for name, _ in rates}
        return tuple((n, e) for n, e in values if n not in kept), rates

    def body(self, opts: Map | None, key: Scalar, kind: QuestionKind) -> str:
        """The body a question is about: 'body: NAME', or the scene's only body."""
        names = [b.name for b in self.bodies]
        body_node = opts.get("body") if opts else None
        if body_node is None:
            if len(names) != 1:
                found = "no bodies" if not names else f"{len(names)} bodies ({', '.join(names)})"
                raise InputError(f"'{kind.value}' needs 'body: NAME' when the scene has {found}", key.loc)
            return names[0]
        body = expect_scalar(body_node, "a body name").text
        if body not in names:
            raise InputError(f"no body '{body}'{did_you_mean(body, names)}", body_node.loc)
        return body

    def steady_motion(self, opts: Map | None, key: Scalar) -> SteadyMotionOptions:
        from rbdsolve.problem.options import SteadyMotionOptions

        get = opts.get if opts else (lambda _: None)
        triads = self.reading.triad_names
        triad_node = get("triad")
        if triad_node is None:
            if len(triads) != 1:
                raise InputError("'steady_motion' needs 'triad: NAME', the turning triad the motion is steady "
                                 f"in ({'no triads are declared' if not triads else ', '.join(triads)})", key.loc)
            triad = triads[0]
        else:
            triad = expect_scalar(triad_node, "a triad name").text.strip()
            if triad not in triads:
                hint = did_you_mean(triad, list(triads)) or f" (triads: {', '.join(triads) or 'none'})"
                raise InputError(f"no triad '{triad}'{hint}", triad_node.loc)
        if get("about") is None:
            raise InputError("'steady_motion' needs 'about: POINT', the point for angular momentum", key.loc)
        body = self.body(opts, key, QuestionKind.STEADY_MOTION)
        contacts = self.point_list(get("rolling_at"))
        contacts += tuple(_point(c) for c in self.contacts if c.surface.kind is SurfaceKind.PLANE
                          and c.body == body and c.name not in {p.text for p in contacts})
        reactions = self.reactions(get("reactions"))
        targets = self.constants(get("solve_for"), "what to solve for")
        if next(b for b in self.bodies if b.name == body).velocity is not None:
            raise InputError(f"'steady_motion' needs the position of body '{body}' ('at'); it is given by its "
                             "velocity at one instant", key.loc)
        where = get("reactions").loc if get("reactions") is not None else None
        return SteadyMotionOptions(body, triad, self.point(get("about")), contacts, reactions, targets, where,
                                   self.parameter(get("for")))

    def refuse_plane_rolling(self, kind: QuestionKind, key: Scalar) -> None:
        """eom, equilibria, modes and reactions need independent coordinates: a contact
        rolling on a plane in 3D gives a relation between the rates that eliminates none."""
        for c in self.contacts:
            if c.surface.kind is SurfaceKind.PLANE:
                raise InputError(f"'{kind.value}' cannot take contact '{c.name}' (line {c.loc.line}): "
                                 f"{NOT_INTEGRABLE}, and '{kind.value}' needs independent coordinates (Lagrange's "
                                 "equations with constraint multipliers are not supported yet); a steady motion "
                                 "takes it ('steady_motion' keeps it as a constraint)", key.loc)

    def point_list(self, node: Node | None) -> tuple[ex.Expr, ...]:
        """One point, or a list of points (a cone rolls at its tip and at its rim)."""
        if node is None:
            return ()
        items = node.items if isinstance(node, Seq) else [node]
        return tuple(self.point(item) for item in items)

    def constants(self, node: Node | None, what: str) -> tuple[ex.Expr, ...]:
        if node is None:
            return ()
        items = node.items if isinstance(node, Seq) else [node]
        return tuple(self.reading.constant(item, what) for item in items)

    def reactions(self, node: Node | None) -> tuple[Reaction, ...]:
        """[{at: POINT, force: VECTOR}, ...]: contact forces with unknown magnitudes."""
        if node is None:
            return ()
        from rbdsolve.problem.options import Reaction

        if not isinstance(node, Seq):
            raise InputError(f"expected a list of reactions [{{at: POINT, force: VECTOR}}, ...], found "
                             f"{describe(node)}", node.loc)
        found = []
        for item in node.items:
            spec = expect_mapping(item, "a reaction {at: POINT, force: VECTOR}")
            check_keys(spec, ("at", "force"), (), "reaction")
            found.append(Reaction(self.point(spec.get("at")),
                                  self.reading.expr(spec.get("force"), ex.Kind.VECTOR, "a force vector")))
        return tuple(found)

    def inertia(self, opts: Map | None, key: Scalar) -> InertiaOptions:
        from rbdsolve.problem.options import InertiaOptions

        body = self.body(opts, key, QuestionKind.INERTIA)
        if next(b for b in self.bodies if b.name == body).velocity is not None:
            raise InputError(f"'inertia' needs the position of body '{body}' ('at'); it is given by its "
                             "velocity at one instant", key.loc)
        get = opts.get if opts else (lambda _: None)
        about, axes, at, axis = get("about"), get("axes"), get("at"), get("axis")
        if at is not None and not self.coordinates:
            raise InputError("'at' gives values for the coordinates, and this scene has none: its inertia "
                             "does not depend on a configuration", at.loc)
        return InertiaOptions(body, self.moment_point(about) if about is not None else None,
                              self.axes(axes) if axes is not None else None,
                              self.reading.coordinate_values(at, "'at'", complete=False) if at is not None else (),
                              self.reading.axis(axis) if axis is not None else None)

    def precession(self, node: Node) -> PrecessionOptions:
        """{spin: ω₃, transverse: ω⊥} or {spin: ω₃, angle: α}: constants."""
        from rbdsolve.problem.options import PrecessionOptions

        spec = expect_mapping(node, "the free motion {spin: RATE, transverse: RATE} (or angle: ANGLE)")
        check_keys(spec, ("spin",), ("transverse", "angle"), "precession")
        transverse, angle = spec.get("transverse"), spec.get("angle")
        if (transverse is None) == (angle is None):
            raise InputError("'precession' needs ω across the symmetry axis: 'transverse: RATE' (its size) or "
                             "'angle: ANGLE' (between ω and the axis), one of them", spec.loc)
        read = self.reading.constant
        return PrecessionOptions(read(spec.get("spin"), "the spin along the symmetry axis"),
                                 read(transverse, "the rate across the axis") if transverse is not None else None,
                                 read(angle, "the angle between ω and the axis") if angle is not None else None)

    def point(self, node: Node) -> ex.Expr:
        """A point to take moments about: a point name or a constant position vector."""
        return self.reading.expr(node, ex.Kind.VECTOR, "a point name or position vector")

    def moment_point(self, node: Node) -> ex.Expr:
        """The point of an inertia question: as ``point``, or a contact's point C (the
        moment of inertia of a rocking body about its contact point)."""
        scope = self.reading.scope
        scope = replace(scope, vectors=scope.vectors | {c.name for c in self.contacts})
        return self.reading.expr(node, ex.Kind.VECTOR, "a point name, a contact's name or a position vector", scope)

    def axes(self, node: Node) -> tuple[ex.Expr, ex.Expr, ex.Expr]:
        if not isinstance(node, Seq) or len(node.items) != 3:
            raise InputError("expected three axis vectors [e1, e2, e3] (unit vectors of the "
                             "frame, in scene axes)", node.loc)
        vectors = [self.reading.axis(item) for item in node.items]  # x, -y, … or vectors
        return vectors[0], vectors[1], vectors[2]
