"""dfvn.nn_stats and dfvn.rdf: the command line's statistics on NumPy arrays."""
import csv
import io

import numpy as np
import pytest

import dfvn


def test_nn_stats_equal_the_cli_stats_command(cli, tmp_path):
    points = dfvn.sample("cnj", 4, grid=6, seed=5)
    np.save(tmp_path / "cnj.npy", points)
    row = next(csv.DictReader(io.StringIO(cli("stats", "--input", tmp_path / "cnj.npy"))))
    stats = dfvn.nn_stats(points)
    assert stats["points"] == len(points) == int(row["points"])
    for name in ("min", "median", "mean", "median_scaled"):  # the CLI prints 9 significant digits
        assert float(row["nn_" + name]) == pytest.approx(stats[name], rel=1e-8, abs=0), name


def test_nn_stats_of_a_lattice_are_its_spacing():
    axis = (np.arange(6) + 0.5) / 6
    lattice = np.stack(np.meshgrid(axis, axis, axis, indexing="ij"), -1).reshape(-1, 3)
    stats = dfvn.nn_stats(lattice)
    for name in ("min", "median", "mean", "q01"):
        assert stats[name] == pytest.approx(1 / 6, rel=1e-12)
    assert stats["median_scaled"] == pytest.approx(1.0, rel=1e-12)
    assert dfvn.nn_stats(np.array([0.1, 0.4, 0.5]))["min"] == pytest.approx(0.1)  # 1-D points


def test_nn_stats_agree_with_brute_force_for_both_kd_trees():
    points = np.random.default_rng(4).random((400, 6))
    distance = np.sqrt(((points[:, None, :] - points[None, :, :]) ** 2).sum(-1))
    np.fill_diagonal(distance, np.inf)
    nearest = distance.min(axis=1)
    for knn in ("nanoflann", "flann"):
        stats = dfvn.nn_stats(points, knn=knn)
        assert stats["min"] == pytest.approx(nearest.min(), rel=1e-14)
        assert stats["median"] == pytest.approx(np.median(nearest), rel=1e-14)
        assert stats["q01"] == pytest.approx(np.quantile(nearest, 0.01), rel=1e-14)


def test_periodic_nn_stats_equal_scipys_periodic_kd_tree():
    from scipy.spatial import cKDTree  # an independent implementation of minimum-image distances

    for dim in (1, 2, 5):
        points = np.random.default_rng(dim).random((3000, dim))
        nearest = cKDTree(points, boxsize=1.0).query(points, k=2)[0][:, 1]
        stats = dfvn.nn_stats(points, periodic=True)
        assert stats["min"] == pytest.approx(nearest.min(), rel=1e-14)
        assert stats["median"] == pytest.approx(np.median(nearest), rel=1e-14)
        assert stats["q01"] == pytest.approx(np.quantile(nearest, 0.01), rel=1e-14)


def test_periodic_rdf_of_uniform_random_points_is_about_one():
    points = np.random.default_rng(2).random((20000, 2))
    r, g = dfvn.rdf(points, bins=20, r_max=0.05, periodic=True)
    assert np.all(np.abs(g[5:] - 1.0) < 0.15)
    with pytest.raises(ValueError, match="half the side"):
        dfvn.rdf(points, r_max=0.5, periodic=True)


def test_rdf_equals_the_cli_rdf(cli, tmp_path):
    cli("--dim", 3, "--grid", 8, "--seed", 6, "--domain", "cube", "--methods", "jitter,sobol",
        "--rdf", tmp_path / "rdf.csv", "--stats", tmp_path / "stats.csv", "--quiet")
    rows = list(csv.DictReader(open(tmp_path / "rdf.csv")))
    for method in ("jitter", "sobol"):
        r, g = dfvn.rdf(dfvn.sample(method, 3, grid=8, seed=6), seed=6)
        expected = [row for row in rows if row["method"] == method]
        assert len(expected) == len(r) == len(g) == 50
        np.testing.assert_allclose([float(row["r"]) for row in expected], r, rtol=1e-8)
        np.testing.assert_allclose([float(row["g"]) for row in expected], g, rtol=1e-8, atol=1e-12)


