"""The scene families: one module per kind of exam problem, each with ``FAMILY`` (its
name) and ``generate(builder)``, which writes one scene with the builder's random
choices. A new family is a new module added to FAMILIES with its weight."""

from __future__ import annotations

from benchmarks.neighbours.draw import Draw
from benchmarks.neighbours.families import (chains, frames, future, impact, inertia, pendulum, rocking, rolling, spin,
                                             springs, steady, strings)
from benchmarks.neighbours.families.base import Builder
from benchmarks.neighbours.scene import Scene

# name -> (module, weight): how often the family is drawn
FAMILIES = {
    pendulum.FAMILY: (pendulum, 3.0),
    rolling.FAMILY: (rolling, 2.0),
    rocking.FAMILY: (rocking, 1.5),
    strings.FAMILY: (strings, 1.5),
    chains.FAMILY: (chains, 2.0),
    springs.FAMILY: (springs, 1.5),
    frames.FAMILY: (frames, 1.5),
    impact.FAMILY: (impact, 1.5),
    inertia.FAMILY: (inertia, 1.0),
    spin.FAMILY: (spin, 0.7),
    future.FAMILY: (future, 0.7),
    steady.FAMILY: (steady, 0.7),
}


def generate(seed: int, index: int, only: tuple[str, ...] = ()) -> Scene:
    """Scene ``index`` of the run with ``seed``: the same whatever else is generated."""
    draw = Draw(seed, index)
    names = [n for n in FAMILIES if not only or n in only]
    weights = [FAMILIES[n][1] for n in names]
    total = sum(weights)
    name = draw.choice(names, p=[w / total for w in weights])
    module = FAMILIES[name][0]
    b = Builder(draw, name, "", "")
    module.generate(b)
    if not b.title:
        b.title = f"{name} {b.variant} (neighbour {index} of seed {seed})"
    scene = b.scene()
    scene.index, scene.seed = index, seed
    return scene
