"""Bodies as weighted material points: a quadrature of each shape of the library, in
its own axes, from its geometry alone (never from the table of moments).

Each shape is a map from a box of parameters to the body with its Jacobian (the
volume, area or length element); Gauss–Legendre nodes on each parameter integrate the
second moments exactly where the integrand is a polynomial (boxes, disks in ρ), and
to rounding where it is analytic (arcs of a circle). A body is then the list of
(mass, position) of its points; a hole counts with negative mass, and mass, centre
and inertia follow by sums: m = Σ mᵢ, G = Σ mᵢ rᵢ/m, J_G = Σ mᵢ (|dᵢ|² 1 − dᵢ dᵢᵀ),
dᵢ = rᵢ − G (J_xy = −Σ mᵢ xᵢ yᵢ: the products with the minus sign)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

_N = 24  # nodes per parameter: the arcs' trigonometric integrands to rounding


def _gl(a: float, b: float, n: int = _N) -> tuple[np.ndarray, np.ndarray]:
    x, w = np.polynomial.legendre.leggauss(n)
    return 0.5 * (b - a) * x + 0.5 * (b + a), 0.5 * (b - a) * w


def _grid(*axes):
    """The tensor grid of nodes and the product of weights."""
    nodes = np.meshgrid(*[a[0] for a in axes], indexing="ij")
    weights = np.meshgrid(*[a[1] for a in axes], indexing="ij")
    w = np.ones_like(nodes[0])
    for wi in weights:
        w = w * wi
    return [n.ravel() for n in nodes], w.ravel()


def _normalised(points: np.ndarray, w: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    return points, w / w.sum()


def _polar_plate(r_in, r_out, phi0, phi1, z=0.0):
    (rho, phi), w = _grid(_gl(r_in, r_out), _gl(phi0, phi1, 2 * _N))
    pts = np.stack([rho * np.cos(phi), rho * np.sin(phi), np.full_like(rho, z)], axis=1)
    return _normalised(pts, w * rho)


def particle(**_):
    return np.zeros((1, 3)), np.ones(1)


def rod(length, **_):
    x, w = _gl(-length / 2, length / 2)
    return _normalised(np.stack([x, 0 * x, 0 * x], axis=1), w)


def ring(radius, **_):
    phi, w = _gl(0, 2 * math.pi, 2 * _N)
    return _normalised(np.stack([radius * np.cos(phi), radius * np.sin(phi), 0 * phi], axis=1), w)


def disk(radius, **_):
    return _polar_plate(0, radius, 0, 2 * math.pi)


def _solid_of_revolution(r_in, r_out, z0, z1, radius_at=None):
    """ρ ∈ [r_in, r_out(z)], φ, z: the volume element ρ dρ dφ dz."""
    (u, phi, z), w = _grid(_gl(0, 1), _gl(0, 2 * math.pi, 2 * _N), _gl(z0, z1))
    outer = r_out if radius_at is None else radius_at(z)
    rho = r_in + u * (outer - r_in)
    pts = np.stack([rho * np.cos(phi), rho * np.sin(phi), z], axis=1)
    return _normalised(pts, w * rho * (outer - r_in))


def cylinder(radius, height, **_):
    return _solid_of_revolution(0.0, radius, -height / 2, height / 2)


def tube(inner_radius, outer_radius, height, **_):
    return _solid_of_revolution(inner_radius, outer_radius, -height / 2, height / 2)


def cylindrical_shell(radius, height, **_):
    (phi, z), w = _grid(_gl(0, 2 * math.pi, 2 * _N), _gl(-height / 2, height / 2))
    return _normalised(np.stack([radius * np.cos(phi), radius * np.sin(phi), z], axis=1), w)


def cone(radius, height, **_):
    return _solid_of_revolution(0.0, radius, 0.0, height, lambda z: radius * (1 - z / height))


def _ball(radius, c0, c1, shell: bool):
    """A sphere (c = cos of the polar angle from c0 to c1); a shell's area element is
    uniform in z = r c (Archimedes), a ball's volume element ρ² dρ dc dφ."""
    if shell:
        (c, phi), w = _grid(_gl(c0, c1), _gl(0, 2 * math.pi, 2 * _N))
        rho = np.full_like(c, radius)
    else:
        (rho, c, phi), w = _grid(_gl(0, radius), _gl(c0, c1), _gl(0, 2 * math.pi, 2 * _N))
        w = w * rho ** 2
    s = np.sqrt(1 - c ** 2)
    return _normalised(np.stack([rho * s * np.cos(phi), rho * s * np.sin(phi), rho * c], axis=1), w)


