"""The neighbours oracle (benchmarks/neighbours/) is right where the answers are known:
it agrees with every expected answer in problems/ that it can model (the expected files
are derived by hand, not by rbdsolve), and with textbook results. These tests never
run rbdsolve: they judge the expected answers, and the oracle's own numbers."""

from __future__ import annotations

from pathlib import Path

import mpmath
import numpy as np
import pytest
import yaml

from benchmarks.neighbours.check import judge
from benchmarks.neighbours.expr import FLOAT, MP
from benchmarks.neighbours.from_problem import Unmodelled, scene
from benchmarks.neighbours.oracle.mechanics import System
from benchmarks.neighbours.oracle.reactions import support_forces
from benchmarks.neighbours.oracle.search import equilibria, stability
from benchmarks.neighbours.scene import Body, Coord, Param, Scene, Support

ROOT = Path(__file__).resolve().parents[2] / "problems"
PROBLEMS = sorted(p for p in ROOT.glob("*/*.yaml") if not p.name.endswith(".expected.yaml"))
# What the oracle does not model, by file (each refused by from_problem with its reason):
# 3D steady motions, scenes at one instant, a prescribed unknown, rolling on a plane,
# and, since the files of issue 40, applied loads, bodies' own points and bodies placed
# by a contact whose placement has not been written by hand in from_problem.PLACED.
UNMODELLED = {"heavy-top-precession-rates", "ball-struck-on-table", "heavy-top-euler-angles", "p2-rod-impact",
              "p3-rolling-ring", "p5-accelerated-pendulum", "heavy-top", "rolling-coin", "rolling-cone",
              "rod-on-turning-shaft", "disk-pinned-on-shaft", "rod-on-turning-arm", "gyroscope-gimbal", "sleeping-top", "hanging-top", "rod-conical-pendulum",
              "disk-on-tilted-axle-nutation", "plate-on-turning-shaft",
              # applied loads
              "cylinder-pulled", "disk-pulled-up-incline", "motor-on-pendulum", "rod-follower-force",
              "rod-pushed-sideways", "spool-pulled-at-angle", "spool-radius-of-gyration-pulled", "spool-pulled-off-top",
              "wheel-driven-by-couple",
              # bodies placed by a contact, no placement by hand yet
              "disk-in-turning-ring", "slab-on-drum-angle", "half-disk-on-incline",
              "spool-radius-of-gyration", "atwood-massive-pulley",
              "atwood-spring-below", "cylinder-on-plank-spring", "disk-on-incline-spring", "disk-spring-at-top",
              "incline-block-massive-pulley", "double-incline-massive-pulley", "stepped-pulley",
              "table-block-massive-pulley", "cylinder-massive-pulley-block",
              # a body's own points
              "inverted-rod-spring-at-point"}


# Files whose exact answers are partial by design, and say so (a warning): the oracle finds
# what they leave out (strict expected failures, as ORACLE_GAPS).
PARTIAL = {
    "double-pendulum-hinge-spring": "the hinge spring makes the equilibrium equations transcendental: the exact "
                                    "route lists the evident roots (0, 0), (π, π) and warns that others may exist; "
                                    "for a soft spring (c = 0.69 N·m/rad) the oracle finds one at (−2.90, 0.82)",
}


# Files the oracle models but cannot judge yet: its own gaps, not rbdsolve's (each an
# expected failure, strict, so the entry goes the day the oracle learns it).
ORACLE_GAPS = {
    "collar-on-horizontal-turning-rod": "the oracle takes the kink of V at r = 0 (the spring at zero length, the edge of "
                                        "the declared range, where ∂V/∂r jumps from k L to −k L) for an equilibrium: its "
                                        "central differences see ∂V/∂r = 0 there",
    "cylinder-precession": "the oracle's steady-spin check reads no 'steady_spins' answer of this form",
    "ball-sticks-to-turntable": "the oracle's impact matrix is singular for a particle sticking to a turning body",
    "pendulum-light-rod-torsion": "the oracle's guide (SUPPORTS) pushes along the light rod only; the rod also carries "
                                  "the torsion spring's couple to the particle as a force across it, which the oracle "
                                  "does not model (rbdsolve's N agrees with the hand's, test_golden)",
    "bob-on-offset-torsion-rod": "as pendulum-light-rod-torsion: a light rod's torsion spring, not in the oracle's supports",
}


