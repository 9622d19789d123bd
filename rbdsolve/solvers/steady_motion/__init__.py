"""Steady motion in a turning triad: rolling conditions, ω, angular momentum about a
point, dL/dt = moment, solved for the unknowns asked.

    answers.py   what the question answers, both routes
    balances.py  the kinematics and balances both routes solve
    exact.py     solved exactly for the asked quantities
    numeric.py   least squares from many starts
    steps.py     the worked solution of both routes
"""
