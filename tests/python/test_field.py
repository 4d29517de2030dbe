"""dfvn.field and dfvn.trace: the CLI's numbers, NumPy in and out, clear errors."""
import numpy as np
import pytest

import dfvn


def random_points(n, dim, seed, scale=4.0):
    return np.random.default_rng(seed).uniform(-scale, scale, size=(n, dim))


@pytest.mark.parametrize("dim", [2, 3, 5, 8])
@pytest.mark.parametrize("noise", ["turning-bands", "simplex", "quintic-gradient"])
def test_field_equals_the_cli_bit_for_bit(cli, tmp_path, dim, noise):
    points = random_points(200, dim, seed=dim)
    path = tmp_path / "points.csv"
    np.savetxt(path, points, delimiter=",", fmt="%.17g")
    out = cli("field", "--dim", dim, "--seed", 11, "--frequency", 0.7, "--noise", noise, "--input", path)
    table = np.loadtxt(out.splitlines()[1:], delimiter=",", ndmin=2)
    c, f = dfvn.field(points, seed=11, frequency=0.7, noise=noise)
    assert c.shape == (200, dim) and f.shape == (200, dim - 1)
    assert c.dtype == np.float64 and c.flags.c_contiguous
    np.testing.assert_array_equal(table[:, :dim], points)  # 17 digits read back exactly
    np.testing.assert_array_equal(table[:, dim:2 * dim], c)
    np.testing.assert_array_equal(table[:, 2 * dim:], f)


def test_field_is_divergence_free_and_rms_one():
    points = random_points(20000, 4, seed=3, scale=50.0)
    c, _ = dfvn.field(points, seed=2)
    assert abs(np.sqrt(np.mean(np.sum(c * c, axis=1))) - 1.0) < 0.05
    # Central differences of one component sum, by points: div c = sum_j d c_j / d x_j ~ 0.
    h = 1e-5
    divergence = np.zeros(len(points[:500]))
    for j in range(4):
        step = np.zeros(4)
        step[j] = h
        plus, _ = dfvn.field(points[:500] + step, seed=2)
        minus, _ = dfvn.field(points[:500] - step, seed=2)
        divergence += (plus[:, j] - minus[:, j]) / (2 * h)
    assert np.max(np.abs(divergence)) < 1e-5


def test_field_converts_other_layouts_and_types_to_the_same_result():
    points = random_points(50, 3, seed=5).astype(np.float32).astype(np.float64)  # exact in float32 too
    c, f = dfvn.field(points, seed=4)
    for other in (np.asfortranarray(points), points.astype(np.float32), points.tolist()):
        c2, f2 = dfvn.field(other, seed=4)
        np.testing.assert_array_equal(c2, c)
        np.testing.assert_array_equal(f2, f)
    wide = np.zeros((50, 6))
    wide[:, ::2] = points  # a strided view: converted, same numbers
    np.testing.assert_array_equal(dfvn.field(wide[:, ::2], seed=4)[0], c)


def test_field_does_not_depend_on_threads():
    points = random_points(5000, 7, seed=6)
    one = dfvn.field(points, seed=9, threads=1)
    many = dfvn.field(points, seed=9, threads=4)
    np.testing.assert_array_equal(one[0], many[0])
    np.testing.assert_array_equal(one[1], many[1])


@pytest.mark.parametrize(
    "points, kwargs, error, words",
    [
        (np.zeros((3, 9)), {}, ValueError, "columns"),
        (np.zeros((3, 1)), {}, ValueError, "columns"),
        (np.zeros(3), {}, ValueError, "2-D"),
        (np.array([[0.0, np.nan, 0.0]]), {}, ValueError, "point 1"),
        (np.array([[0.0, 1e300, 0.0]]), {}, ValueError, "point 1"),
        (np.zeros((2, 3)), {"noise": "perlin"}, ValueError, "perlin"),
        (np.zeros((2, 3)), {"frequency": 0.0}, ValueError, "frequency"),
        (np.zeros((2, 3)), {"threads": -1}, ValueError, "thread"),
        (np.array([["a", "b", "c"]]), {}, (TypeError, ValueError), ""),
    ],
)
def test_field_refuses_bad_input_with_a_clear_error(points, kwargs, error, words):
    with pytest.raises(error, match=words):
        dfvn.field(points, **kwargs)


