"""A point's kinematics: position, velocity and acceleration of named points at a
state, and distances between points (the "(a) find the velocity of B" of an exam).

    answers.py  what the question answers, both routes
    exact.py    sympy: v = dr/dt, a = dv/dt by the chain rule, the state put in
    numeric.py  the same at the parameter values, in floating point
    steps.py    the worked solution of both routes
"""
