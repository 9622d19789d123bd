"""rbdsolve: a command-line exam solver for rigid body dynamics.

Pipeline (imports run one way; docs/architecture.md)::

    problem/   YAML text -> Problem  (validated, located, no sympy)
    model/     Problem   -> Model    (sympy: kinematics, inertia, T, V)
    solvers/   Model     -> Solution (answers + steps), one folder per family
    report/    the vocabulary: steps, solutions, reports, keys, variant tables
    render/    reports   -> terminal | markdown | latex | html | json; drawings
    teaching/  answer keys and exam variants
    cli/       load -> build -> solve -> render
    form/      the exam form of mathematics, used by all of the above
    api/       the Python API: load, solve, render (docs/api.md)

The Python API (docs/api.md) is this package's surface::

    import rbdsolve
    result = rbdsolve.solve("p1.yaml", values={"g": 9.81})
    result["modes"].answers.eigenvalues      # sympy objects

Its names are imported when first used, so ``import rbdsolve`` (and the CLI's start)
loads nothing of the pipeline, and no sympy.
"""

__version__ = "0.1.0"

_API = ("Answer", "ExitCode", "InputError", "InternalError", "Problem", "RbdError", "Result", "UnsolvedError",
        "load", "load_dict", "loads", "solve")
__all__ = ["__version__", *_API]


def __getattr__(name: str):
    """``rbdsolve.solve`` and the rest of the API, imported on first use (PEP 562)."""
    if name in _API:
        import rbdsolve.api

        return getattr(rbdsolve.api, name)
    raise AttributeError(f"module 'rbdsolve' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted({*globals(), *_API})
