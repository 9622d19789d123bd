"""What the force questions read: the supports ``reactions`` asks about, and where
``energy`` gives the speed; both at a state of the motion (``at:`` or ``from_rest:``,
problem/sections/states.py, as ``eom``).

    reactions: {forces: [O], from_rest: {theta: 0}}        # the force at O on the only body
    reactions: {forces: [O], from_rest: {theta: 0}, to: {theta: pi}}   # and where it gets to
    reactions: {forces: [{at: J, on: rod2, by: rod1}, C]}  # a joint; contact C (its body)

Whether a point really holds the body (a pivot, a smooth guide, a joint) needs the
kinematics, so the model checks it (solvers/reactions/supports.py).
"""

from __future__ import annotations

from rbdsolve.errors import InputError, did_you_mean
from rbdsolve.problem.context import Reading
from rbdsolve.problem.readers import check_keys, expect_scalar, read_bool
from rbdsolve.problem.options import EnergyOptions, ReactionsOptions, Support, SupportKind
from rbdsolve.problem.scene import Contact
from rbdsolve.problem.schema import Body
from rbdsolve.problem.sections.states import instant
from rbdsolve.problem.yamlnodes import Map, Node, Seq


def energy_options(reading: Reading, opts: Map | None, key, points: tuple[str, ...]) -> EnergyOptions:
    """``energy: {from_rest: {…} | at: {…}, to: {q: value}, points: [P]}``: the start state
    is needed; ``to`` is a configuration (every coordinate), ``points`` names points."""
    start = instant(reading, opts)
    if start is None:
        raise InputError("'energy' needs the state the motion starts from: 'from_rest: {q: VALUE}' or 'at: {q: "
                         "VALUE, dot(q): RATE}'", key.loc)
    to = opts.get("to")
    configuration = reading.coordinate_values(to, "the configuration 'to'", complete=True) if to is not None else ()
    node = opts.get("points")
    names = ()
    if node is not None:
        items = node.items if isinstance(node, Seq) else [node]
        names = tuple(_point_name(item, points) for item in items)
    return EnergyOptions(start, configuration, names, key.loc)


def _point_name(node: Node, points: tuple[str, ...]) -> str:
    name = expect_scalar(node, "a point name").text.strip()
    if name not in points:
        hint = did_you_mean(name, list(points)) or (f" (points: {', '.join(points)})" if points else "")
        raise InputError(f"no point '{name}'{hint}", node.loc)
    return name


def reactions_options(reading: Reading, opts: Map | None, key, bodies: tuple[Body, ...],
                      contacts: tuple[Contact, ...]) -> ReactionsOptions:
    """The supports asked about (default: every contact) and the state."""
    forces = opts.get("forces") if opts else None
    if forces is None:
        if not contacts:
            raise InputError("'reactions' needs 'forces:', the points where a body is held (a pivot 'O', a joint "
                             "'{at: J, on: rod2, by: rod1}', a contact's name)", key.loc)
        supports = tuple(_contact(c, c.loc) for c in contacts)
    else:
        items = forces.items if isinstance(forces, Seq) else [forces]
        if not items:
            raise InputError("'forces' lists at least one point or contact", forces.loc)
        supports = tuple(_Supports(reading, bodies, contacts).support(item) for item in items)
    _no_twice(supports)
    start = instant(reading, opts)
    to = opts.get("to") if opts else None
    if to is not None and (start is None or not start.from_rest):
        raise InputError("'to' asks for the forces where the motion released from rest gets to: give "
                         "'from_rest: {q: VALUE}' with it", to.loc)
    configuration = reading.coordinate_values(to, "the configuration 'to'", complete=True) if to is not None else ()
    return ReactionsOptions(supports, start, key.loc, configuration)


def _contact(c: Contact, loc) -> Support:
    return Support(SupportKind.CONTACT, c.name, c.body, None, None, loc)


