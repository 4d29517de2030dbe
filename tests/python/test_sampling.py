"""dfvn.sample: the same bits as `dfvn-sample --points DIR --format npy`, point counts, errors."""
import warnings

import numpy as np
import pytest

import dfvn

METHODS = ["cnj", "jitter", "jitter-matched", "pds", "sobol", "random", "halton", "lhs"]


@pytest.mark.parametrize("protocol", ["unit", "paper"])
def test_sample_equals_the_cli_points_bit_for_bit(cli, tmp_path, protocol):
    # The engines' "unit" protocol is the CLI's fair one on the torus (the default), but for Poisson disk,
    # which the engines run in the unit cube at radius 1/K (here 0.2).
    cli("--dim", 3, "--grid", 5, "--seed", 3, "--protocol", "fair" if protocol == "unit" else protocol,
        "--methods", ",".join(METHODS), "--points", tmp_path, "--format", "npy", "--stats", tmp_path / "stats.csv",
        "--quiet")
    if protocol == "unit":
        cli("--dim", 3, "--grid", 5, "--seed", 3, "--domain", "cube", "--methods", "pds", "--pds-radius", 0.2,
            "--points", tmp_path, "--format", "npy", "--stats", tmp_path / "stats.csv", "--quiet")
    for method in METHODS:
        expected = np.load(tmp_path / f"{method}.npy")
        got = dfvn.sample(method, 3, grid=5, seed=3, protocol=protocol)
        assert got.dtype == np.float64 and got.flags.c_contiguous and got.shape[1] == 3
        np.testing.assert_array_equal(got, expected, err_msg=method)


def test_sample_options_reach_the_generator_as_on_the_command_line(cli, tmp_path):
    # CNJ in the ball; the sequences and Poisson disk (which the engines run in the cube) in the cube.
    cli("--dim", 4, "--grid", 4, "--seed", 8, "--methods", "cnj", "--noise", "quintic-gradient",
        "--cycles-per-spacing", 0.35, "--step-scale", 0.3, "--integrator", "euler", "--reproject", "newton",
        "--steps", 3, "--domain", "ball", "--bound", "ramp",
        "--points", tmp_path, "--format", "npy", "--stats", tmp_path / "stats.csv", "--quiet")
    cli("--dim", 4, "--grid", 4, "--seed", 8, "--methods", "sobol,halton,pds", "--domain", "cube", "--scramble", "none",
        "--pds-radius", 0.2, "--pds-candidates", 10,
        "--points", tmp_path, "--format", "npy", "--stats", tmp_path / "stats.csv", "--quiet")
    common = dict(grid=4, seed=8, scramble=False)
    cnj = dfvn.sample("cnj", 4, noise="quintic-gradient", cycles_per_spacing=0.35, step_scale=0.3, integrator="euler",
                      reprojection="newton", steps=3, domain="ball", bound="ramp", **common)
    np.testing.assert_array_equal(cnj, np.load(tmp_path / "cnj.npy"))
    np.testing.assert_array_equal(dfvn.sample("sobol", 4, **common), np.load(tmp_path / "sobol.npy"))
    np.testing.assert_array_equal(dfvn.sample("halton", 4, **common), np.load(tmp_path / "halton.npy"))
    pds = dfvn.sample("pds", 4, radius=0.2, ncandidates=10, **common)
    np.testing.assert_array_equal(pds, np.load(tmp_path / "pds.npy"))
    assert not np.array_equal(cnj, dfvn.sample("cnj", 4, grid=4, seed=8))  # the options did change something


@pytest.mark.parametrize("method", ["sobol", "random", "halton", "lhs"])
def test_n_gives_exactly_n_points_in_the_unit_cube(method):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        points = dfvn.sample(method, 5, n=1000, seed=2)
    assert points.shape == (1000, 5)
    assert points.min() >= 0.0 and points.max() <= 1.0


def test_sobol_warns_unless_n_is_a_power_of_two_as_scipy_does():
    with pytest.warns(UserWarning, match="power of 2"):
        dfvn.sample("sobol", 3, n=1000)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert dfvn.sample("sobol", 3, n=1024).shape == (1024, 3)


def test_lattice_methods_take_the_lattice_nearest_to_n():
    assert dfvn.sample("jitter", 3, n=1000).shape == (1000, 3)   # 10^3
    assert dfvn.sample("jitter", 3, n=40).shape == (27, 3)       # 3^3 = 27 is nearer than 4^3 = 64
    assert dfvn.sample("jitter", 3, n=50).shape == (64, 3)
    assert dfvn.sample("jitter", 2, n=1).shape == (4, 2)         # the smallest lattice, 2^2
    assert dfvn.sample("cnj", 3, n=1000).shape == (1000, 3)      # the torus keeps every point
    assert dfvn.sample("cnj", 3, n=1000, domain_mode="drop").shape[0] <= 1000  # drop mode drops, in the cube


