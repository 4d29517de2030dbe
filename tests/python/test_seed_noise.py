"""Seed 001's rotation= (noise='simplex' in 3D) and seed 002's steer_quality= and steer_image= (noise='steerable'):
the CLI's numbers, the defaults, refusals."""
import numpy as np
import pytest

import dfvn


def test_rotation_equals_the_cli_and_defaults_to_two_vector(cli, tmp_path):
    points = np.random.default_rng(4).uniform(-3, 3, size=(100, 3))
    path = tmp_path / "points.csv"
    np.savetxt(path, points, delimiter=",", fmt="%.17g")
    for rotation in ("two-vector", "fast", "well-behaved"):
        table = np.loadtxt(cli("field", "--noise", "simplex", "--rotation", rotation, "--phase", 0.7, "--input", path)
                           .splitlines()[1:], delimiter=",")
        c, f = dfvn.field(points, noise="simplex", rotation=rotation, phase=0.7)
        np.testing.assert_array_equal(table[:, 3:6], c)
        np.testing.assert_array_equal(table[:, 6:], f)
    np.testing.assert_array_equal(dfvn.field(points, noise="simplex", phase=0.7)[0],
                                  dfvn.field(points, noise="simplex", phase=0.7, rotation="two-vector")[0])


@pytest.mark.parametrize("bad", [dict(rotation="slow"), dict(rotation="fast", noise="turning-bands"),
                                 dict(rotation="fast", dim=2), dict(rotation="well-behaved", dim=4)])
def test_rotation_refusals(bad):
    dim = bad.pop("dim", 3)
    with pytest.raises(ValueError):
        dfvn.field(np.zeros((1, dim)), **{"noise": "simplex", **bad})


def test_steer_quality_and_image(cli, tmp_path):
    points = np.random.default_rng(5).uniform(0, 1, size=(100, 2))
    path = tmp_path / "points.csv"
    np.savetxt(path, points, delimiter=",", fmt="%.17g")
    directions = np.zeros((5, 7, 2))
    directions[..., 1] = 1.0
    directions[:, :3] = [1.0, 1.0]
    image = tmp_path / "dirs.npy"
    np.save(image, directions)
    table = np.loadtxt(cli("field", "--noise", "steerable", "--steer-image", image, "--steer-quality", 1, "--input", path)
                       .splitlines()[1:], delimiter=",")
    c, f = dfvn.field(points, noise="steerable", steer_image=str(image), steer_quality=1)
    np.testing.assert_array_equal(table[:, 2:4], c)
    np.testing.assert_array_equal(table[:, 4:], f)
    assert not np.array_equal(dfvn.field(points, noise="steerable", steer=[1, 0], steer_quality=2)[0],
                              dfvn.field(points, noise="steerable", steer=[1, 0])[0])
    with pytest.raises(ValueError):
        dfvn.field(points, noise="steerable", steer=[1, 0], steer_quality=3)
    with pytest.raises(ValueError):
        dfvn.field(points, noise="steerable", steer=[1, 0], steer_image=str(image))
    with pytest.raises(ValueError):
        dfvn.field(points, steer_quality=1)
