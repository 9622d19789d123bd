"""The sections of a problem file, each read and validated: bodies, coordinates,
contacts, forces and couples, 3D orientations, and the questions with each kind's
options (kinematics, impact, the force questions' states, modes' amplitudes).

Used by problem/loader.py, which hands each reader the file's reading context."""
