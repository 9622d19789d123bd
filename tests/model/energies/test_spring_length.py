"""A spring's length without |…| where its sign is known (issue 38): an exam writes a
spring from the wall at −d to a cart at x as d + x, and V = ½ k (d + x − l₀)², never
|d + x|, sign(d + x) or DiracDelta(d + x). Where the sign is not known, |…| stays and
the model section says why, in words. Expected values by hand in each test.
"""

from __future__ import annotations

import sympy as sp

from conftest import PROBLEMS
from rbdsolve.model.build import build_model
from rbdsolve.model.energies.energy import potential_energy
from rbdsolve.model.energies.spring_length import without_deltas
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem

CART = (PROBLEMS / "examples" / "cart-between-springs.yaml").read_text()

# One spring from the anchor A = (h, 0) to a cart at (l + x, 0): its length at x = 0 is
# l − h, of a sign nothing decides.
OFFSET = """\
parameters: {m: mass, k: stiffness, h: anchor, l: reference position, l0: natural length}
coordinates: [x]
points:
  A: [h, 0]
  P: [l + x, 0]
bodies:
  cart: {shape: particle, mass: m, at: P}
springs:
  s: {stiffness: k, between: [A, P], natural_length: l0}
questions:
  - eom
"""

SIGNS = (sp.Abs, sp.sign, sp.DiracDelta)


def _model(text: str):
    return build_model(load_text(text, "scene.yaml"))


def _symbols(model, names: str):
    return [model.symbols.parameters[n] for n in names.split()]


def test_two_springs_on_a_cart_have_lengths_d_plus_x_and_d_minus_x() -> None:
    model = _model(CART)
    k, d, l0 = _symbols(model, "k d l0")
    (x,) = model.q
    V = potential_energy(model).total
    assert not V.has(*SIGNS)
    assert sp.expand(V - (k * (d + x - l0) ** 2 / 2 + k * (d - x - l0) ** 2 / 2)) == 0
    report = solve_problem(model)
    eom, equilibria, modes = report.solutions
    assert not any(s.has(*SIGNS) for s in eom.answers.equations)
    (equilibrium,) = equilibria.answers.equilibria
    assert equilibrium.at["x"] == 0 and equilibrium.stability.value == "stable"
    assert sp.simplify(modes.answers.eigenvalues[0] - 2 * k / model.symbols.parameters["m"]) == 0
    assert not any("its length is |" in step.text for step in report.model.steps)


def test_a_spring_whose_sign_is_not_known_keeps_its_bars_and_says_why() -> None:
    report = solve_problem(_model(OFFSET))
    (note,) = [step for step in report.model.steps if "its length is |" in step.text]
    assert "l − h + x where l − h + x > 0" in note.text and "[l > h]" in note.text
    (equation,) = report.solutions[0].answers.equations
    assert equation.has(sp.sign)  # two cases, as the note says


def test_an_assumption_decides_the_sign_either_way() -> None:
    """[l > h + l0]: the length is l − h + x; [h > l]: it is h − l − x."""
    for assumption, length in (("[l > h + l0]", lambda l, h, x: l - h + x), ("[h > l]", lambda l, h, x: h - l - x)):
        model = _model(OFFSET.replace("coordinates:", f"assumptions: {assumption}\ncoordinates:"))
        k, h, l, l0 = _symbols(model, "k h l l0")
        (x,) = model.q
        V = potential_energy(model).total
        assert sp.expand(V - k * (length(l, h, x) - l0) ** 2 / 2) == 0


def test_a_spring_through_zero_length_is_refused_by_modes_with_a_reason() -> None:
    """The anchor at the cart's reference point: the length |x| is zero at x = 0, where V
    = ½ k (|x| − l₀)² has no second derivative."""
    text = OFFSET.replace("A: [h, 0]", "A: [0, 0]").replace("P: [l + x, 0]", "P: [x, 0]")
    text = text.replace("  - eom\n", "  - eom\n  - modes: {about: {x: 0}}\n")
    report = solve_problem(_model(text))
    (note,) = [step for step in report.model.steps if "its length is |" in step.text]
    assert "zero at x = 0" in note.text
    assert "give x a range on one side of 0 to take that side, such as 'x: {kind: length, range: [0, …]}'" \
        in note.text
    modes = report.solutions[1]
    assert not modes.solved and "does not exist at this configuration" in modes.error


