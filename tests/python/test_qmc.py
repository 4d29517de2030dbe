"""dfvn's scipy.stats.qmc engines: what SciPy's own suite (test_scipy_qmc_suite.py) does not check. SciPy's
consumers take them, seeds as SciPy takes them (and 128-bit ones), exact shapes and counts, the set
engines' count contract, Poisson disk sampling that grows one sample, Sobol up to 21201 dimensions and
64 bits, Halton in any dimension, the engines without SciPy, discrepancy as SciPy's."""
import inspect
import math
import re
import subprocess
import sys
import warnings

import numpy as np
import pytest
from scipy.spatial import distance
from scipy.stats import qmc

import dfvn
from dfvn import _core

SEQUENCES = [dfvn.Sobol, dfvn.Halton, dfvn.Random]
LATTICES = [dfvn.CNJ, dfvn.Jitter, dfvn.JitterMatched]
ENGINES = SEQUENCES + LATTICES + [dfvn.LatinHypercube, dfvn.PoissonDisk]


def quiet(draw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return draw()


# SciPy's consumers and base class ---------------------------------------------------------------------

@pytest.mark.parametrize("engine_class", ENGINES)
def test_every_engine_is_a_scipy_qmc_engine_that_scipys_consumers_take(engine_class):
    engine = engine_class(2, seed=1)
    assert isinstance(engine, qmc.QMCEngine) and isinstance(engine, dfvn.QMCEngine)
    normal = quiet(lambda: qmc.MultivariateNormalQMC(mean=[0, 0], engine=engine).random(8))
    assert normal.shape[1] == 2 and len(normal) <= 8 and np.isfinite(normal).all()
    # SciPy 1.11's integrate.qmc_quad makes its further engines as type(qrng)(seed=..., **qrng._init_quad).
    again = type(engine)(seed=2, **engine._init_quad)
    assert type(again) is engine_class and again.d == 2 and quiet(lambda: again.random(4)).shape[1] == 2


def test_the_issues_one_liners():
    points = qmc.MultivariateNormalQMC(mean=[0, 0], engine=dfvn.Sobol(2, seed=1)).random(8)
    assert points.shape == (8, 2)
    assert dfvn.Sobol(d=1000, seed=np.random.SeedSequence().entropy).random(2**10).shape == (1024, 1000)


@pytest.mark.parametrize("engine_class", [dfvn.Sobol, dfvn.Halton, dfvn.Random, dfvn.LatinHypercube])
def test_multinomial_qmc_takes_the_one_dimensional_engines(engine_class):
    draws = qmc.MultinomialQMC([0.2, 0.3, 0.5], n_trials=64, engine=engine_class(1, seed=5)).random(4)
    assert draws.shape == (4, 3) and (draws.sum(axis=1) == 64).all()


@pytest.mark.parametrize("engine_class", ENGINES)
@pytest.mark.parametrize("optimization", ["random-cd", "lloyd"])
def test_scipys_optimizers_run_on_every_draw(engine_class, optimization):
    plain = quiet(lambda: engine_class(2, seed=3).random(64))
    optimized = quiet(lambda: engine_class(2, seed=3, optimization=optimization).random(64))
    assert optimized.shape == plain.shape and not np.array_equal(optimized, plain)
    if optimization == "random-cd":  # coordinates swapped between points: each column keeps its values
        np.testing.assert_array_equal(np.sort(optimized, axis=0), np.sort(plain, axis=0))
        assert qmc.discrepancy(optimized) < qmc.discrepancy(plain)


def test_integers_and_num_generated_count_points():
    engine = dfvn.Sobol(3, seed=4)
    values = engine.integers([0, -5, 10], u_bounds=[2, 5, 11], n=64)
    assert values.dtype == np.int64 and values.shape == (64, 3)
    assert values[:, 0].min() == 0 and values[:, 0].max() == 1 and (values[:, 2] == 10).all()
    assert values[:, 1].min() == -5 and values[:, 1].max() == 4
    assert engine.num_generated == 64
    np.testing.assert_array_equal(values, np.floor(dfvn.Sobol(3, seed=4).random(64) * [2, 10, 1] + [0, -5, 10]))
    with pytest.raises(ValueError, match="must be integers"):
        engine.integers(1.5)
    jitter = dfvn.Jitter(2, seed=1)
    quiet(lambda: jitter.random(10))
    assert jitter.num_generated == 9  # 3^2 points, not the 10 asked nor one call


# Seeds ---------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("engine_class", ENGINES)
def test_seeds_as_scipy_takes_them_and_128_bit_ones(engine_class):
    big = 2**127 + 12345  # np.random.SeedSequence().entropy is a 128-bit int
    draw = lambda seed: quiet(lambda: engine_class(2, seed=seed).random(16))  # noqa: E731
    np.testing.assert_array_equal(draw(big), draw(big))
    assert not np.array_equal(draw(big), draw(big + 1))
    # A SeedSequence is its entropy (np.random.default_rng takes either alike).
    np.testing.assert_array_equal(draw(np.random.SeedSequence(big)), draw(big))
    np.testing.assert_array_equal(draw(np.random.default_rng(9)), draw(np.random.default_rng(9)))
    np.testing.assert_array_equal(draw(np.random.RandomState(9)), draw(np.random.RandomState(9)))
    np.testing.assert_array_equal(draw(np.uint64(2**63 + 5)), draw(2**63 + 5))
    assert engine_class(2, seed=7).library_seed == 7  # below 2^64 the seed itself: dfvn-sample's --seed


def test_a_generator_seed_is_drawn_from_the_generator_which_moves_on():
    rng = np.random.default_rng(7)
    expected = int(np.random.default_rng(7).integers(0, 2**64, dtype=np.uint64))
    engine = dfvn.Sobol(3, seed=rng)
    assert engine.library_seed == expected and engine.rng is rng  # SciPy's engines use the given generator
    np.testing.assert_array_equal(engine.random(8), dfvn.Sobol(3, seed=expected).random(8))
    assert dfvn.Sobol(3, seed=rng).library_seed != expected


def test_seed_none_draws_fresh_entropy():
    assert dfvn.Sobol(2).library_seed != dfvn.Sobol(2).library_seed
    assert not np.array_equal(dfvn.CNJ(2).random(grid=4), dfvn.CNJ(2).random(grid=4))


@pytest.mark.parametrize("seed, words", [("one", "'one' cannot be used to seed"), (1.5, "cannot be used to seed"),
                                         (-1, "negative"), ([1, 2], "cannot be used to seed")])
@pytest.mark.parametrize("engine_class", [dfvn.Sobol, dfvn.CNJ])
def test_a_bad_seed_is_a_one_line_value_error_as_scipys(engine_class, seed, words):
    with pytest.raises(ValueError, match=words) as raised:
        engine_class(3, seed=seed)
    assert "\n" not in str(raised.value)
    with pytest.raises(ValueError):
        qmc.Sobol(3, seed=seed)  # SciPy raises the same kind


# Shapes and counts ---------------------------------------------------------------------------------------

@pytest.mark.parametrize("engine_class", ENGINES)
def test_dimension_zero_and_zero_points(engine_class):
    engine = engine_class(0, seed=1)
    for n in (0, 1, 5):
        assert quiet(lambda: engine.random(n)).shape == (n, 0)
    assert quiet(lambda: engine_class(3, seed=1).random(0)).shape == (0, 3)


@pytest.mark.parametrize("engine_class", SEQUENCES + [dfvn.LatinHypercube])
def test_sequences_and_latin_hypercubes_give_exactly_n(engine_class):
    engine = engine_class(4, seed=2)
    for n in (1, 2, 3, 7, 100, 129):
        points = quiet(lambda: engine.random(n))
        assert points.shape == (n, 4) and points.dtype == np.float64
        assert points.min() >= 0.0 and points.max() < 1.0


@pytest.mark.parametrize("engine_class", LATTICES)
@pytest.mark.parametrize("d", [2, 3])
def test_lattice_engines_take_the_largest_lattice_below_n(engine_class, d):
    """Never more than n: K^d with K the largest such that K^d <= n; one uniform point below 2^d."""
    engine = engine_class(d, seed=3)
    for n in range(0, 70):
        points = quiet(lambda: engine.random(n))
        k = max(k for k in range(0, 10) if k**d <= n)
        assert points.shape == (k**d, d), f"n = {n}"
        assert points.min(initial=0.0) >= 0.0 and points.max(initial=0.0) <= 1.0
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the count asked, no warning
        assert engine.random(4**d).shape == (4**d, d)
    with pytest.warns(UserWarning, match=rf"{engine_class.__name__}: {3**d} points instead of the {4**d - 1} asked "
                                         rf"\(the largest K\^d <= n: 3\^{d} = {3**d}\)"):
        engine.random(4**d - 1)


def test_fewer_points_than_the_lattice_warn_naming_why():
    with pytest.warns(UserWarning, match=r"CNJ: \d+ points instead of the 1000 asked \(the ball's sites"):
        assert len(dfvn.CNJ(3, seed=1, domain="ball").random(1000)) < 1000
    with pytest.warns(UserWarning, match=r"CNJ: \d+ points instead of the 1000 asked \(\d+ dropped"):
        assert len(dfvn.CNJ(3, seed=1, domain_mode="drop").random(1000)) < 1000
    with pytest.warns(UserWarning, match=r"PoissonDisk: \d+ points instead of the 1000 asked .*saturated"):
        assert len(dfvn.PoissonDisk(2, seed=1, radius=0.2).random(1000)) < 1000


@pytest.mark.parametrize("engine_class", LATTICES + [dfvn.LatinHypercube])
def test_set_engines_give_a_new_set_per_call_and_reset_replays(engine_class):
    engine = engine_class(3, seed=40)
    sets = [quiet(lambda: engine.random(64)) for _ in range(3)]
    assert engine.num_generated == 3 * 64
    assert not np.array_equal(sets[0], sets[1])
    np.testing.assert_array_equal(quiet(lambda: engine.reset().random(64)), sets[0])
    engine.reset().fast_forward(64)  # SciPy's: random(64) dropped, so the next call is the second set
    np.testing.assert_array_equal(quiet(lambda: engine.random(64)), sets[1])
    # Set k is the set of library_seed + k, as `dfvn-sample --seed s --realizations R` numbers them.
    np.testing.assert_array_equal(quiet(lambda: engine_class(3, seed=41).random(64)), sets[1])


@pytest.mark.parametrize("engine_class, method, options", [
    (dfvn.CNJ, "cnj", {"cycles_per_spacing": 0.3, "domain": "cube", "bound": "ramp"}),
    (dfvn.CNJ, "cnj", {"domain": "ball"}),
    (dfvn.JitterMatched, "jitter-matched", {"domain": "cube"}),
    (dfvn.Jitter, "jitter", {}),
])
@pytest.mark.parametrize("protocol", ["unit", "paper"])
def test_a_lattice_engines_first_set_is_dfvn_sample_and_the_command_lines(engine_class, method, options, protocol):
    for size in ({"grid": 5}, {"n": 125}):
        old = _core._generate(method, 3, seed=11, protocol=protocol, grid=5, **options)[0]
        np.testing.assert_array_equal(quiet(lambda: dfvn.sample(method, 3, seed=11, protocol=protocol, **size,
                                                                **options)), old)
        engine = engine_class(3, seed=11, protocol=protocol, **options)
        np.testing.assert_array_equal(quiet(lambda: engine.random(**size)), old)


@pytest.mark.parametrize("engine_class, method, options", [
    (dfvn.Sobol, "sobol", {"scramble": False}), (dfvn.Sobol, "sobol", {}), (dfvn.Halton, "halton", {}),
    (dfvn.Random, "random", {}), (dfvn.LatinHypercube, "lhs", {}),
    (dfvn.PoissonDisk, "pds", {"radius": 0.15, "ncandidates": 10}),
])
def test_the_other_engines_first_draw_is_dfvn_sample_and_the_command_lines(engine_class, method, options):
    old = _core._generate(method, 3, seed=11, n=200, **options)[0]
    np.testing.assert_array_equal(quiet(lambda: dfvn.sample(method, 3, seed=11, n=200, **options)), old)
    np.testing.assert_array_equal(quiet(lambda: engine_class(3, seed=11, **options).random(200)), old)


def test_sample_warns_at_its_callers_line_naming_both_counts():
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        assert len(dfvn.sample("jitter", 3, n=500)) == 512  # dfvn-sample's nearest lattice
    assert len(caught) == 1 and caught[0].filename == __file__
    assert re.search(r"Jitter: 512 points instead of the 500 asked .*8\^3 = 512", str(caught[0].message))


# Poisson disk sampling: one sample that grows ---------------------------------------------------------------

def min_distance(points):
    return distance.pdist(points).min()


def test_poisson_disk_calls_continue_one_sample():
    engine = dfvn.PoissonDisk(2, seed=6)
    assert engine.radius == 0.05  # SciPy's default
    parts = [engine.random(n) for n in (1, 40, 0, 100)]
    assert [len(p) for p in parts] == [1, 40, 0, 100] and engine.num_generated == 141
    whole = np.vstack(parts)
    np.testing.assert_array_equal(whole, dfvn.PoissonDisk(2, seed=6).random(141))
    assert min_distance(whole) >= 0.05
    rest = engine.fill_space()
    full = np.vstack([whole, rest])
    assert min_distance(full) >= 0.05 and engine.num_generated == len(full) > 250
    with pytest.warns(UserWarning, match="saturated"):
        assert engine.random(5).shape == (0, 2)  # the domain is full
    np.testing.assert_array_equal(engine.reset().random(141), whole)
    np.testing.assert_array_equal(dfvn.PoissonDisk(2, seed=6).fill_space(), full)


def test_poisson_disk_default_radius_gives_n_where_n_fits():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        points = dfvn.PoissonDisk(2, seed=1).random(250)
    assert points.shape == (250, 2) and min_distance(points) >= 0.05
    assert points.min() >= 0.0 and points.max() <= 1.0


# Dimensions and bits ------------------------------------------------------------------------------------

def test_sobol_in_all_21201_dimensions_is_scipys_unscrambled():
    ours = dfvn.Sobol(21201, scramble=False).random(64)
    np.testing.assert_array_equal(ours, qmc.Sobol(21201, scramble=False).random(64))
    scrambled = dfvn.Sobol(21201, seed=3).random(64)
    assert scrambled.shape == (64, 21201) and 0.0 <= scrambled.min() and scrambled.max() < 1.0
    with pytest.raises(ValueError, match="Maximum supported dimensionality is 21201"):
        dfvn.Sobol(21202)


@pytest.mark.parametrize("scramble", [False, True])
def test_sobol_bits_up_to_64(scramble):
    """bits 33..64: the sequence carried to 64 digits, 2^bits points; bits <= 32 the 32-digit sequence."""
    for bits in (1, 5, 32):
        np.testing.assert_array_equal(dfvn.Sobol(3, bits=bits, scramble=scramble, seed=2).random(2**min(bits, 10)),
                                      dfvn.Sobol(3, scramble=scramble, seed=2).random(2**min(bits, 10)))
    wide = dfvn.Sobol(5, bits=64, scramble=scramble, seed=2)
    points = wide.random(1024)
    assert points.shape == (1024, 5) and points.min() >= 0.0 and points.max() < 1.0
    assert ((points < 0.5).sum(axis=0) == 512).all()  # balanced at 2^m
    if not scramble:
        np.testing.assert_array_equal(points, qmc.Sobol(5, scramble=False, bits=64).random(1024))
    far = dfvn.Sobol(5, bits=64, scramble=scramble, seed=2).fast_forward(2**40)
    tail = far.random(4)
    assert tail.shape == (4, 5) and far.num_generated == 2**40 + 4
    with pytest.raises(ValueError, match="At most 2\\*\\*3=8 distinct points .* Consider increasing `bits`"):
        dfvn.Sobol(2, bits=3).random(16)
    with pytest.raises(ValueError, match="Maximum supported 'bits' is 64"):
        dfvn.Sobol(2, bits=65)


def test_halton_in_any_dimension_is_scipys_unscrambled():
    np.testing.assert_allclose(dfvn.Halton(300, scramble=False).random(100),
                               qmc.Halton(300, scramble=False).random(100), rtol=0, atol=1e-15)
    points = dfvn.Halton(2000, seed=1).random(16)
    assert points.shape == (16, 2000) and 0.0 <= points.min() and points.max() < 1.0


@pytest.mark.parametrize("engine_class, options", [(dfvn.Sobol, {"scramble": True}), (dfvn.Sobol, {"scramble": False}),
                                                   (dfvn.Sobol, {"bits": 64}), (dfvn.Sobol, {"bits": 64, "scramble": False}),
                                                   (dfvn.Halton, {"scramble": True}), (dfvn.Halton, {"scramble": False}),
                                                   (dfvn.Random, {})])
@pytest.mark.parametrize("k", [1, 5, 100, 4097])
@pytest.mark.parametrize("d", [5, 17])
def test_fast_forward_then_random_is_the_tail_of_one_long_draw(engine_class, options, k, d):
    whole = quiet(lambda: engine_class(d, seed=99, **options).random(k + 300))
    engine = engine_class(d, seed=99, **options).fast_forward(k)
    np.testing.assert_array_equal(quiet(lambda: engine.random(300)), whole[k:])
    assert engine.num_generated == k + 300
    pieces = engine_class(d, seed=99, **options)
    np.testing.assert_array_equal(quiet(lambda: np.vstack([pieces.random(k), pieces.random(300)])), whole)


@pytest.mark.parametrize("engine_class, options", [(dfvn.Sobol, {}), (dfvn.Sobol, {"bits": 64}), (dfvn.Halton, {}),
                                                   (dfvn.Random, {})])
def test_workers_never_change_the_points(engine_class, options):
    a = engine_class(6, seed=3, **options).random(2**14, workers=1)
    np.testing.assert_array_equal(a, engine_class(6, seed=3, **options).random(2**14, workers=-1))
    whole = engine_class(6, seed=3, **options).random(3 * 2**14, workers=1)
    for workers in (1, 2, -1):
        later = engine_class(6, seed=3, **options).fast_forward(2**14 + 3)
        np.testing.assert_array_equal(quiet(lambda: later.random(2**15 - 3, workers=workers)), whole[2**14 + 3:])
    np.testing.assert_array_equal(dfvn.CNJ(3, seed=3).random(grid=6, workers=1),
                                  dfvn.CNJ(3, seed=3).random(grid=6, workers=2))


def test_a_scipy_loop_ports_by_changing_the_class_name():
    def loop(engine_class):
        engine = engine_class(d=4, scramble=True, seed=12345)
        first, second = engine.random(64), engine.random(64)
        engine.reset()
        replay = engine.random(128)
        engine.reset().fast_forward(64)
        return first, second, replay, engine.random(64)

    for engine_class in (qmc.Sobol, dfvn.Sobol, qmc.Halton, dfvn.Halton):
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # powers of 2 throughout: neither library may warn
            first, second, replay, tail = loop(engine_class)
        np.testing.assert_array_equal(replay, np.vstack([first, second]))
        np.testing.assert_array_equal(tail, second)


# Errors --------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("call, error, words", [
    (lambda: dfvn.Halton(-1), ValueError, "d must be a non-negative integer value"),
    (lambda: dfvn.CNJ(d=1.5), ValueError, "d must be a non-negative integer value"),
    (lambda: dfvn.CNJ(9), ValueError, "d must be 0 or in 2..8 for CNJ, got 9"),
    (lambda: dfvn.PoissonDisk(1), ValueError, "d must be 0 or in 2..8 for PoissonDisk, got 1"),
    (lambda: dfvn.PoissonDisk(2, hypersphere="toto"), ValueError, "'toto' is not a valid hypersphere"),
    (lambda: dfvn.PoissonDisk(2, hypersphere="surface"), ValueError, "'surface' is not available"),
    (lambda: dfvn.PoissonDisk(2, radius=0.0), ValueError, "radius must be a finite number > 0"),
    (lambda: dfvn.LatinHypercube(2, strength=3), ValueError, "3 is not a valid strength"),
    (lambda: dfvn.LatinHypercube(2, strength=2).random(16), ValueError, "n is not the square of a prime"),
    (lambda: dfvn.LatinHypercube(5, strength=2).random(9), ValueError, "n is too small for d"),
    (lambda: dfvn.Sobol(2, optimization="toto"), ValueError, "'toto' is not a valid optimization method"),
    (lambda: dfvn.CNJ(3, frequency=2.0), TypeError, "cycles_per_spacing .* cycles per unit length"),
    (lambda: dfvn.JitterMatched(3, frequency=2.0), TypeError, "cycles_per_spacing"),
    (lambda: dfvn.Jitter(3, scramble=True), TypeError, "unexpected keyword argument 'scramble'"),
    (lambda: dfvn.Sobol(3).random(-1), ValueError, "n must be at least 0"),
    (lambda: dfvn.Sobol(3).fast_forward(-1), ValueError, "n must be at least 0"),
    (lambda: dfvn.Sobol(3).random(4, workers=0), ValueError, "Invalid number of workers: 0, must be -1 or > 0"),
    (lambda: dfvn.Sobol(3).fast_forward(2**32).random(1), ValueError, "At most 2\\*\\*32=4294967296 distinct points"),
    (lambda: dfvn.CNJ(3).random(8, grid=3), ValueError, "give one of n .* and grid"),
    (lambda: dfvn.CNJ(3, domain="klein").random(64), ValueError, "klein"),
    (lambda: dfvn.CNJ(3, domain="torus", bound="ramp").random(64), ValueError, "bound applies"),
    (lambda: dfvn.JitterMatched(3, domain="ball").random(64), ValueError, "jitter-matched"),
])
def test_engines_refuse_bad_arguments_in_one_line(call, error, words):
    with pytest.raises(error, match=words) as raised:
        call()
    assert "\n" not in str(raised.value)


