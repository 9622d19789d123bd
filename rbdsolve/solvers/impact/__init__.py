"""Impact: Lagrange's equations for impact, Δ(∂T/∂q̇) = generalized impulses, closed by
Newton's restitution laws.

    answers.py    what the question answers
    equations.py  the impulse equations of one impact, set up and solved
    exact.py      solved in a fraction field, answers as cancelled fractions
    numeric.py    solved in floats, with the condition number
    steps.py      the worked solution of both routes
"""
