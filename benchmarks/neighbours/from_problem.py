"""The oracle's description of a problem file from problems/ (to show that the oracle
agrees with every expected answer there that it can model): parameters, values (SI),
coordinates, gravity, points, bodies placed by `at`/`angle` (or 3D turns), springs,
read from the YAML; a body placed by a contact gets the placement of the generator's
geometry (PLACED below, written by hand, as for the generated scenes); questions as
written. Scenes the oracle does not model (steady motion, velocities at one instant,
a prescribed unknown function, rolling on a plane) are refused with the reason."""

from __future__ import annotations

import re
from pathlib import Path

import yaml

from benchmarks.neighbours.scene import Body, Coord, Param, Part, Question, Scene, Spring, Support

UNITS = {"kg": "1", "g": "1/1000", "m": "1", "cm": "1/100", "mm": "1/1000", "s": "1", "deg": "pi/180",
         "°": "pi/180", "rad": "1", "rev": "2*pi", "min": "60", "rpm": "2*pi/60", "N": "1", "Hz": "2*pi"}


class Unmodelled(Exception):
    """The oracle has no model of this problem (the reason)."""


def si(text) -> str:
    """A value as written (``'30 cm'``, ``'120 rev/min'``, ``'9.81 m/s^2'``) in SI."""
    s = str(text).strip()
    m = re.match(r"^([-+*/().\w\s]*?\d[\w./*()+-]*|pi/\d+|\w+)\s*([A-Za-z°][\w*/^°]*)?$", s)
    num, unit = (m.group(1), m.group(2)) if m else (s, None)
    if unit is None or unit in ("pi",):
        return s
    factor = "1"
    for i, part in enumerate(re.split(r"(/|\*)", unit)):
        if part in ("*", "/", ""):
            continue
        sign = "/" if "/" + part in unit and unit.split(part)[0].endswith("/") else "*"
        name, _, power = part.partition("^")
        if name not in UNITS:
            raise Unmodelled(f"unit {name!r}")
        term = f"({UNITS[name]})" + (f"**{power}" if power else "")
        factor = f"{factor}{sign}{term}"
    return f"({num})*{factor}"


def _vec(v) -> str:
    return "[" + ", ".join(str(x) for x in v) + "]" if isinstance(v, list) else str(v)


AXES = {"x": (1, 0, 0), "y": (0, 1, 0), "z": (0, 0, 1), "-x": (-1, 0, 0), "-y": (0, -1, 0), "-z": (0, 0, -1)}

