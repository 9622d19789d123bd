"""Energy as an answer: the energy integral along a motion from a start state (T + V
constant where energy is conserved, Jacobi's h = T₂ − T₀ + V where the Lagrangian holds
no t), the rate it gives as a function of the coordinate, at a configuration asked
(``to``), and the speed of named points: "T + V is constant: … so θ̇² = 3 g sin θ/l".

    answers.py  what the question answers, both routes
    exact.py    sympy: the integral (solvers/lagrange/energy_integral.py), q̇²(q), at ``to``
    numeric.py  the exact route's expressions at the parameter values, in floating point
    steps.py    the worked solution of both routes
"""
