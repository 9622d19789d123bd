"""What every family uses to write a scene: a Builder that collects the file's sections
and, beside them, the oracle's description (scene.py), and writes both at the end."""

from __future__ import annotations

from benchmarks.neighbours.draw import Draw
from benchmarks.neighbours.scene import Body, Coord, Force, Param, Question, Scene, Spring, Support
from benchmarks.neighbours.yamltext import document


class Builder:
    """One scene in the making. Points given with ``point`` go to the file and to the
    oracle; ``hidden`` points (the generator's own geometry: a rolling body's centre,
    a contact point) only to the oracle."""

    def __init__(self, draw: Draw, family: str, variant: str, title: str):
        self.draw = draw
        self.family = family
        self.variant = variant
        self.title = title
        self.statement = ""
        self.features: list[str] = []
        self.params: list[Param] = []
        self.coords: list[Coord] = []
        self.coord_yaml: dict | list | None = None
        self.gravity: str | None = None
        self.gravity_yaml: str | None = None
        self.points: dict[str, str] = {}
        self.yaml_points: dict[str, str] = {}   # the file's form of a point where it differs (prescribed names)
        self.prescribed: dict[str, str] = {}
        self.hidden: dict[str, str] = {}
        self.bodies_yaml: dict[str, dict] = {}
        self.bodies: list[Body] = []
        self.springs_yaml: dict[str, dict] = {}
        self.springs: list[Spring] = []
        self.contacts_yaml: dict[str, dict] = {}
        self.frames_yaml: dict[str, dict] = {}
        self.forces_yaml: dict[str, dict] = {}
        self.couples_yaml: dict[str, dict] = {}
        self.forces: list[Force] = []
        self.supports: list[Support] = []
        self.questions: list[Question] = []
        self.assumptions: list[str] = []
        self.file_assumptions: list[str] = []
        self.extra: dict[str, object] = {}
        self.future: str | None = None
        self.planar = True
        self.still_in: str | None = None

    # --- parameters and coordinates ----------------------------------------------------
    def param(self, name: str, kind: str, description: str = "", **kw) -> Param:
        if any(p.name == name for p in self.params):  # one name for two quantities (k a stiffness and a radius)
            raise ValueError(f"parameter {name!r} drawn twice in one scene")
        p = self.draw.param(name, kind, description, **kw)
        self.params.append(p)
        return p

    def fixed(self, name: str, kind: str, text: str, si: str, description: str = "") -> Param:
        if any(p.name == name for p in self.params):
            raise ValueError(f"parameter {name!r} drawn twice in one scene")
        p = Param(name, kind, text, si, description=description)
        self.params.append(p)
        return p

    def coordinate(self, name: str, kind: str = "angle", periodic: bool = True, low: str | None = None,
                   high: str | None = None) -> Coord:
        c = Coord(name, kind, periodic, low, high)
        self.coords.append(c)
        return c

    def feature(self, *names: str) -> None:
        for n in names:
            if n not in self.features:
                self.features.append(n)

    # --- the scene ---------------------------------------------------------------------
    def point(self, name: str, expr: str) -> str:
        self.points[name] = expr
        return name

    def hide(self, name: str, expr: str) -> str:
        self.hidden[name] = expr
        return name

    def body(self, yaml_entry: dict, oracle: Body) -> Body:
        self.bodies_yaml[oracle.name] = yaml_entry
        self.bodies.append(oracle)
        return oracle

    def spring(self, yaml_entry: dict, oracle: Spring) -> None:
        self.springs_yaml[oracle.name] = yaml_entry
        self.springs.append(oracle)
        self.feature("torsion spring" if oracle.angle is not None else "linear spring")

    def ask(self, kind: str, options: dict | None = None) -> None:
        self.questions.append(Question(kind, options or {}))

    # --- the file ----------------------------------------------------------------------
    def text(self) -> str:
        params = {}
        for p in self.params:
            params[p.name] = p.description or p.kind if p.positive else {"description": p.description, "positive": False}
        values = {p.name: p.value for p in self.params if p.value is not None}
        if self.coord_yaml is not None:
            coords = self.coord_yaml
        else:
            coords = "[" + ", ".join(c.name for c in self.coords) + "]" if self.coords else None
        doc = {
            "title": self.title,
            "statement": self.statement or None,
            "parameters": params,
            "values": values or None,
            "assumptions": ("[" + ", ".join(self.file_assumptions) + "]") if self.file_assumptions else None,
            "unknowns": self.extra.get("unknowns"),
            "triads": self.extra.get("triads"),
            "prescribed": self.prescribed or None,
            "coordinates": coords,
            "gravity": self.gravity_yaml or self.gravity,
            "frames": self.frames_yaml or None,
            "points": {**self.points, **self.yaml_points} or None,
            "bodies": self.bodies_yaml or None,
            "contacts": self.contacts_yaml or None,
            "springs": self.springs_yaml or None,
            "forces": self.forces_yaml or None,
            "couples": self.couples_yaml or None,
            "questions": [q.kind if not q.options else {q.kind: q.options} for q in self.questions],
        }
        for k, v in self.extra.items():
            if k not in ("unknowns", "triads"):
                doc[k] = v
        return document(doc)

    def scene(self) -> Scene:
        points = dict(self.points)
        points.update(self.hidden)
        return Scene(family=self.family, variant=self.variant, features=tuple(self.features), text=self.text(),
                     params=self.params, coords=self.coords, questions=self.questions, gravity=self.gravity,
                     points=points, bodies=self.bodies, springs=self.springs, supports=self.supports,
                     forces=self.forces, assumptions=tuple(self.assumptions), planar=self.planar,
                     still_in=self.still_in, future=self.future)


def rotated(vec: tuple[str, str], angle: str) -> str:
    """The vector R(angle)·(a, b) as an expression: [a cos − b sin, a sin + b cos]."""
    a, b = vec
    terms_x, terms_y = [], []
    if a != "0":
        terms_x.append(f"({a})*cos({angle})")
        terms_y.append(f"({a})*sin({angle})")
    if b != "0":
        terms_x.append(f"-({b})*sin({angle})")
        terms_y.append(f"({b})*cos({angle})")
    x = " + ".join(terms_x).replace("+ -", "- ") or "0"
    y = " + ".join(terms_y).replace("+ -", "- ") or "0"
    return f"[{x}, {y}]"