def test_latin_hypercube_strength_2_and_centred_as_scipys():
    with pytest.warns(UserWarning, match="'centered' is deprecated"):
        centred = dfvn.LatinHypercube(3, centered=True, seed=1).random(10)
    np.testing.assert_array_equal(np.sort(centred, axis=0), np.tile((np.arange(10)[:, None] + 0.5) / 10, (1, 3)))
    oa = dfvn.LatinHypercube(4, strength=2, seed=1).random(49)
    for i in range(4):  # an LHS of 49 points, and every pair of axes holds all 7 x 7 coarse cells
        assert sorted((oa[:, i] * 49).astype(int)) == list(range(49))
        for j in range(i):
            assert len({(a, b) for a, b in (oa[:, [i, j]] * 7).astype(int)}) == 49


# Without SciPy -------------------------------------------------------------------------------------------

def test_the_engines_work_without_scipy():
    program = """
import sys
sys.modules["scipy"] = None  # import scipy fails
import numpy as np, dfvn
for engine_class in (dfvn.Sobol, dfvn.Halton, dfvn.Random, dfvn.CNJ, dfvn.Jitter, dfvn.LatinHypercube, dfvn.PoissonDisk):
    engine = engine_class(2, seed=2**70)
    assert engine.random(16).shape == (16, 2) and engine.num_generated == 16, engine_class
    assert engine.reset().integers(4, n=16).dtype == np.int64
assert dfvn.Sobol(3, seed=1).random(8).tolist() == dfvn.sample("sobol", 3, n=8, seed=1).tolist()
try:
    dfvn.Sobol(2, optimization="random-cd")
except ValueError as e:
    assert "needs SciPy" in str(e)
else:
    raise AssertionError("optimization without SciPy")
print("ok")
"""
    done = subprocess.run([sys.executable, "-c", program], capture_output=True, text=True)
    assert done.returncode == 0 and done.stdout == "ok\n", done.stderr


