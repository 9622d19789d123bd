"""Steady spin of a free body: Euler's equations, ω an eigenvector of J, each spin's
stability.

    answers.py  what the question answers, both routes
    exact.py    the case analysis on equal principal moments
    numeric.py  principal moments and spins in floats
    steps.py    the worked solution of both routes
"""