def test_poisson_disk_gives_n_points_or_warns_that_it_saturated():
    points = dfvn.sample("pds", 2, n=100, radius=0.02)
    assert points.shape == (100, 2)
    with pytest.warns(UserWarning, match="saturated"):
        few = dfvn.sample("pds", 2, n=1000, radius=0.2)
    assert 0 < len(few) < 1000
    distance = np.sqrt(((few[:, None, :] - few[None, :, :]) ** 2).sum(-1)) + np.eye(len(few))
    assert distance.min() >= 0.2


def test_cnj_steps_zero_is_the_domains_count():
    two = dfvn.sample("cnj", 3, grid=5, steps=2)  # the torus: the free field's two steps
    np.testing.assert_array_equal(dfvn.sample("cnj", 3, grid=5, steps=0), two)
    np.testing.assert_array_equal(dfvn.sample("cnj", 3, grid=5), two)
    one = dfvn.sample("cnj", 3, grid=5, steps=1, domain="cube")  # the bounded cube: one step
    np.testing.assert_array_equal(dfvn.sample("cnj", 3, grid=5, domain="cube"), one)
    assert not np.array_equal(two, dfvn.sample("cnj", 3, grid=5, steps=1))


def test_cnj_on_the_torus_stays_in_the_half_open_cube_and_jitter_matched_moves_as_far():
    cnj = dfvn.sample("cnj", 4, grid=5, seed=3)
    assert cnj.shape == (625, 4) and cnj.min() >= 0.0 and cnj.max() < 1.0
    matched = dfvn.sample("jitter-matched", 4, grid=5, seed=3)
    assert matched.shape == (625, 4) and matched.min() >= 0.0 and matched.max() < 1.0
    periodic = dfvn.nn_stats(cnj, periodic=True)
    assert periodic["min"] <= dfvn.nn_stats(cnj)["min"]  # minimum images are never farther


def test_same_seed_same_bits_other_seed_other_points_any_threads():
    a = dfvn.sample("cnj", 4, grid=5, seed=1, threads=1)
    np.testing.assert_array_equal(a, dfvn.sample("cnj", 4, grid=5, seed=1, threads=3))
    assert not np.array_equal(a, dfvn.sample("cnj", 4, grid=5, seed=2))


@pytest.mark.parametrize(
    "args, kwargs, error, words",
    [
        (("sobol", 3), {}, ValueError, "exactly one of grid"),
        (("sobol", 3), {"grid": 4, "n": 64}, ValueError, "exactly one of grid"),
        (("voronoi", 3), {"grid": 4}, ValueError, "voronoi"),
        (("sobol", 9), {"grid": 4}, ValueError, "dim must be in 2..8"),
        (("sobol", 3), {"n": 0}, ValueError, "at least 1"),
        (("jitter", 3), {"grid": 1}, ValueError, "grid"),
        (("sobol", 3), {"grid": 4, "protocol": "box"}, ValueError, "box"),
        (("cnj", 3), {"grid": 4, "noise": "perlin"}, ValueError, "perlin"),
        (("cnj", 3), {"grid": 4, "steps": -1}, ValueError, "steps"),
        (("cnj", 3), {"grid": 4, "domain": "klein"}, ValueError, "klein"),
        (("cnj", 3), {"grid": 4, "domain": "torus", "domain_mode": "drop"}, ValueError, "torus has no boundary"),
        (("cnj", 3), {"grid": 4, "domain": "torus", "bound": "ramp"}, ValueError, "bound applies"),
        (("cnj", 3), {"grid": 4, "noise": "simplex"}, ValueError, "periodic noise basis"),
        (("cnj", 3), {"grid": 4, "bound": "mirror"}, ValueError, "mirror"),
        (("jitter-matched", 3), {"grid": 4, "domain": "ball"}, ValueError, "jitter-matched"),
        (("sobol", 3), {"grid": 4, "colour": "red"}, TypeError, "colour|argument"),
        (("sobol", 3), {"n": -5}, ValueError, "n must be at least 1"),
        (("sobol", 3), {"n": 2.5}, TypeError, "n must be an int"),
        (("cnj", 3), {"grid": 4, "frequency": 0.2}, TypeError, "cycles_per_spacing"),
        (("cnj", 3), {"grid": 4, "seed": "one"}, ValueError, "'one' cannot be used to seed a numpy.random.Generator"),
    ],
)
def test_sample_refuses_bad_arguments_with_a_clear_error(args, kwargs, error, words):
    with pytest.raises(error, match=words):
        dfvn.sample(*args, **kwargs)
