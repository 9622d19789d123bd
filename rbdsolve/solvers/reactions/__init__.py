"""Reactions: the forces (and moments) that pivots, joints, smooth guides, rolling
contacts and strings exert, by Newton–Euler per body with the accelerations from
Lagrange's equations; along a motion released from rest, the speed by conservation of
energy and where a contact is lost or slips.

    answers.py   what the question answers, both routes
    supports.py  which force each support can exert, from the kinematics
    balances.py  the free body diagrams, and the forces solved from them
    motion.py    T + V constant, forces along the motion, contact limits
    exact.py     sympy, exact
    numeric.py   the same with the parameter values as floats, at a state
    steps.py     the worked solution of both routes
"""
