"""A guide held both ways (a bead threaded on its wire) loses no contact: its push may
change sign. The same scene taken as a surface that only pushes is left where N = 0.

By hand, a bead of mass m on a vertical circle of radius R released from rest at the
horizontal (θ = π/2, θ from the downward vertical): R θ̇² = 2 g cos θ, and the normal
balance gives N = m (R θ̇² + g cos θ) = 3 m g cos θ, zero at cos θ = 0."""

import json

from click.testing import CliRunner

from rbdsolve.cli import main

BEAD = """\
parameters: {m: bead mass, R: wire radius, g: gravity}
coordinates: [theta]
gravity: [0, -g]
points:
  P: R*[sin(theta), -cos(theta)]
bodies:
  bead: {shape: particle, mass: m, at: P}
questions:
  - reactions: {forces: [FORCE], from_rest: {theta: pi/2}}
"""


def _answers(tmp_path, force: str) -> dict:
    path = tmp_path / "bead.yaml"
    path.write_text(BEAD.replace("FORCE", force), encoding="utf-8")
    result = CliRunner().invoke(main, ["solve", str(path), "-f", "json"])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)["results"][0]["answers"]


def test_a_threaded_bead_loses_no_contact(tmp_path) -> None:
    answers = _answers(tmp_path, "{at: P, two_sided: true}")
    assert not answers["contact_lost"] or not any(answers["contact_lost"].values())


def test_a_push_only_contact_is_lost_where_n_vanishes(tmp_path) -> None:
    answers = _answers(tmp_path, "P")
    assert answers["contact_lost"] == {"N_P": ["Eq(cos(theta(t)), 0)"]}
