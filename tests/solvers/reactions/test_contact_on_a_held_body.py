"""A contact on another body's edge pushes back on that body (Newton's third law): where
that body is held too, its balance has the contact's push and friction (a new user's
plank pulled from under a rolling cylinder, the plank on the floor, was refused: "the
forces asked for cannot keep body 'plank' in its motion").

By hand: the plank (M) slides on a smooth floor under the pull F; the cylinder (m, r)
rolls on it without slipping, s its contact's travel along the plank, φ̇ = −ṡ/r. F_C is
the friction on the cylinder along −x, and on the plank along +x. Cylinder: m (ẍ + s̈) =
−F_C, N_C = m g, and about its centre ½ m r² φ̈ = −r F_C, so F_C = ½ m s̈. Plank:
M ẍ = F + F_C. Solved: ẍ = 3F/(3M + m), s̈ = −2F/(3M + m), F_C = −m F/(3M + m), and the
floor's push on the plank N_P = (M + m) g."""

from __future__ import annotations

import json

from click.testing import CliRunner

from rbdsolve.cli import main

from conftest import same

PLANK = """title: a plank pulled from under a rolling cylinder
parameters: {M: plank, L: length, h: thickness, m: cylinder, r: radius, F: pull, g: gravity}
coordinates: [x, s]
gravity: [0, -g]
points:
  P: [x, h/2]
bodies:
  plank: {shape: plate, mass: M, width: L, height: h, at: P}
  cylinder: {shape: cylinder, mass: m, radius: r, height: 1}
contacts:
  C: {body: cylinder, rolls_on: {body: plank, edge: top}, along: s}
forces:
  pull: {on: plank, force: [F, 0]}
questions:
  - reactions: {forces: [C, {at: P, on: plank, normal: [0, 1]}], at: {x: 0, s: 0, dot(x): 0, dot(s): 0}}
"""


def test_the_plank_s_floor_carries_both(tmp_path) -> None:
    path = tmp_path / "p.yaml"
    path.write_text(PLANK, encoding="utf-8")
    out = CliRunner().invoke(main, ["solve", str(path), "--format", "json"])
    assert out.exit_code == 0, out.output
    at = json.loads(out.stdout)["results"][0]["answers"]["at"]
    assert same(at["C"]["components"]["F_C"], "-F*m/(3*M + m)")
    assert same(at["C"]["components"]["N_C"], "g*m")
    assert same(at["P"]["components"]["N_P"], "g*(M + m)")
