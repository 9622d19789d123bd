"""T and V of a model, and the Lagrangian's parts: the energies body by body (König),
a spring's length as an exam writes it, the applied forces and couples with their
generalized forces and potentials, the gyroscopic terms (the Lagrangian by its degree
in the rates), and the Lagrangian as seen from a moving frame.

Used by model/summary/ (the T and V every solution opens with) and by every solver
family."""