def test_no_delta_in_K_where_the_spring_has_a_length() -> None:
    """A cart at x on a spring from the wall at −h, natural length 2h: the length h + x
    (positive at x = 0), V = ½ k (x − h)², the equilibrium x = h with K = k (by hand),
    where |h + x| gave K = k (1 − 2h DiracDelta(…))."""
    text = OFFSET.replace("A: [h, 0]", "A: [-h, 0]").replace("P: [l + x, 0]", "P: [x, 0]")
    text = text.replace("natural_length: l0", "natural_length: 2*h").replace("  - eom\n", "  - equilibria\n  - modes\n")
    model = _model(text)
    k, h, m = _symbols(model, "k h m")
    equilibria, modes = solve_problem(model).solutions
    (equilibrium,) = equilibria.answers.equilibria
    assert sp.simplify(equilibrium.at["x"] - h) == 0 and equilibrium.hessian == sp.Matrix([[k]])
    assert sp.simplify(modes.answers.frequencies[0] - sp.sqrt(k / m)) == 0


def test_without_deltas_keeps_only_a_delta_at_zero() -> None:
    k, h, l = sp.symbols("k h l", positive=True)
    K = sp.Matrix([[k * (1 - 2 * h * sp.DiracDelta(h - l))]])
    assert without_deltas(K) == sp.Matrix([[k]])
    assert without_deltas(sp.Matrix([[k * sp.DiracDelta(0)]])).has(sp.DiracDelta)


def test_a_spring_pull_in_a_free_body_diagram_has_no_bars() -> None:
    """The cart's springs pull it with −k (d + x − l₀) and k (d − x − l₀) along x."""
    text = CART.replace("  - eom\n  - equilibria\n  - modes: {about: {x: 0}}\n",
                        "  - reactions: {forces: [P], at: {x: 0, dot(x): 0}}\n")
    text = text.replace("coordinates: [x]", "coordinates: [x]\ngravity: [0, -g]").replace(
        "  l0: natural length of each spring\n", "  l0: natural length of each spring\n  g: gravity\n")
    report = solve_problem(_model(text))
    (solution,) = report.solutions
    assert solution.solved, solution.error
    pulls = [m for step in solution.steps for m in step.math if getattr(m, "lhs", None) is not None]
    assert not any(sp.sympify(m.rhs).has(*SIGNS) if isinstance(m.rhs, sp.Basic) else False for m in pulls)
    (said,) = [step.text for step in solution.steps if "spring 'left' pulls" in step.text]
    assert "(−k (d − l₀ + x), 0)" in said and "(k (d − l₀ − x), 0)" in said and "|" not in said


# A block at x along a slope at α, a spring from it up the slope to the point d along it:
# d·d = (d − x)² (cos² α + sin² α), a square once sin² + cos² are joined.
SLOPE = """\
parameters: {m: mass, k: stiffness, d: anchor distance, l0: natural length, alpha: slope}
coordinates: [x]
points:
  A: "d*[cos(alpha), sin(alpha)]"
  P: "x*[cos(alpha), sin(alpha)]"
bodies:
  block: {shape: particle, mass: m, at: P}
springs:
  s: {stiffness: k, between: [A, P], natural_length: l0}
questions:
  - eom
"""


def test_a_spring_along_a_slope_is_written_d_minus_x() -> None:
    """By hand: |A − P| = |d − x|, d − x > 0 at x = 0 (d > 0), so V = ½ k (d − x − l₀)²,
    ∂V/∂x = −k (d − x − l₀), with no root or |…| left."""
    model = _model(SLOPE)
    V = potential_energy(model).total
    (x,) = model.q
    k, d, l0 = (model.symbols.parameters[n] for n in ("k", "d", "l0"))
    assert not V.has(*SIGNS) and not any(p.exp == sp.S.Half for p in V.atoms(sp.Pow))
    assert sp.simplify(sp.diff(V, x) + k * (d - x - l0)) == 0


def test_a_declared_range_decides_the_sign_of_a_length_linear_in_its_coordinate() -> None:
    """u linear in q keeps one sign between its values at the range's ends (by hand):
    r on [0, 10 L] is ≥ 0 with r > 0 inside, so |r| = r; −r there is −|r|; r − L changes
    sign inside (undecided); r² is not linear (left to the other rules)."""
    from rbdsolve.model.energies.spring_length import _sign_over

    r, L = sp.Symbol("r", real=True), sp.Symbol("L", positive=True)
    ranges = {r: (sp.Integer(0), 10 * L)}
    assert _sign_over(r, ranges, {}) == 1
    assert _sign_over(-r, ranges, {}) == -1
    assert _sign_over(r - L, ranges, {}) is None
    assert _sign_over(r**2 + 1, ranges, {}) is None
    assert _sign_over(r, {}, {}) is None  # no range declared: nothing decided here
    assert _sign_over(r + 1, {r: (-sp.Integer(1), sp.Integer(2))}, {}) == 1  # zero only at the low end


def test_a_collar_on_a_turning_rod_with_its_range_has_no_bars() -> None:
    """The spring from the axis to a collar at r ∈ [0, 10 L]: V = ½ k (L − r)² (by hand),
    no |r| and no sign(r) in the equations."""
    model = build_model(load_text((PROBLEMS / "frames" / "collar-on-horizontal-turning-rod.yaml").read_text()))
    V = potential_energy(model).total
    r, L, k = (model.symbols.parameters.get(n) or dict(zip(model.symbols.state.names, model.q))[n] for n in "rLk")
    assert not V.has(sp.Abs) and sp.simplify(V - k * (L - r) ** 2 / 2) == 0