def sphere(radius, **_):
    return _ball(radius, -1.0, 1.0, shell=False)


def spherical_shell(radius, **_):
    return _ball(radius, -1.0, 1.0, shell=True)


def hemisphere(radius, **_):
    return _ball(radius, 0.0, 1.0, shell=False)


def hemispherical_shell(radius, **_):
    return _ball(radius, 0.0, 1.0, shell=True)


def half_disk(radius, **_):
    return _polar_plate(0, radius, 0, math.pi)


def half_ring(radius, **_):
    phi, w = _gl(0, math.pi, 2 * _N)
    return _normalised(np.stack([radius * np.cos(phi), radius * np.sin(phi), 0 * phi], axis=1), w)


def quarter_disk(radius, **_):
    return _polar_plate(0, radius, 0, math.pi / 2)


def cylinder_segment(radius, height, half_angle, **_):
    """The section y ≥ r cos α of the circle, by the angle ψ from own y and ρ from the
    chord (r cos α / cos ψ) to the rim; z along the length."""
    (psi, u, z), w = _grid(_gl(-half_angle, half_angle, 2 * _N), _gl(0, 1), _gl(-height / 2, height / 2))
    inner = radius * math.cos(half_angle) / np.cos(psi) if half_angle < math.pi / 2 - 1e-12 else 0 * psi
    if half_angle > math.pi / 2 + 1e-12:  # beyond a half: the chord is below the centre
        return _segment_by_rows(radius, height, half_angle)
    rho = inner + u * (radius - inner)
    pts = np.stack([rho * np.sin(psi), rho * np.cos(psi), z], axis=1)
    return _normalised(pts, w * rho * (radius - inner))


def _segment_by_rows(radius, height, half_angle):
    """A section larger than a half: rows y from r cos α to r, x within the circle."""
    (y, u, z), w = _grid(_gl(radius * math.cos(half_angle), radius, 4 * _N), _gl(-1, 1), _gl(-height / 2, height / 2))
    half = np.sqrt(np.maximum(radius ** 2 - y ** 2, 0))
    pts = np.stack([u * half, y, z], axis=1)
    return _normalised(pts, w * half)


def box(width, depth, height, **_):
    (x, y, z), w = _grid(_gl(-width / 2, width / 2, 3), _gl(-depth / 2, depth / 2, 3), _gl(-height / 2, height / 2, 3))
    return _normalised(np.stack([x, y, z], axis=1), w)


def plate(width, height, **_):
    (x, y), w = _grid(_gl(-width / 2, width / 2, 3), _gl(-height / 2, height / 2, 3))
    return _normalised(np.stack([x, y, 0 * x], axis=1), w)


def triangle(base, height, apex, **_):
    """Vertices (0, 0), (b, 0), (p, h): the point s·(b, 0) + t·(p − s b... ) by the
    collapsed square u ∈ [0, 1], v ∈ [0, 1]: P = (1 − v)(u (b, 0)) + v (p, h)."""
    (u, v), w = _grid(_gl(0, 1, 6), _gl(0, 1, 6))
    x = (1 - v) * u * base + v * apex
    y = v * height
    return _normalised(np.stack([x, y, 0 * x], axis=1), w * (1 - v))