def _no_twice(supports: tuple[Support, ...]) -> None:
    """Each force asked once, and at a point of its own: the answers (N_P, R_Px, the
    JSON's ``at.P``) are named after the point, so two supports at one point would
    answer under one name, one of them lost."""
    seen: dict[str, Support] = {}
    for s in supports:
        first = seen.get(s.point)
        if first is not None and frozenset({first.on, first.by}) == frozenset({s.on, s.by}):
            raise InputError(f"the force at '{s.point}' on '{s.on}' is asked twice", s.loc)
        if first is not None:
            raise InputError(f"two forces are asked at point '{s.point}' ({_between(first)}, and {_between(s)}): "
                             f"the answers are named after their point, so one would hide the other; give the "
                             f"second a point of its own at the same place (points: {{{s.point}2: {s.point}}}, then "
                             f"{{at: {s.point}2, on: {s.on}, …}})", s.loc)
        seen[s.point] = s


def _between(s: Support) -> str:
    return f"on '{s.on}'" + (f" by '{s.by}'" if s.by else "")


class _Supports:
    def __init__(self, reading: Reading, bodies: tuple[Body, ...], contacts: tuple[Contact, ...]):
        self.reading = reading
        self.bodies = [b.name for b in bodies]
        self.contacts = {c.name: c for c in contacts}

    def support(self, node: Node) -> Support:
        """'O' (the only body, or a contact's name), or {at, on, by, normal}."""
        if not isinstance(node, Map):
            name = expect_scalar(node, "a point or contact name, or {at: POINT, on: BODY}").text.strip()
            if name in self.contacts:
                return _contact(self.contacts[name], node.loc)
            self._point(name, node)
            if len(self.bodies) != 1:
                raise InputError(f"say which body the force at '{name}' acts on: {{at: {name}, on: BODY}} (bodies: "
                                 f"{', '.join(self.bodies)})", node.loc)
            return Support(SupportKind.POINT, name, self.bodies[0], None, None, node.loc)
        check_keys(node, ("at",), ("on", "by", "normal", "two_sided"), "a force asked for")
        name = expect_scalar(node.get("at"), "a point name").text.strip()
        if name in self.contacts:
            return self._at_contact(name, node)
        self._point(name, node.get("at"))
        on = self._body(node.get("on"), node, name)
        by = self._body(node.get("by"), node, name) if node.get("by") is not None else None
        if by == on:
            raise InputError(f"a body does not hold itself: 'by' names '{on}' as 'on' does", node.get("by").loc)
        normal = node.get("normal")
        direction = self.reading.axis(normal) if normal is not None else None
        both = node.get("two_sided")
        two_sided = read_bool(both, "true or false") if both is not None else False
        return Support(SupportKind.POINT, name, on, by, direction, node.loc, two_sided)

    def _at_contact(self, name: str, node: Map) -> Support:
        contact = self.contacts[name]
        on = node.get("on")
        if on is not None and expect_scalar(on, "a body name").text.strip() != contact.body:
            raise InputError(f"body '{on.text.strip()}' is not in contact at '{name}': contact '{name}' holds "
                             f"body '{contact.body}'", on.loc)
        for extra in ("by", "normal", "two_sided"):
            if node.get(extra) is not None:
                raise InputError(f"contact '{name}' gives its own surface; '{extra}' is not needed",
                                 node.get(extra).loc)
        return _contact(contact, node.loc)

    def _point(self, name: str, node: Node) -> None:
        known = list(self.reading.point_exprs) + list(self.reading.body_points)
        if name not in known:
            offered = known + list(self.contacts)
            raise InputError(f"no point or contact '{name}'{did_you_mean(name, offered)}", node.loc)

    def _body(self, node: Node | None, spec: Map, point: str) -> str:
        if node is None:
            if len(self.bodies) == 1:
                return self.bodies[0]
            raise InputError(f"say which body the force at '{point}' acts on: 'on: BODY' (bodies: "
                             f"{', '.join(self.bodies)})", spec.loc)
        word = expect_scalar(node, "a body name").text.strip()
        if word not in self.bodies:
            raise InputError(f"no body '{word}'{did_you_mean(word, self.bodies)}", node.loc)
        return word