# Discrepancy ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("method", ["CD", "WD", "MD", "L2-star"])
@pytest.mark.parametrize("d", [1, 2, 5])
@pytest.mark.parametrize("iterative", [False, True])
def test_discrepancy_is_scipys(method, d, iterative):
    points = np.random.default_rng(d).random((257, d))
    expected = qmc.discrepancy(points, method=method, iterative=iterative)
    assert dfvn.discrepancy(points, method=method, iterative=iterative) == pytest.approx(expected, rel=1e-10)
    assert (dfvn.discrepancy(points.tolist(), method=method, iterative=iterative, workers=-1)
            == dfvn.discrepancy(points, method=method, iterative=iterative))


def test_update_discrepancy_is_scipys():
    points = np.random.default_rng(3).random((50, 4))
    start = dfvn.discrepancy(points[:-1], iterative=True)
    updated = dfvn.update_discrepancy(points[-1], points[:-1], start)
    assert updated == pytest.approx(qmc.update_discrepancy(points[-1], points[:-1], start), rel=1e-12)
    assert updated == pytest.approx(dfvn.discrepancy(points), rel=1e-10)


def test_discrepancy_defaults_nan_and_errors_as_scipys():
    points = dfvn.Sobol(3, seed=4).random(128)
    assert dfvn.discrepancy(points) == pytest.approx(qmc.discrepancy(points), rel=1e-10)  # CD by default
    with_nan = points.copy()
    with_nan[5, 1] = np.nan
    assert math.isnan(dfvn.discrepancy(with_nan)) and math.isnan(qmc.discrepancy(with_nan))
    for call, words in [(lambda: dfvn.discrepancy(points + 0.5), "Sample is not in unit hypercube"),
                        (lambda: dfvn.discrepancy(points[0]), "Sample is not a 2D array"),
                        (lambda: dfvn.discrepancy(points, method="cd"), "'cd' is not a valid method"),
                        (lambda: dfvn.discrepancy(points, method="XD"), "'XD' is not a valid method"),
                        (lambda: dfvn.discrepancy(points, workers=-2), "Invalid number of workers")]:
        with pytest.raises(ValueError, match=words):
            call()
    with pytest.raises(ValueError, match="'cd' is not a valid method"):
        qmc.discrepancy(points, method="cd")  # SciPy refuses lower case too


def test_every_engine_documents_every_parameter_with_its_default():
    for engine_class in ENGINES:
        for name, parameter in inspect.signature(engine_class.__init__).parameters.items():
            if name in ("self", "refused"):
                continue
            assert name in engine_class.__doc__, f"{engine_class.__name__} does not explain {name}"
            if parameter.default is not inspect.Parameter.empty:
                pattern = rf"\b{name}\b[^.]{{0,40}}\(default"
                assert re.search(pattern, engine_class.__doc__), f"{engine_class.__name__}: {name} without its default"