# Bodies placed by a contact: the generator's own geometry (docs/format.md's conventions).
PLACED = {
    "ball-in-bowl": {"ball": ("(R - r)*[sin(theta), -cos(theta)]", "-(R - r)*theta/r")},
    "cylinder-in-cylinder": {"cylinder": ("(R - r)*[sin(theta), -cos(theta)]", "-(R - r)*theta/r")},
    "weighted-disk-in-track": {"wheel": ("2*r*[sin(phi), -cos(phi)]", "-2*phi")},  # inside a track of radius 3 r
    "ring-on-drum": {"ring": ("(R + r)*[-sin(theta), cos(theta)]", "(R + r)*theta/r")},
    "wheel-on-incline": {"wheel": ("x*[cos(alpha), -sin(alpha)] + r*[sin(alpha), cos(alpha)]", "-x/r")},
    "yo-yo": {"yoyo": ("[r, -y]", "-y/r")},
    "half-disk-rocking": {"half": ("[-R*theta, R]", "theta")},
    "hemisphere-rocking": {"dome": ("[-R*theta, R]", "theta")},
    "slab-on-drum": {"slab": ("(R + a/2)*[-sin(theta), cos(theta)] + R*theta*[cos(theta), sin(theta)]", "theta")},
    "cylinder-on-plank": {"cylinder": ("[x + s, h + r]", "-s/r")},
    "disk-on-turning-disk": {"disk": ("(R + r)*[-sin(theta), cos(theta)]", "psi + (R + r)*(theta - psi)/r")},
    "cylinder-pulley-block": {"cylinder": ("[x, r]", "-x/r"), "block": ("[d, 2*r - d - 2*x]", None)},
    "incline-30-deg": {"wheel": ("x*[cos(alpha), -sin(alpha)] + r*[sin(alpha), cos(alpha)]", "-x/r")},
    "spool-released": {"spool": ("[b, -y]", "-y/b")},     # the string leaves the hub on the left
    "maxwell-wheel": {"wheel": ("[r, -y]", "-y/r")},      # the string on the axle, radius r
    "slab-released": {"slab": ("(R + a/2)*[-sin(theta), cos(theta)] + R*theta*[cos(theta), sin(theta)]", "theta")},
    "half-disk-about-contact": {"half": ("[-R*theta, R]", "theta")},
    "half-ring-with-particle": {"rocker": ("[-R*theta, R]", "theta")},
    # rolling inside the turning ring: r φ̇ = R ψ̇ − (R − r) θ̇ (no slip at the contact, θ in the scene)
    "ring-and-disk-inside": {"disk": ("(R - r)*[sin(theta), -cos(theta)]", "(R*psi - (R - r)*theta)/r")},
    # a circle of radius r rolling on the drum's top turned by θ: its centre at the angle
    # φ = r θ/(R + r) round the drum (arcs R φ = r (θ − φ))
    "half-disk-on-drum": {"half": ("(R + r)*[-sin(r*theta/(R + r)), cos(r*theta/(R + r))]", "theta")},
    "disk-leaves-drum-spring": {"disk": ("(R + r)*[-sin(theta), cos(theta)]", "(R + r)*theta/r")},
}
SUPPORTS = {  # the contacts' supports, for reactions
    "wheel-on-incline": [Support("C", "wheel", "x*[cos(alpha), -sin(alpha)]", "rolling", normal="[sin(alpha), cos(alpha)]")],
    "yo-yo": [Support("S", "yoyo", "[0, -y]", "string", normal="[0, 1]")],
    "incline-30-deg": [Support("C", "wheel", "x*[cos(alpha), -sin(alpha)]", "rolling", normal="[sin(alpha), cos(alpha)]")],
    "spool-released": [Support("S", "spool", "[0, -y]", "string", normal="[0, 1]")],
    "slab-released": [Support("C", "slab", "R*[-sin(theta), cos(theta)]", "rolling", normal="[-sin(theta), cos(theta)]")],
    "particle-on-sphere": [Support("P", "particle", "P", "guide", normal="P/norm(P)")],
    "bead-in-loop-on-spring": [Support("P", "bead", "P", "guide", normal="-P/norm(P)")],  # the loop pushes inwards
    "particle-inside-track-released": [Support("P", "particle", "P", "guide", normal="-P/norm(P)")],  # so does the track
    "disk-leaves-drum-spring": [Support("C", "disk", "R*[-sin(theta), cos(theta)]", "rolling",
                                        normal="[-sin(theta), cos(theta)]")],
    "rod-pivot-released": [Support("O", "rod", "O", "pivot")],
    "rod-hinge-force-at-the-bottom": [Support("O", "rod", "O", "pivot")],
}
SUPPORTS.update({name: [Support("A", "ladder", "A", "guide", normal="[0, 1]"),  # the floor pushes up,
                        Support("B", "ladder", "B", "guide", normal="[1, 0]")]   # the wall at x = 0 to the right
                 for name in ("ladder-released", "ladder-angle-from-floor", "ladder-load-at-top")})
SUPPORTS.update({name: [Support("O", "rod", "[0, 0]", "pivot")]
                 for name in ("ball-hits-pinned-rod", "bullet-embeds-in-hanging-rod", "pendulum-struck")})
