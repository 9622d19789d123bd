"""form/labels.py: a solver's own labels never print like a problem's names; and
names print as an exam writes them (θ₁,f, x_B), their rates with dots."""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.labels import Labels
from rbdsolve.form.printers import to_latex, to_unicode, unicode_name
from rbdsolve.model.state import t

MODES = ("mass_matrix", "stiffness_matrix", "displacement", "eigenvalue", "scaled_eigenvalue", "frequency",
         "growth_rate", "amplitude")


def test_without_clashes_the_usual_labels() -> None:
    labels = Labels.of(["m", "l", "g", "theta"], MODES)
    assert [unicode_name(labels.name(k)) for k in MODES] == ["M", "K", "u", "λ", "μ", "ω", "γ", "a"]


def test_each_clash_moves_to_the_next_candidate() -> None:
    labels = Labels.of(["M", "K", "a", "mu", "lamda", "x"], MODES)
    assert labels.name("mass_matrix") == "M_q" and labels.name("stiffness_matrix") == "K_q"
    assert labels.name("amplitude") == "X"  # a cart's acceleration a: the amplitudes are X₁, X₂
    assert labels.name("eigenvalue") == "Lambda"  # a parameter λ: det(K − ΛM) = 0
    assert labels.name("scaled_eigenvalue") == "kappa"


def test_a_bare_rate_keeps_the_indexed_frequency_and_indexes_the_prose() -> None:
    labels = Labels.of(["omega", "R"], MODES)
    assert labels.symbol("frequency", 1) == sp.Symbol("omega_1")
    assert labels.text("frequency") == "ωₖ"  # "an oscillation at ωₖ = √λ", beside the hoop's ω


def test_an_indexed_name_moves_the_indexed_label() -> None:
    assert Labels.of(["omega1", "omega2"], MODES).name("frequency") == "nu"
    assert Labels.of(["lamda_1"], MODES).name("eigenvalue") == "Lambda"


def test_labels_of_one_solution_differ_from_each_other() -> None:
    """M taken by the problem: the total mass cannot fall back to the mass matrix's M."""
    labels = Labels.of(["m"], ("mass_matrix", "total_mass"))
    assert labels.name("mass_matrix") == "M" and labels.name("total_mass") == "m_tot"
    assert Labels.of(["m"], ("total_mass",)).name("total_mass") == "M"
    assert Labels.of(["M", "M_q"], ("mass_matrix",)).name("mass_matrix") == "M_q'"


def test_subscripted_names_and_their_rates() -> None:
    assert unicode_name("theta1_f") == "θ₁,f" and unicode_name("xB") == "x_B"
    assert unicode_name("omega0") == "ω₀" and unicode_name("T_long_rod") == "T_long_rod"
    xB, theta = sp.Function("xB")(t), sp.Function("theta1_f")(t)
    assert to_unicode(xB.diff(t)) == "ẋ_B"
    assert to_unicode(theta.diff(t)) == "θ̇₁,f" and to_unicode(theta.diff(t, 2)) == "θ̈₁,f"
    assert to_latex(xB.diff(t)) == "\\dot{x}_{B}"


def test_the_exponent_of_u_equals_x_e_st_moves_off_a_spin_named_s() -> None:
    # A top's spin rate s: the roots of (s²M + sG + K) X = 0 would read as the spin.
    assert Labels.of(["m", "g"], ["exponent"]).name("exponent") == "s"
    assert Labels.of(["s", "m"], ["exponent"]).name("exponent") == "p"
    assert Labels.of(["s_1", "m"], ["exponent"]).name("exponent") == "p"  # s₁ would read as a root



def test_the_energy_constant_moves_off_a_parameter_named_h() -> None:
    # a bead on a wire with a hump of height h: T + V = H, not T + V = h
    assert Labels.of(["m", "g"], ["energy_constant"]).name("energy_constant") == "h"
    assert Labels.of(["h", "m"], ["energy_constant"]).name("energy_constant") == "H"
