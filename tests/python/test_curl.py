"""field='curl' (Bridson's curl noise, issue 26): the CLI's numbers, its defaults and its refusals."""
import numpy as np
import pytest

import dfvn


def random_points(n, dim, seed, scale=4.0):
    return np.random.default_rng(seed).uniform(-scale, scale, size=(n, dim))


@pytest.mark.parametrize("dim", [2, 3])
@pytest.mark.parametrize("noise", ["turning-bands", "simplex", "quintic-gradient"])
def test_curl_field_equals_the_cli_bit_for_bit(cli, tmp_path, dim, noise):
    points = random_points(100, dim, seed=dim)
    path = tmp_path / "points.csv"
    np.savetxt(path, points, delimiter=",", fmt="%.17g")
    out = cli("field", "--field", "curl", "--dim", dim, "--seed", 5, "--frequency", 0.7, "--noise", noise,
              "--input", path)
    table = np.loadtxt(out.splitlines()[1:], delimiter=",", ndmin=2)
    c, psi = dfvn.field(points, seed=5, frequency=0.7, noise=noise, field="curl")
    np.testing.assert_array_equal(table[:, dim:2 * dim], c)
    np.testing.assert_array_equal(table[:, 2 * dim:], psi)
    if dim == 3:  # not the dfvn field
        assert not np.array_equal(c, dfvn.field(points, seed=5, frequency=0.7, noise=noise)[0])


def test_curl_field_is_divergence_free_with_rms_one():
    points = random_points(20000, 3, seed=4, scale=50.0)
    c, _ = dfvn.field(points, seed=2, field="curl")
    assert abs(np.sqrt(np.mean(np.sum(c * c, axis=1))) - 1.0) < 0.03
    h = 1e-5
    div = sum((dfvn.field(points + h * np.eye(3)[j], seed=2, field="curl")[0][:, j]
               - dfvn.field(points - h * np.eye(3)[j], seed=2, field="curl")[0][:, j]) / (2 * h) for j in range(3))
    assert np.median(np.abs(div)) < 1e-7


def test_curl_trace_defaults_to_no_reprojection_and_refuses_one():
    points = random_points(50, 3, seed=1)
    moved = dfvn.trace(points, 0.1, seed=3, field="curl", steps=4)
    np.testing.assert_array_equal(moved, dfvn.trace(points, 0.1, seed=3, field="curl", steps=4, reprojection="none"))
    assert not np.array_equal(moved, points)
    for reprojection in ["newton", "gauss-newton"]:
        with pytest.raises(ValueError, match="no reprojection"):
            dfvn.trace(points, 0.1, field="curl", reprojection=reprojection)
    # dfvn's default is still Gauss-Newton.
    np.testing.assert_array_equal(dfvn.trace(points, 0.1, seed=3),
                                  dfvn.trace(points, 0.1, seed=3, reprojection="gauss-newton"))


def test_curl_refuses_high_dimensions_and_bounded_domains():
    with pytest.raises(ValueError, match="2D and 3D"):
        dfvn.field(random_points(5, 4, seed=1), field="curl")
    with pytest.raises(ValueError, match="bound ramp"):
        dfvn.field(random_points(5, 3, seed=1), field="curl", domain="cube")
    with pytest.raises(ValueError):
        dfvn.field(random_points(5, 3, seed=1), field="bitangent")
    with pytest.raises(ValueError, match="2D and 3D"):
        dfvn.sample("cnj", 4, grid=3, field="curl")
    with pytest.raises(ValueError, match="no reprojection"):
        dfvn.CNJ(3, seed=1, field="curl", reprojection="newton").random(grid=3)
    with pytest.raises(ValueError, match="no boundary"):
        dfvn.sample("cnj", 3, grid=3, field="curl", domain="cube")


def test_curl_cnj_equals_the_cli(cli, tmp_path):
    cli("--dim", 3, "--grid", 5, "--seed", 4, "--methods", "cnj", "--field", "curl", "--points", tmp_path,
        "--format", "npy", "--no-stats", "--quiet")
    points = dfvn.sample("cnj", 3, grid=5, seed=4, field="curl")
    np.testing.assert_array_equal(points, np.load(tmp_path / "cnj.npy"))
    assert not np.array_equal(points, dfvn.sample("cnj", 3, grid=5, seed=4))
    np.testing.assert_array_equal(dfvn.CNJ(3, seed=4, field="curl").random(grid=5), points)


def test_obstacles_equal_the_cli_and_bad_ones_are_refused(cli, tmp_path):
    points = np.random.default_rng(2).uniform(0.0, 1.0, size=(50, 3))
    path = tmp_path / "points.csv"
    np.savetxt(path, points, delimiter=",", fmt="%.17g")
    for field in ("curl", "dfvn"):
        out = cli("field", "--field", field, "--domain", "cube", "--bound", "ramp", "--obstacle", "sphere:0.5,0.5,0.5,0.1",
                  "--input", path)
        table = np.loadtxt(out.splitlines()[1:], delimiter=",", ndmin=2)
        c, _ = dfvn.field(points, field=field, domain="cube", bound="ramp", obstacles=["sphere:0.5,0.5,0.5,0.1"])
        np.testing.assert_array_equal(c, table[:, 3:6])
    starts = points[np.linalg.norm(points - 0.5, axis=1) > 0.1]
    ends = dfvn.trace(starts, 0.1, domain="cube", steps=4, obstacles=["sphere:0.5,0.5,0.5,0.1"])
    assert (np.linalg.norm(ends - 0.5, axis=1) >= 0.1).all()
    for bad in ("sphere:1.5,0.5,0.5,0.1", "sphere:0.5,0.5,0.5,-0.1", "sphere:0.5,0.5,0.1", "sphere:nan,0.5,0.5,0.1"):
        with pytest.raises(ValueError):
            dfvn.field(points, domain="cube", obstacles=[bad])
    with pytest.raises(ValueError, match="cube' or 'ball"):
        dfvn.field(points, obstacles=["sphere:0.5,0.5,0.5,0.1"])