# Issue 43, the neighbours' elastic pendulum: r in P = r (sin θ, −cos θ) is a polar
# distance ((−r, θ) is (r, θ + π)), so r ≥ 0 and its spring's |r| = r, as a declared range
# [0, …] says; an end-to-end vector that is not a unit vector times r, or whose direction
# does not reverse at θ + π, is no polar distance.
def test_a_polar_distance_is_nonnegative() -> None:
    from rbdsolve.model.energies.spring_length import polar_distances

    r, th, ph, a = sp.symbols("r theta phi a", real=True)
    assert polar_distances(sp.Matrix([r * sp.sin(th), -r * sp.cos(th)]), (r, th)) == {r: (0, sp.oo)}
    spherical = r * sp.Matrix([sp.sin(th) * sp.cos(ph), sp.sin(th) * sp.sin(ph), sp.cos(th)])
    assert set(polar_distances(spherical, (r, th, ph))) == {r}  # θ + π reverses it
    assert polar_distances(sp.Matrix([r * sp.sin(th), 2 * r * sp.cos(th)]), (r, th)) == {}  # not a unit vector
    assert polar_distances(sp.Matrix([r * sp.sin(th), -r * sp.cos(th) + 1]), (r, th)) == {}  # not r times one
    assert polar_distances(sp.Matrix([r * sp.sin(a), -r * sp.cos(a)]), (r,)) == {}  # a fixed direction: r of either sign
    assert polar_distances(sp.Matrix([r, 0]), (r, th)) == {}  # [r, 0]: no turn


def test_the_elastic_pendulums_spring_is_written_r_minus_L() -> None:
    from rbdsolve.model.build import build_model
    from rbdsolve.problem import load_text

    model = build_model(load_text("""
parameters: {m: mass, k: stiffness, L: natural length, g: gravity}
coordinates: [r, theta]
gravity: [0, -g]
points: {O: "[0, 0]", P: "r*[sin(theta), -cos(theta)]"}
bodies: {bob: {shape: particle, mass: m, at: P}}
springs: {s: {stiffness: k, between: [O, P], natural_length: L}}
questions: [eom]
""", "elastic.yaml"))
    r = model.q[0]
    L = model.symbols.parameters["L"]
    assert sp.expand(model.springs[0].stretch - (r - L)) == 0


HALF_ANGLE = """title: a rod hinged on a wall, a spring from its end to the wall 2a above the hinge
parameters: {m: mass, a: half length, k: stiffness, g: acceleration of gravity}
coordinates: [u]
gravity: [0, -g]
points:
  B: 2*a*[sin(2*u), cos(2*u)]
  C: [0, 2*a]
bodies:
  rod: {shape: rod, mass: m, length: 2*a, at: B/2, angle: 2*u, axis: y}
springs:
  s: {stiffness: k, between: [B, C], natural_length: a}
questions:
  - eom
"""


def test_the_note_gives_the_whole_length_not_only_what_is_under_the_bars() -> None:
    """|B − C|² = 4 a² (sin² 2u + (cos 2u − 1)²) = 8 a² (1 − cos 2u) = 16 a² sin² u: the
    length is 4 a |sin(u)|, zero at u = 0 (it was said to be |sin(u)|)."""
    report = solve_problem(_model(HALF_ANGLE))
    (note,) = [step for step in report.model.steps if "its length is" in step.text]
    assert "its length is 4 a |sin(u)|, which is 4 a sin(u) where sin(u) > 0 and −4 a sin(u) where" in note.text


def test_the_range_the_note_suggests_takes_one_side() -> None:
    """The note's own remedy, x in [0, 10 l0]: the length |x| is x, V = ½ k (x − l₀)², and
    the equilibrium x = l₀ with K = k (by hand)."""
    text = OFFSET.replace("A: [h, 0]", "A: [0, 0]").replace("P: [l + x, 0]", "P: [x, 0]")
    text = text.replace("coordinates: [x]", "coordinates: {x: {kind: length, range: [0, 10*l0]}}")
    text = text.replace("  - eom\n", "  - equilibria\n")
    model = _model(text)
    k, l0 = _symbols(model, "k l0")
    (x,) = model.q
    assert sp.expand(potential_energy(model).total - k * (x - l0) ** 2 / 2) == 0
    report = solve_problem(model)
    assert not any("its length is |" in step.text for step in report.model.steps)
    (equilibrium,) = report.solutions[0].answers.equilibria
    assert equilibrium.at["x"] == l0 and equilibrium.hessian == sp.Matrix([[k]])