SUPPORTS["plate-struck-by-ball"] = [Support("O", "plate", "[0, 0]", "pivot")]
CONTACT_POINTS = {"half-disk-about-contact": {"C": "[-R*theta, 0]"}}  # a contact asked about, as a point
ASSUMED = {"ball-in-bowl": ("R > r",), "cylinder-in-cylinder": ("R > r",), "ring-and-disk-inside": ("R > r",)}  # implied by rolling inside
DOMAINS = {"half-disk-rocking": ("-pi/2", "pi/2"), "hemisphere-rocking": ("-pi/2", "pi/2"),
           "slab-on-drum": ("-b/(2*R)", "b/(2*R)"), "slab-released": ("-b/(2*R)", "b/(2*R)"),
           "half-disk-about-contact": ("-pi/2", "pi/2"),
           "half-ring-with-particle": ("-pi/2", "pi/2"),
           # the contact stays on the curved edge while θ + φ < π/2
           "half-disk-on-drum": ("-pi/2*(R + r)/(R + 2*r)", "pi/2*(R + r)/(R + 2*r)")}


def scene(path: Path) -> Scene:
    doc = yaml.safe_load(path.read_text())
    name = path.stem
    for key in ("triads", "unknowns"):
        if key in doc:
            raise Unmodelled(f"'{key}' (3D steady motion)")
    if any(isinstance(v, dict) and "velocity" in v for v in (doc.get("points") or {}).values()):
        raise Unmodelled("a scene at one instant (velocities)")
    if any(v == "unknown" for v in (doc.get("prescribed") or {}).values()):
        raise Unmodelled("a prescribed unknown function of time")
    contacts = doc.get("contacts") or {}
    if any("plane" in str(c.get("rolls_on", "")) for c in contacts.values()):
        raise Unmodelled("rolling on a plane in 3D")
    if "forces" in doc or "couples" in doc:
        raise Unmodelled("applied forces and couples (the converter reads no loads)")
    if any(isinstance(b, dict) and "points" in b for b in (doc.get("bodies") or {}).values()):
        raise Unmodelled("a body's own points (the converter reads the scene's points only)")
    placed = {c.get("body") for c in contacts.values() if isinstance(c, dict) and c.get("body")}
    if placed - set(PLACED.get(name, {})):
        raise Unmodelled("a body placed by a contact with no placement written by hand in PLACED")
    params = []
    raw = doc.get("parameters") or {}
    values = doc.get("values") or {}
    for p in (raw if isinstance(raw, dict) else {n: "" for n in raw}):
        v = values.get(p)
        if isinstance(v, dict):
            v = None  # a range for variants: symbolic
        params.append(Param(p, "length", None if v is None else str(v), None if v is None else si(v), 0.5, 2.0,
                            not (isinstance(raw, dict) and isinstance(raw[p], dict) and raw[p].get("positive") is False)))
    coords = _coords(doc.get("coordinates") or [], name)
    points = {k: _vec(v) for k, v in (doc.get("points") or {}).items()} | CONTACT_POINTS.get(name, {})
    for k, v in (doc.get("prescribed") or {}).items():
        points = {p: re.sub(rf"\b{k}\b", f"({v})", e) for p, e in points.items()}
    bodies = [_body(n, b, PLACED.get(name, {})) for n, b in (doc.get("bodies") or {}).items()]
    centres = {b["at"]: n for n, b in (doc.get("bodies") or {}).items() if isinstance(b, dict)
               and isinstance(b.get("at"), str)}
    # a spring's end may name a body (its centre): where the body is placed (``at``, or PLACED)
    placed_at = {n: PLACED[name][n][0] for n in PLACED.get(name, {})} | {
        n: _vec(b["at"]) for n, b in (doc.get("bodies") or {}).items() if isinstance(b, dict) and "at" in b}
    springs = [_spring(n, s, centres, placed_at) for n, s in (doc.get("springs") or {}).items()]
    questions = [Question(*(next(iter(q.items())) if isinstance(q, dict) else (q, {}))) for q in doc["questions"]]
    planar = all(len(str(_vec(v)).split(",")) < 3 for v in (doc.get("points") or {}).values()) and "gravity" not in doc \
        or len(str(doc.get("gravity", "[0, -g]")).split(",")) < 3
    assumptions = tuple(doc.get("assumptions") or ()) + ASSUMED.get(name, ())
    return Scene("problems", name, (), path.read_text(), params, coords, questions, _vec(doc["gravity"]) if "gravity" in doc else None,
                 points, bodies, springs, SUPPORTS.get(name, []), [], assumptions, planar=planar)


