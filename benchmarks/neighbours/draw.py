"""Values as exams write them, drawn from tables: each with the text the file gets
(``'20 cm'``, ``'30 deg'``, ``'pi/6'``, ``'9.81 m/s^2'``) and its exact SI value
(``'1/5'``, ``'pi/6'``), which the oracle uses; or no value (a symbolic parameter,
which the oracle samples in a range)."""

from __future__ import annotations

import numpy as np

from benchmarks.neighbours.scene import Param

TABLES: dict[str, list[tuple[str, str]]] = {
    "mass": [("2 kg", "2"), ("500 g", "1/2"), ("3", "3"), ("1.5 kg", "3/2"), ("200 g", "1/5"), ("4", "4"),
             ("1", "1"), ("800 g", "4/5"), ("5 kg", "5")],
    "length": [("30 cm", "3/10"), ("1 m", "1"), ("0.5", "1/2"), ("2", "2"), ("40 cm", "2/5"), ("1.2 m", "6/5"),
               ("3/2", "3/2"), ("80 cm", "4/5"), ("25 cm", "1/4"), ("60 cm", "3/5")],
    "accel": [("9.81 m/s^2", "981/100"), ("9.81", "981/100"), ("10", "10"), ("9.8 m/s^2", "49/5")],
    "angle": [("30 deg", "pi/6"), ("pi/6", "pi/6"), ("45 deg", "pi/4"), ("pi/4", "pi/4"), ("60°", "pi/3"),
              ("20 deg", "pi/9"), ("pi/3", "pi/3")],
    "stiffness": [("200 N/m", "200"), ("50", "50"), ("120 N/m", "120"), ("80", "80"), ("1000 N/m", "1000")],
    "torsion": [("2 N*m/rad", "2"), ("5", "5"), ("1/2 N*m/rad", "1/2"), ("10 N*m/rad", "10")],
    "rate": [("3 rad/s", "3"), ("60 rev/min", "2*pi"), ("2", "2"), ("5 rad/s", "5"), ("120 rpm", "4*pi")],
    "speed": [("5 m/s", "5"), ("2", "2"), ("3 m/s", "3"), ("10 m/s", "10")],
    "impulse": [("2 N*s", "2"), ("1", "1"), ("1/2", "1/2")],
    "ratio": [("1/2", "1/2"), ("0.8", "4/5"), ("2/3", "2/3"), ("1/3", "1/3")],
    "inertia": [("0.05 kg*m^2", "1/20"), ("1/10", "1/10"), ("2", "2")],
}
SMALL = [("20 cm", "1/5"), ("0.3", "3/10"), ("25 cm", "1/4"), ("0.4", "2/5"), ("10 cm", "1/10")]  # a wheel's radius
LARGE = [("1 m", "1"), ("1.2 m", "6/5"), ("2", "2"), ("1.5", "3/2"), ("80 cm", "4/5")]  # a circle it rolls in

SAMPLE = {"mass": (0.5, 3.0), "length": (0.3, 2.0), "accel": (5.0, 12.0), "angle": (0.2, 1.2),
          "stiffness": (20.0, 200.0), "torsion": (1.0, 20.0), "rate": (1.0, 6.0), "speed": (1.0, 6.0),
          "impulse": (0.5, 3.0), "ratio": (0.2, 0.9), "inertia": (0.05, 2.0)}


class Draw:
    """The random choices of one scene (numpy's default_rng of the seed and the index)."""

    def __init__(self, seed: int, index: int):
        self.rng = np.random.default_rng([seed, index])
        self.mode = self.choice(["numbers", "symbols", "mixed"], p=[0.4, 0.35, 0.25])

    def choice(self, options, p=None):
        i = self.rng.choice(len(options), p=p)
        return options[i]

    def chance(self, p: float) -> bool:
        return bool(self.rng.random() < p)

    def integer(self, low: int, high: int) -> int:
        return int(self.rng.integers(low, high + 1))

    def param(self, name: str, kind: str, description: str = "", symbolic: bool | None = None,
              table: list[tuple[str, str]] | None = None, low: float | None = None, high: float | None = None,
              positive: bool = True) -> Param:
        """A parameter, with a value from the kind's table unless drawn symbolic (the
        scene's mode: all numbers, all symbols, or each by chance)."""
        if symbolic is None:
            symbolic = {"numbers": False, "symbols": True}.get(self.mode, self.chance(0.5))
        lo, hi = SAMPLE.get(kind, (0.5, 2.0))
        lo, hi = (low if low is not None else lo), (high if high is not None else hi)
        if symbolic:
            return Param(name, kind, None, None, lo, hi, positive, description)
        text, si = self.choice(table or TABLES[kind])
        return Param(name, kind, text, si, lo, hi, positive, description)
