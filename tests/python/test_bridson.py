"""Bridson et al. 2007's toolbox in dfvn.field and dfvn.trace (octaves, amplitude, viscous, bodies,
vortices): the CLI's numbers bit for bit, the boundary conditions from outside, and the refusals."""
import numpy as np
import pytest

import dfvn

FLOW = dict(field="curl", domain="cube", bound="ramp", boundary_width=0.05, octaves=3,
            bodies=["sphere:0.5,0.5,0.55,0.08,0.3,0,0.5,0,0,2"], vortices=["ring:0.5,0.5,0.2,0,0,1,0.15,3,0.05"],
            amplitude=["obstacles:0.3"])
CLI_FLOW = ["--field", "curl", "--domain", "cube", "--bound", "ramp", "--boundary-width", 0.05, "--octaves", 3,
            "--body", "sphere:0.5,0.5,0.55,0.08,0.3,0,0.5,0,0,2", "--vortex", "ring:0.5,0.5,0.2,0,0,1,0.15,3,0.05",
            "--amplitude", "obstacles:0.3"]


def test_flow_field_equals_the_cli_bit_for_bit(cli, tmp_path):
    points = np.random.default_rng(1).uniform(0.05, 0.95, size=(200, 3))
    path = tmp_path / "points.csv"
    np.savetxt(path, points, delimiter=",", fmt="%.17g")
    for viscous in (False, True):
        table = np.loadtxt(cli("field", *CLI_FLOW, *(["--viscous"] if viscous else []), "--input", path).splitlines()[1:],
                           delimiter=",")
        c, psi = dfvn.field(points, viscous=viscous, **FLOW)
        np.testing.assert_array_equal(table[:, 3:6], c)
        np.testing.assert_array_equal(table[:, 6:], psi)


def test_moving_body_and_viscous_walls():
    n = np.random.default_rng(2).normal(size=(500, 3))
    n /= np.linalg.norm(n, axis=1)[:, None]
    centre, radius = np.array([0.5, 0.5, 0.55]), 0.08
    velocity, angular = np.array([0.3, 0.0, 0.5]), np.array([0.0, 0.0, 2.0])
    x = centre + radius * n
    c, _ = dfvn.field(x, **FLOW)
    relative = c - velocity - np.cross(angular, x - centre)
    assert np.max(np.abs(np.sum(relative * n, axis=1))) < 1e-8
    wall = np.random.default_rng(3).uniform(0, 1, size=(300, 3))
    wall[:, 2] = 1.0
    c, _ = dfvn.field(wall, octaves=2, domain="cube", bound="eq13", viscous=True)
    assert np.max(np.abs(c)) == 0.0
    assert np.max(np.abs(dfvn.field(wall, octaves=2, domain="cube", bound="eq13")[0])) > 0.01


def test_trace_takes_the_flow():
    start = np.array([[0.3, 0.4, 0.2], [0.6, 0.6, 0.8]])
    a = dfvn.trace(start, 0.1, steps=8, **FLOW)
    b = dfvn.trace(start, 0.1, steps=8, **{**FLOW, "octaves": 1})
    assert a.shape == (2, 3) and np.all(np.isfinite(a)) and not np.array_equal(a, b)


@pytest.mark.parametrize("bad", [dict(octaves=0), dict(octaves=11), dict(octave_gain=0.0), dict(amplitude=["height:1,1"]),
                                 dict(bodies=["sphere:0.5,0.5,0.5,0.1"]), dict(vortices=["ring:0,0,0,0,0,1,0.1,1,0.2"])])
def test_bad_flow_values_raise(bad):
    with pytest.raises(ValueError):
        dfvn.field(np.full((1, 3), 0.5), **{**FLOW, **bad})
    with pytest.raises(ValueError):  # bodies need curl noise
        dfvn.field(np.full((1, 3), 0.5), domain="cube", bodies=FLOW["bodies"])