def test_empty_input_gives_empty_output():
    c, f = dfvn.field(np.zeros((0, 3)))
    assert c.shape == (0, 3) and f.shape == (0, 2)


def test_trace_stays_on_the_iso_contours_only_with_reprojection():
    points = random_points(300, 5, seed=8)
    _, f0 = dfvn.field(points, seed=3)
    kept = dfvn.field(dfvn.trace(points, 0.05, seed=3, steps=4), seed=3)[1]
    np.testing.assert_allclose(kept, f0, rtol=0, atol=1e-9)  # Gauss-Newton reprojection keeps every f_i
    drifted = dfvn.field(dfvn.trace(points, 0.05, seed=3, steps=4, reprojection="none"), seed=3)[1]
    assert np.max(np.abs(drifted - f0)) > 1e-8  # without it, RK4's error moves them off


def test_trace_moves_by_c_t_for_a_short_time():
    points = random_points(300, 5, seed=8)
    c0, _ = dfvn.field(points, seed=3)
    t = 1e-4  # the second-order term, t^2 |Dc| |c| / 2, is then far below the tolerance
    moved = dfvn.trace(points, t, seed=3, steps=4)
    np.testing.assert_allclose(moved - points, c0 * t, rtol=0, atol=0.05 * t)


def test_trace_matches_a_fine_euler_reference_and_runs_backwards():
    points = random_points(50, 3, seed=9)
    t = 0.1
    rk4 = dfvn.trace(points, t, seed=1, integrator="rk4", reprojection="none", steps=8)
    euler = dfvn.trace(points, t, seed=1, integrator="euler", reprojection="none", steps=20000)
    np.testing.assert_allclose(rk4, euler, atol=1e-5)
    back = dfvn.trace(rk4, -t, seed=1, integrator="rk4", reprojection="none", steps=8)
    np.testing.assert_allclose(back, points, atol=1e-5)  # RK4's error, as above
    np.testing.assert_array_equal(dfvn.trace(points, 0.0, seed=1, reprojection="none"), points)


def test_trace_refuses_bad_options():
    points = np.zeros((2, 3))
    with pytest.raises(ValueError, match="steps"):
        dfvn.trace(points, 0.1, steps=0)
    with pytest.raises(ValueError, match="integrator"):
        dfvn.trace(points, 0.1, integrator="midpoint")
    with pytest.raises(ValueError, match="finite"):
        dfvn.trace(points, float("inf"))


@pytest.mark.parametrize("domain, extra", [("torus", []), ("cube", ["--bound", "ramp", "--boundary-width", 0.15]),
                                           ("ball", [])])
def test_field_domains_equal_the_cli(cli, tmp_path, domain, extra):
    points = np.random.default_rng(7).random((100, 3))
    path = tmp_path / "points.csv"
    np.savetxt(path, points, delimiter=",", fmt="%.17g")
    out = cli("field", "--dim", 3, "--seed", 4, "--frequency", 1.5, "--domain", domain, *extra, "--input", path)
    table = np.loadtxt(out.splitlines()[1:], delimiter=",", ndmin=2)
    options = {"bound": "ramp", "boundary_width": 0.15} if extra else {}
    c, f = dfvn.field(points, seed=4, frequency=1.5, domain=domain, **options)
    np.testing.assert_array_equal(table[:, 3:6], c)
    np.testing.assert_array_equal(table[:, 6:], f)


def test_trace_on_the_torus_wraps_and_in_the_cube_stays_inside():
    points = np.random.default_rng(9).random((300, 4))
    ends = dfvn.trace(points, 0.4, frequency=1.2, domain="torus", steps=2)
    assert ends.min() >= 0.0 and ends.max() < 1.0
    free = dfvn.trace(points + 1.0, 0.4, frequency=1.2, domain="torus", steps=2)
    np.testing.assert_allclose(free, ends, atol=1e-10)  # period 1: the shifted starts end at the same points
    inside = dfvn.trace(points, 0.4, frequency=1.2, domain="cube", bound="ramp", boundary_width=0.05)
    assert inside.min() >= 0.0 and inside.max() <= 1.0
    with pytest.raises(ValueError, match="bound and boundary_width apply"):
        dfvn.trace(points, 0.4, domain="torus", bound="ramp")
    with pytest.raises(ValueError, match="periodic noise basis"):
        dfvn.field(points, domain="torus", noise="simplex")
