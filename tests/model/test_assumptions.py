"""model.assumptions: what the assumptions imply, checked against intervals by hand."""


def test_the_assumptions_imply_a_condition_on_their_parameter() -> None:
    """0 < α < π/2 (an incline): α ≤ π/2 and tan α ≥ 0 hold for every α allowed, α ≤ π/3
    and tan α ≤ 0 do not; without an assumption on α nothing is implied."""
    import sympy as sp

    from rbdsolve.model.assumptions import Assumed, implies

    alpha = sp.Symbol("alpha", positive=True)
    incline = (Assumed(alpha, True, None), Assumed(sp.pi / 2 - alpha, True, None))
    assert implies(incline, alpha <= sp.pi / 2) and implies(incline, sp.tan(alpha) >= 0)
    assert not implies(incline, alpha <= sp.pi / 3) and not implies(incline, sp.tan(alpha) <= 0)
    assert not implies((), alpha <= 1)