SHAPES = {
    "particle": particle, "point": particle, "rod": rod, "slender_rod": rod, "ring": ring, "hoop": ring,
    "disk": disk, "cylindrical_shell": cylindrical_shell, "shell": cylindrical_shell, "cylinder": cylinder,
    "tube": tube, "spherical_shell": spherical_shell, "sphere": sphere, "ball": sphere,
    "hemisphere": hemisphere, "solid_hemisphere": hemisphere, "hemispherical_shell": hemispherical_shell,
    "half_disk": half_disk, "semicircular_plate": half_disk, "half_ring": half_ring,
    "semicircular_wire": half_ring, "quarter_disk": quarter_disk, "cylinder_segment": cylinder_segment,
    "cone": cone, "box": box, "cuboid": box, "plate": plate, "rectangle": plate, "triangle": triangle,
}

# The direction of each shape's own axis in its own axes (the format: a rod along x,
# a half disk into its material along y, a quarter disk along its diagonal, else z).
OWN_AXIS = {"rod": (1, 0, 0), "slender_rod": (1, 0, 0), "half_disk": (0, 1, 0), "semicircular_plate": (0, 1, 0),
            "half_ring": (0, 1, 0), "semicircular_wire": (0, 1, 0), "cylinder_segment": (0, 1, 0),
            "quarter_disk": (1 / math.sqrt(2), 1 / math.sqrt(2), 0)}


def turn_to(direction, own) -> np.ndarray:
    """The smallest rotation taking ``own`` to ``direction`` (Rodrigues about own ×
    direction); opposite ones: a half turn about y, or about z when own has no z part
    (the format's rule for `axis:`)."""
    d = np.asarray(direction, float)
    d = d / np.linalg.norm(d)
    a = np.asarray(own, float)
    c = float(a @ d)
    if abs(c - 1) < 1e-14:
        return np.eye(3)
    if abs(c + 1) < 1e-14:
        f = np.array([0.0, 1.0, 0.0]) if abs(a[2]) > 0 else np.array([0.0, 0.0, 1.0])
        return 2 * np.outer(f, f) - np.eye(3)
    k = np.cross(a, d)
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + K + K @ K / (1 + c)


@dataclass(frozen=True)
class Cloud:
    """Material points in body axes: masses (a hole's negative) and positions."""

    masses: np.ndarray
    points: np.ndarray

    def __add__(self, other: "Cloud") -> "Cloud":
        return Cloud(np.concatenate([self.masses, other.masses]), np.concatenate([self.points, other.points]))

    @property
    def mass(self) -> float:
        return float(self.masses.sum())

    @property
    def centre(self) -> np.ndarray:
        return (self.masses[:, None] * self.points).sum(axis=0) / self.mass

    def inertia(self, about=None) -> np.ndarray:
        """J = Σ mᵢ (|dᵢ|² 1 − dᵢ dᵢᵀ), dᵢ from ``about`` (default: the centre)."""
        c = self.centre if about is None else np.asarray(about, float)
        d = self.points - c
        r2 = (d * d).sum(axis=1)
        return (self.masses[:, None, None] * (r2[:, None, None] * np.eye(3) - d[:, :, None] * d[:, None, :])).sum(axis=0)


def cloud(shape: str, mass: float, dims: dict[str, float], axis=None, at=(0.0, 0.0, 0.0), hole: bool = False) -> Cloud:
    """A shape of ``mass`` with its own axis along ``axis`` (body axes) and its origin at ``at``."""
    pts, w = SHAPES[shape](**dims)
    if axis is not None:
        pts = pts @ turn_to(axis, OWN_AXIS.get(shape, (0, 0, 1))).T
    pts = pts + np.asarray(list(at) + [0.0] * (3 - len(at)), float)
    return Cloud((-1 if hole else 1) * mass * w, pts)
