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
"""

__version__ = "0.1.0"
