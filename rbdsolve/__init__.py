"""rbdsolve: a command-line exam solver for rigid body dynamics.

Pipeline (imports run one way, top to bottom)::

    problem/  YAML text -> Problem  (validated, located, no sympy)
    model/    Problem   -> Model    (sympy: kinematics, inertia, T, V)
    solvers/  Model     -> Solution (answers + steps), one per question
    report/   step and solution types
    render/   Solution  -> terminal | markdown | latex | json
    cli.py    load -> build -> solve -> render
"""

__version__ = "0.1.0"
