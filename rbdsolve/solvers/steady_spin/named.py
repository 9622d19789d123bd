"""The names the steady spin's worked solution prints its answers by (report/numbers.py):
the principal moments (J₁, J₂, J₃), each steady spin ω whose size is known with its rate
ν (stable) or γ (unstable), and a free precession's ω₃, ω⊥, |L|, |ω|, Ω_b, φ̇, α, ν, γ."""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.display import Label
from rbdsolve.model.build import Model
from rbdsolve.report.numbers import Named
from rbdsolve.solvers.steady_spin.answers import Stability

MOMENTS = sp.Tuple(*[sp.Symbol(f"J_{k}") for k in (1, 2, 3)])
PRECESSION = {"spin": sp.Symbol("omega_3"), "transverse": Label("ω⊥", r"\omega_{\perp}"),
              "angular_momentum": sp.Symbol("|L|"), "omega": Label("|ω|", r"|\omega|"),
              "body_rate": sp.Symbol("Omega_b"), "space_rate": Label("φ̇", r"\dot{\varphi}"),
              "alpha": sp.Symbol("alpha"), "nu": sp.Symbol("nu"), "gamma": sp.Symbol("gamma")}  # fmt: skip


def named(question, answers, model: Model) -> tuple[Named, ...]:
    out = [Named(("moments",), MOMENTS)]
    if hasattr(answers, "cases"):  # the exact route
        for k, case in enumerate(answers.cases):
            for i, s in enumerate(case.stability):
                group = f"Steady spin {i + 1}" + (f" (case {k + 1})" if len(answers.cases) > 1 else "")
                out.append(Named(("cases", k, "stability", i, "spin"), sp.Symbol("omega"), group))
                if s.stability in (Stability.STABLE, Stability.UNSTABLE):
                    rate = "nu" if s.stability is Stability.STABLE else "gamma"
                    out.append(Named(("cases", k, "stability", i, "rate"), sp.Symbol(rate), group))
    else:
        for i in range(len(answers.spins)):
            out += [Named(("spins", i, "axis"), sp.Symbol(f"e_{i + 1}"), f"Spin {i + 1}"),
                    Named(("spins", i, "moment"), sp.Symbol(f"J_{i + 1}"), f"Spin {i + 1}")]
    if answers.precession is not None:
        out += [Named(("precession", key), name, "Free precession") for key, name in PRECESSION.items()]
    return tuple(out)