def _as_results(path: Path) -> dict:
    """The expected file as if rbdsolve had printed it (exact strings; numbers alone as
    the numeric route's)."""
    expected = yaml.safe_load(path.with_name(path.stem + ".expected.yaml").read_text())
    doc = yaml.safe_load(path.read_text())
    results = []
    for r in expected["results"]:
        answers, values = r.get("answers") or {}, r.get("values") or {}
        route = "exact" if answers or not values else "numeric"
        results.append({"question": r["question"], "ok": True, "route": route,
                        "answers": answers if answers or not values else values, "values": values})
    return {"symbols": list(doc.get("parameters") or []), "results": results}


@pytest.mark.parametrize("path", PROBLEMS, ids=lambda p: f"{p.parent.name}/{p.stem}")
def test_the_oracle_agrees_with_the_expected_answers(path):
    try:
        sc = scene(path)
    except Unmodelled as exc:
        assert path.stem in UNMODELLED, f"{path.stem}: the oracle should model it ({exc})"
        return
    assert path.stem not in UNMODELLED
    out = judge(sc, _as_results(path))
    bad = [(q.kind, q.status, q.reason) for q in out.questions if q.status != "answered"]
    for known in (ORACLE_GAPS, PARTIAL):
        if path.stem in known:
            assert bad, f"{path.stem}: the oracle agrees with it now: take it out of its list"
            pytest.xfail(known[path.stem])
    assert not bad, bad


def test_a_missed_equilibrium_is_a_mismatch_unless_rbdsolve_said_its_list_is_partial():
    """The cylinder in a cylinder with θ = π left out of the equilibria: a mismatch; the
    same list with rbdsolve's warning that other equilibria may exist (the exact route's
    evident roots of a transcendental equation): refused, with that reason."""
    path = ROOT / "contacts" / "cylinder-in-cylinder.yaml"
    results = _as_results(path)
    k = [r["question"] for r in results["results"]].index("equilibria")
    results["results"][k]["answers"]["equilibria"] = results["results"][k]["answers"]["equilibria"][:1]
    missed = judge(scene(path), results).questions[k]
    assert (missed.status, missed.reason[:22]) == ("mismatch", "missed the equilibrium")
    results["results"][k]["warnings"] = [
        "the equilibrium equations are transcendental, not polynomial in sin, cos and the coordinates, and no "
        "closed form lists every root: … The exact route lists only the evident roots, where every term vanishes: "
        "θ = 0. Other equilibria may exist; the numeric route …"]
    partial = judge(scene(path), results).questions[k]
    assert (partial.status, partial.reason) == ("refused", "equilibria: the evident roots only (transcendental equations)")


# --- textbook cases ----------------------------------------------------------------------

def _system(params: dict, coords, bodies, gravity="[0, -g]", points=None, supports=(), ns=MP):
    sc = Scene("textbook", "", (), "", [Param(k, "length", str(v), str(v)) for k, v in params.items()],
               [Coord(*c) if isinstance(c, tuple) else Coord(c) for c in coords], [], gravity, points or {},
               bodies, [], list(supports))
    return System(sc, {k: mpmath.mpf(v) for k, v in params.items()}, ns), sc


def _omega2(s: System, q0) -> list[float]:
    from scipy.linalg import eigh
    K, _ = s.stiffness([mpmath.mpf(x) for x in q0])
    M = s.mass_matrix([mpmath.mpf(x) for x in q0])
    return sorted(eigh(np.array(K, float), np.array(M, float), eigvals_only=True))


P = {"m": 2, "l": 1.5, "g": 9.81}


def test_simple_pendulum_omega_squared_is_g_over_l():
    s, _ = _system(P, ["theta"], [Body("bob", "m", "particle", origin="l*[sin(theta), -cos(theta)]")])
    assert _omega2(s, [0]) == pytest.approx([9.81 / 1.5], rel=1e-12)