def _coords(c, name) -> list[Coord]:
    out = []
    items = c.items() if isinstance(c, dict) else [(n, None) for n in c]
    for n, spec in items:
        kind = spec if isinstance(spec, str) else (spec or {}).get("kind", "angle") if isinstance(spec, dict) else "angle"
        periodic = not isinstance(spec, dict) or spec.get("periodic", True)
        rng = spec.get("range") if isinstance(spec, dict) else None
        if kind == "length" or (kind == "auto" and n in ("x", "y", "s", "r")):
            out.append(Coord(n, "length", False, *(map(str, rng) if rng else ("-10", "10"))))
        elif not periodic:
            out.append(Coord(n, "angle", False, *(map(str, rng) if rng else ("-10*pi", "10*pi"))))
        elif name in DOMAINS:
            out.append(Coord(n, "angle", False, *DOMAINS[name]))
        else:
            out.append(Coord(n, "length" if n in ("x", "y", "s") else "angle", n not in ("x", "y", "s"),
                             *(("-10", "10") if n in ("x", "y", "s") else (None, None))))
    return out


def _dims(b: dict) -> dict:
    skip = {"shape", "mass", "at", "angle", "axis", "inertia", "parts", "orientation", "hole", "velocity",
            "angular_velocity"}
    return {k: str(v) for k, v in b.items() if k not in skip}


def _axis(v):
    if v is None:
        return None
    if isinstance(v, str) and v in AXES:
        return AXES[v]
    return tuple(float(x) for x in v)


def _body(name: str, b: dict, placed: dict) -> Body:
    origin, angle = placed.get(name, (None, None))
    turns = None
    if "orientation" in b:
        turns = tuple((str(ax), str(a)) for ax, a in b["orientation"])
    body = Body(name, str(b.get("mass", "0")), b.get("shape"), _dims(b), _axis(b.get("axis")),
                origin=origin or _vec(b.get("at", "[0, 0]")), angle=angle if origin else (str(b["angle"]) if "angle" in b else None),
                turns=turns)
    if "inertia" in b:
        inertia = b["inertia"]
        body.inertia = str(inertia) if not isinstance(inertia, list) else tuple(str(x) for x in inertia)
    if "parts" in b:
        body.parts = tuple(Part(p.get("shape"), str(p["mass"]), _dims(p), tuple(str(x) for x in p.get("at", [0, 0, 0])),
                                _axis(p.get("axis")), p.get("inertia"), bool(p.get("hole"))) for p in b["parts"].values())
    return body


def _spring(name: str, s: dict, centres: dict, placed_at: dict) -> Spring:
    """A spring, each end on the body whose centre (``at``) it names, or the body it
    names (at its centre, ``placed_at``), else on the ground (the oracle's reactions
    apply its force to that body: oracle/reactions.py)."""
    if "angle" in s:
        return Spring(name, str(s["stiffness"]), angle=str(s["angle"]), rest=str(s.get("rest", 0)))
    a, b = s["between"]
    ends = tuple(placed_at[e] if isinstance(e, str) and e in placed_at else _vec(e) for e in (a, b))
    on = tuple((e if e in placed_at else centres.get(e)) if isinstance(e, str) else None for e in (a, b))
    return Spring(name, str(s["stiffness"]), ends=ends, on=on,
                  natural_length=str(s.get("natural_length", 0)))