def test_rdf_of_uniform_random_points_is_about_one():
    points = np.random.default_rng(1).random((20000, 2))
    r, g = dfvn.rdf(points, bins=20, r_max=0.05)
    assert r.shape == g.shape == (20,)
    assert np.all(np.abs(g[5:] - 1.0) < 0.15)


@pytest.mark.parametrize(
    "function, points, kwargs, words",
    [
        (dfvn.nn_stats, np.zeros((1, 3)), {}, "at least 2"),
        (dfvn.nn_stats, np.full((3, 2), 2.0), {}, "outside|domain"),
        (dfvn.nn_stats, np.random.default_rng(0).random((5, 9)), {}, "columns"),
        (dfvn.nn_stats, np.random.default_rng(0).random((5, 2)), {"knn": "annoy"}, "annoy"),
        (dfvn.nn_stats, np.random.default_rng(0).random((5, 2)), {"domain_side": 0.0}, "domain_side"),
        (dfvn.rdf, np.random.default_rng(0).random((5, 2)), {"bins": 0}, "bins"),
        (dfvn.rdf, np.random.default_rng(0).random((5, 1)), {}, "columns"),
        (dfvn.rdf, np.array([[0.5, np.nan], [0.1, 0.2]]), {}, "point|nan|NaN"),
    ],
)
def test_stats_refuse_bad_input_with_a_clear_error(function, points, kwargs, words):
    with pytest.raises(ValueError, match=words):
        function(points, **kwargs)


@pytest.mark.parametrize("side", [1e-300, 1e-150, 1e150, 1e200, 1e300])
def test_nn_stats_and_rdf_scale_with_the_set(side):
    """Issue 23: at extreme sides squared distances overflowed or underflowed (Inf, NaN, a crash)."""
    points = np.random.default_rng(23).uniform(0.05, 0.95, (300, 3))
    unit = dfvn.nn_stats(points)
    scaled = dfvn.nn_stats(points * side, domain_side=side)
    for name in ("min", "q01", "median", "mean"):
        assert np.isfinite(scaled[name]) and scaled[name] / side == pytest.approx(unit[name], rel=0, abs=1e-14), name
    assert scaled["median_scaled"] == pytest.approx(unit["median_scaled"], rel=1e-12)
    r, g = dfvn.rdf(points, bins=10)
    r_scaled, g_scaled = dfvn.rdf(points * side, domain_side=side, bins=10)
    assert np.all(np.isfinite(r_scaled)) and np.all(np.isfinite(g_scaled))
    np.testing.assert_allclose(r_scaled / side, r, rtol=1e-12)
    np.testing.assert_allclose(g_scaled, g, rtol=1e-9)


@pytest.mark.parametrize("side", [1e-310, 1e305, float("inf")])
def test_sides_beyond_the_bound_are_refused_naming_it(side):
    with pytest.raises(ValueError, match=r"domain_side .* outside \[2\^-1000, 2\^1000\]"):
        dfvn.nn_stats(np.zeros((2, 2)), domain_side=side)


@pytest.mark.parametrize(
    "call, words",
    [
        (lambda: dfvn.sample("random", 3, n=2**40), r"n=1099511627776 in 3D .* lower n or raise the limit with max_memory_gib"),
        (lambda: dfvn.sample("jitter", 3, grid=100, max_memory_gib=1e-6), r"grid=100 in 3D .* max_memory_gib"),
        (lambda: dfvn.sample("cnj", 3, grid=4, cycles_per_spacing=1e15), r"cycles_per_spacing=1e\+15 .* grid=4"),
        (lambda: dfvn.CNJ(3, cycles_per_spacing=1e15).random(grid=4), r"cycles_per_spacing=1e\+15 .* grid=4"),
        (lambda: dfvn.nn_stats(np.full((3, 2), 0.75), domain_side=0.5), r"give the side with domain_side"),
    ],
)
def test_messages_name_the_keywords_not_the_command_line_options(call, words):
    """Issue 23: the library's messages named --grid and --max-memory, which Python does not have."""
    with pytest.raises(ValueError, match=words) as raised:
        call()
    assert "--" not in str(raised.value)