def test_physical_pendulum_of_a_rod_from_its_end():
    s, _ = _system(P, ["theta"], [Body("rod", "m", "rod", {"length": "l"}, (0, 1, 0),
                                       origin="l/2*[sin(theta), -cos(theta)]", angle="theta")])
    assert _omega2(s, [0]) == pytest.approx([3 * 9.81 / (2 * 1.5)], rel=1e-12)


def test_cylinder_rolling_down_an_incline_accelerates_at_two_thirds_g_sin_alpha():
    p = {"m": 3, "r": 0.4, "g": 9.81, "alpha": 0.5}
    s, _ = _system(p, [("x", "length", False)], [Body(
        "c", "m", "cylinder", {"radius": "r", "height": "1"},
        origin="x*[cos(alpha), -sin(alpha)] + r*[sin(alpha), cos(alpha)]", angle="-x/r")])
    (a,) = s.accelerations([mpmath.mpf("0.3")], [mpmath.mpf(1)])
    assert float(a) == pytest.approx(2 / 3 * 9.81 * np.sin(0.5), rel=1e-12)


def test_atwood_machine():
    p = {"m1": 3, "m2": 1, "g": 9.81}
    s, _ = _system(p, [("y", "length", False)], [Body("a", "m1", "particle", origin="[-1, -y]"),
                                                  Body("b", "m2", "particle", origin="[1, y]")])
    (a,) = s.accelerations([mpmath.mpf(0)], [mpmath.mpf(0)])
    assert float(a) == pytest.approx((3 - 1) * 9.81 / (3 + 1), rel=1e-12)


def test_cylinder_in_a_cylinder():
    p = {"m": 1, "r": 0.3, "R": 1.2, "g": 9.81}
    s, _ = _system(p, ["theta"], [Body("c", "m", "cylinder", {"radius": "r", "height": "1"},
                                       origin="(R - r)*[sin(theta), -cos(theta)]", angle="-(R - r)*theta/r")])
    assert _omega2(s, [0]) == pytest.approx([2 * 9.81 / (3 * (1.2 - 0.3))], rel=1e-12)


def test_ball_in_a_bowl_hemisphere_and_half_disk_rocking():
    ball, _ = _system({"m": 1, "r": 0.3, "R": 1.2, "g": 9.81}, ["theta"], [Body(
        "b", "m", "sphere", {"radius": "r"}, origin="(R - r)*[sin(theta), -cos(theta)]", angle="-(R - r)*theta/r")])
    assert _omega2(ball, [0]) == pytest.approx([5 * 9.81 / (7 * 0.9)], rel=1e-12)
    dome, _ = _system({"m": 1, "R": 0.5, "g": 9.81}, ["theta"], [Body(
        "d", "m", "hemisphere", {"radius": "R"}, (0, -1, 0), origin="[-R*theta, R]", angle="theta")])
    assert _omega2(dome, [0]) == pytest.approx([15 * 9.81 / (26 * 0.5)], rel=1e-10)
    half, _ = _system({"m": 1, "R": 0.5, "g": 9.81}, ["theta"], [Body(
        "h", "m", "half_disk", {"radius": "R"}, (0, -1, 0), origin="[-R*theta, R]", angle="theta")])
    assert _omega2(half, [0]) == pytest.approx([8 * 9.81 / ((9 * np.pi - 16) * 0.5)], rel=1e-10)


def test_particle_leaves_a_sphere_at_cos_theta_two_thirds():
    p = {"m": 1, "R": 2, "g": 9.81}
    s, _ = _system(p, ["theta"], [Body("p", "m", "particle", origin="R*[sin(theta), cos(theta)]")],
                   points={"P": "R*[sin(theta), cos(theta)]"}, supports=[Support("P", "p", "P", "guide", normal="P/norm(P)")])
    theta = mpmath.acos(mpmath.mpf(2) / 3)
    rate2 = 2 * 9.81 * (1 - mpmath.cos(theta)) / 2  # energy from rest at the top
    forces, residual = support_forces(s, [theta], [mpmath.sqrt(rate2)])
    assert residual < 1e-25
    assert abs(forces["P"][2][0]) < 1e-20  # N = m g (3 cos θ − 2) = 0


