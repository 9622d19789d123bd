"""What holds the bodies to each other and to the ground besides their coordinates:
rolling contacts (a curved edge on a line or a circle, a round body on a plane in 3D)
and the place and angle that rolling gives a body, each shape's named edges, strings
wound on drums and led over pulleys, and the lengths this geometry needs positive.

Used by model/build.py while it builds a scene, and by the energies and the solvers
that ask where a contact is (solvers/configuration/)."""
