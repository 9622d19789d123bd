"""Drawings of planar scenes: their geometry to scale (sketch.py), the shapes of the
modes to draw (mode_shapes.py), and the pictures themselves with matplotlib (figures.py)."""
