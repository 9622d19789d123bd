"""The geometry of the configuration space: where the scene is for given coordinates
(the placement) and where the coordinates fail to say it, singular mass matrices,
continua of equilibria, and the span of an edge on which a rocking contact holds.

Used by the equilibria and modes families (exact and numeric routes) and by numeric/."""