def test_equilibria_of_a_bead_on_a_turning_hoop():
    """Above the critical rate: θ = 0 unstable, cos θ = g/(R Ω²) stable, π unstable."""
    p = {"m": 1, "R": 1, "g": 9.81, "Omega": 5}
    sc_body = Body("b", "m", "particle", origin="R*[sin(theta)*cos(Omega*t), -cos(theta), -sin(theta)*sin(Omega*t)]")
    ms, sc = _system(p, ["theta"], [sc_body], gravity="[0, -g, 0]")
    fs = System(sc, {k: mpmath.mpf(v) for k, v in p.items()}, FLOAT)
    roots = sorted(float(r[0]) for r in equilibria(ms, fs))
    c = np.arccos(9.81 / 25)
    assert roots == pytest.approx([-c, 0, c, np.pi], abs=1e-12)
    assert [stability(ms, [mpmath.mpf(x)])[0] for x in roots] == ["stable", "unstable", "stable", "unstable"]


def test_free_rod_struck_at_its_end():
    """v_G = P/m, ω = 6P/(m l) (Jω = P l/2, J = m l²/12)."""
    from benchmarks.neighbours.oracle.impact import solve
    p = {"m": 2, "l": 3, "P": 1.5}
    s, _ = _system(p, [("x", "length", False), ("y", "length", False), "theta"],
                   [Body("rod", "m", "rod", {"length": "l"}, origin="[x, y]", angle="theta")], gravity=None,
                   points={"A": "[x, y] + l/2*[cos(theta), sin(theta)]"})
    zero = [mpmath.mpf(0)] * 3
    out = solve(s, zero, zero, [], {"A": [mpmath.mpf(0), mpmath.mpf("1.5")]})
    assert [float(x) for x in out["qd"]] == pytest.approx([0, 1.5 / 2, 6 * 1.5 / (2 * 3)], abs=1e-14)


def test_simulation_at_small_amplitude_confirms_the_linearization():
    """The oracle's two roads to a frequency agree: the rod pendulum's √(3g/2l) by
    integrating its nonlinear equations released at a thousandth of a radian."""
    from benchmarks.neighbours.oracle.search import simulated_frequency
    _, sc = _system(P, ["theta"], [Body("rod", "m", "rod", {"length": "l"}, (0, 1, 0),
                                        origin="l/2*[sin(theta), -cos(theta)]", angle="theta")])
    fs = System(sc, {k: mpmath.mpf(v) for k, v in P.items()}, FLOAT)
    w = simulated_frequency(fs, [0.0], [1.0], omega_guess=3.0)
    assert w == pytest.approx(np.sqrt(3 * 9.81 / (2 * 1.5)), rel=1e-5)


def test_an_equilibrium_is_judged_only_where_its_conditions_hold() -> None:
    """docs/json.md: an equilibrium exists only where each of its ``conditions`` is ≥ 0.
    With 1 − c² and c = 2k/m: at k = 1, m = 4 (c = 1/2) it holds (1 − 1/4 ≥ 0), at k = 3,
    m = 4 (c = 3/2) it does not (1 − 9/4 < 0): there the entry is no equilibrium to judge
    (seed 2037's scene 81, whose acos was judged at a point outside them)."""
    from types import SimpleNamespace

    from benchmarks.neighbours.check.equilibria import _conditions_hold
    from benchmarks.neighbours.read import Reader

    ctx = SimpleNamespace(reader=Reader(["k", "m"], ["theta"]))
    entry = {"conditions": ["1 - 4*k**2/m**2", "m"]}
    assert _conditions_hold(ctx, entry, {"k": 1, "m": 4})
    assert not _conditions_hold(ctx, entry, {"k": 3, "m": 4})
    assert _conditions_hold(ctx, {"conditions": []}, {"k": 3, "m": 4})
