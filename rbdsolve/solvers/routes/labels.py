"""The labels a solution prints, chosen beside the problem's names (form/labels.py)."""

from __future__ import annotations

from rbdsolve.form.labels import Labels
from rbdsolve.model.build import Model

MODES = ("mass_matrix", "stiffness_matrix", "displacement", "eigenvalue", "scaled_eigenvalue", "frequency",
         "growth_rate", "amplitude")


def problem_names(model: Model) -> tuple[str, ...]:
    """Every name the problem declares: parameters and unknowns, coordinates, prescribed
    functions, points (by position or by velocity) and bodies."""
    return (*model.symbols.parameters, *model.coordinate_names(), *model.symbols.prescribed,
            *model.points, *model.velocities, *(b.name for b in model.bodies))


def labels_for(model: Model, *keys: str) -> Labels:
    return Labels.of(problem_names(model), keys)
