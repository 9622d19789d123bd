"""Seed problem 1 (two rods in a circle) the way a sympy user solves it today, as a
plain script: bodies and frames in sympy.physics.mechanics, Kane's method, the
Linearizer at θ = φ = 0, then det(K − λM) = 0 for the eigenvalues λ = ω².

The benchmark times this whole process against ``rbdsolve solve p1-two-rods.yaml
--format json``; it prints the eigenvalues, to be compared with rbdsolve's
(3g/(2r)·(…) forms: both in m, r, g).
"""

import sympy as sp
import sympy.physics.mechanics as me

m, r, g = sp.symbols("m r g", positive=True)
theta, phi = me.dynamicsymbols("theta phi")
u1, u2 = me.dynamicsymbols("u1 u2")
N = me.ReferenceFrame("N")
A = N.orientnew("A", "Axis", (theta, N.z))
B = N.orientnew("B", "Axis", (phi, N.z))
A.set_ang_vel(N, u1 * N.z)
B.set_ang_vel(N, u2 * N.z)
O = me.Point("O")
O.set_vel(N, 0)
G1 = O.locatenew("G1", r / 2 * (sp.sin(theta) * N.x - sp.cos(theta) * N.y))
G2 = G1.locatenew("G2", r / 2 * (sp.sin(phi) * N.x - sp.cos(phi) * N.y))
G1.set_vel(N, G1.pos_from(O).dt(N).subs({theta.diff(): u1, phi.diff(): u2}))
G2.set_vel(N, G2.pos_from(O).dt(N).subs({theta.diff(): u1, phi.diff(): u2}))
long_rod = me.RigidBody("long", G1, A, 3 * m, (me.inertia(A, 0, 0, 3 * m * 3 * r**2 / 12), G1))
short_rod = me.RigidBody("short", G2, B, m, (me.inertia(B, 0, 0, m * r**2 / 12), G2))
forces = [(G1, -3 * m * g * N.y), (G2, -m * g * N.y)]
kane = me.KanesMethod(N, q_ind=[theta, phi], u_ind=[u1, u2],
                      kd_eqs=[theta.diff() - u1, phi.diff() - u2])
kane.kanes_equations([long_rod, short_rod], forces)
op = {theta: 0, phi: 0, u1: 0, u2: 0, u1.diff(): 0, u2.diff(): 0}
M_lin, A_lin, _, _ = kane.linearize(op_point=op, A_and_B=False)
M = sp.simplify(M_lin[2:, 2:])
K = sp.simplify(-A_lin[2:, :2])
lam = sp.Symbol("lamda")
print(sp.solve(sp.factor((K - lam * M).det()), lam))
