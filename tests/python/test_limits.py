"""Issue 40 in Python: extreme parameters computed or refused with their range, an empty ball refused, and
every refusal one line (ValueError, TypeError or MemoryError) that names the keyword. Each failed on main
9f7cabe."""
import numpy as np
import pytest

import dfvn

POINTS = np.array([[0.1, 0.2], [0.6, 0.7], [0.3, 0.9]])


@pytest.mark.parametrize("radius", [1e-310, 5e-324])
@pytest.mark.parametrize("dim", [2, 3, 5])
def test_an_obstacle_of_subnormal_radius_is_finite_at_its_centre(dim, radius):
    centre = ",".join(["0.5"] * dim)
    c, f = dfvn.field(np.full((2, dim), 0.5), domain="cube", obstacles=[f"sphere:{centre},{radius}"])
    assert np.isfinite(c).all() and np.isfinite(f).all()


# Bit for bit when U is a power of two times the unit one's; within 1e-12 when its scaling rounds (1e-300).
@pytest.mark.parametrize("tiny, unit, exact", [((2.0 ** -1000, 2.0 ** -1000), (1.0, 1.0), True),
                                               ((2.0 ** 1000, 2.0 ** 1000), (1.0, 1.0), True),
                                               ((5e-324, 0.0), (1.0, 0.0), True),
                                               ((1e-300, 1e-300), (1.0, 1.0), False),
                                               ((1e-310, -1e-310), (1.0, -1.0), False)])
def test_a_direction_of_extreme_length_is_its_unit_direction(tiny, unit, exact):
    same = np.array_equal if exact else (lambda a, b: np.allclose(a, b, rtol=1e-12, atol=1e-12))
    assert same(dfvn.field(POINTS, stretch=(tiny, 2.0))[0], dfvn.field(POINTS, stretch=(unit, 2.0))[0])
    assert same(dfvn.field(POINTS, noise="steerable", steer=tiny)[0], dfvn.field(POINTS, noise="steerable", steer=unit)[0])


def test_a_ramp_beyond_two_to_the_fifty_is_refused_naming_it():
    for call in (lambda: dfvn.field(POINTS, lift="plane:1,0", lift_ramp=1e20),
                 lambda: dfvn.trace(POINTS, 0.1, lift="plane:1,0", lift_ramp=1e308)):
        with pytest.raises(ValueError, match=r"^lift_ramp must be in \[-2\^50, 2\^50\]"):
            call()
    c, _ = dfvn.field(POINTS, lift="plane:1,0", lift_ramp=2.0 ** 50)
    assert np.isfinite(c).all()


@pytest.mark.parametrize("dim", [4, 5, 8])
def test_a_ball_without_a_lattice_site_is_an_error_naming_the_smallest_grid(dim):
    with pytest.raises(ValueError, match=r"no site of the 2\^%d lattice of grid=2; the smallest grid with a site inside is 3"
                       % dim):
        dfvn.sample("cnj", dim, grid=2, domain="ball")
    assert len(dfvn.sample("cnj", dim, grid=3, domain="ball")) >= 1


@pytest.mark.parametrize("kwargs, error, words", [
    (dict(seed=""), TypeError, "field(): seed must be an integer in [0, 2^64), got '' (str)"),
    (dict(seed=-1), ValueError, "field(): seed must be an integer in [0, 2^64), got -1 (int)"),
    (dict(seed=2 ** 64), ValueError, "field(): seed must be an integer in [0, 2^64)"),
    (dict(frequency="x"), TypeError, "field(): frequency must be a real number, got 'x' (str)"),
    (dict(frequency=10 ** 400), ValueError, "field(): frequency must be a real number"),
    (dict(obstacles="sphere:0.5,0.5,0.1"), TypeError, "field(): obstacles must be a list of str"),
    (dict(threads=2 ** 40), ValueError, "field(): threads must be an integer in [-2^31, 2^31)"),
    (dict(bogus=1), TypeError, "field() got an unexpected keyword argument 'bogus'"),
    (dict(domain="cube", boundary_width=0.0), ValueError, "boundary_width (the boundary's transition width) must be in"),
    (dict(domain="cube", obstacles=["sphere:0.5,0.5,-1e-300"]), ValueError, "the radius must be positive, got -1e-300"),
    (dict(noise="x\ny"), ValueError, "unknown noise basis 'x\\ny'"),
])
def test_a_bad_argument_is_one_line_naming_its_keyword(kwargs, error, words):
    with pytest.raises(error) as raised:
        dfvn.field(POINTS, **kwargs)
    message = str(raised.value)
    assert words in message and "\n" not in message and "incompatible function arguments" not in message, message


@pytest.mark.parametrize("call, words", [
    (lambda: dfvn.sample("cnj", 2, grid=4, phase="x"), "phase must be a real number, not str"),
    (lambda: dfvn.sample("cnj", 2, grid=4, cycles_per_spacing=None), "cycles_per_spacing must be a real number"),
    (lambda: dfvn.sample("cnj", 2, grid=4, cycles_per_spacing=0.0), "cycles_per_spacing (CNJ's frequency"),
    (lambda: dfvn.nn_stats(POINTS, knn="x"), "knn: unknown KD-tree backend 'x'"),
    (lambda: dfvn.rdf(POINTS, bins="x"), "rdf(): bins must be an integer"),
    (lambda: dfvn.trace(POINTS, "x"), "trace(): t must be a real number"),
])
def test_the_other_functions_name_their_keyword_too(call, words):
    with pytest.raises((ValueError, TypeError)) as raised:
        call()
    assert words in str(raised.value) and "\n" not in str(raised.value), str(raised.value)


def test_memory_that_cannot_be_had_is_a_memory_error_with_its_size():
    with pytest.raises(MemoryError, match=r"^out of memory: cannot allocate 16\.0 PiB; try a smaller problem$"):
        dfvn.Random(2, seed=1).random(2 ** 50)
    with pytest.raises(MemoryError, match=r"^out of memory: more elements than an array can hold"):  # not max_size()
        dfvn.Random(8, seed=1).random(2 ** 60)


@pytest.mark.parametrize("periodic", [False, True])
def test_statistics_of_points_in_a_corner_of_a_huge_domain_end_cleanly(periodic):
    # The domain's scale and the coordinates' went back and forth for ever (a stack overflow, SIGSEGV).
    r, g = dfvn.rdf(POINTS, domain_side=1e300, periodic=periodic)
    assert np.isfinite(r).all() and np.isfinite(g).all()
    if periodic:
        with pytest.raises(ValueError, match="closer than 2\\^-510"):
            dfvn.nn_stats(POINTS, domain_side=1e300, periodic=True)
    assert dfvn.nn_stats(POINTS, domain_side=1e100, periodic=periodic)["points"] == 3


def test_random_base2_refuses_m_beyond_sobols_points_before_computing_two_to_the_m():
    # 2 ** (2 ** 63) was computed first: a call that never returned.
    with pytest.raises(ValueError, match=r"^m must be at most 32 \(Sobol supports at most 2\^32 points\), got 9223372036854775808$"):
        dfvn.Sobol(2, seed=1).random_base2(2 ** 63)
