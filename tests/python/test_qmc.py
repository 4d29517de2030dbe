"""The engines shaped like scipy.stats.qmc's (dfvn.Sobol, dfvn.CNJ, ...), seeds, count warnings, discrepancy."""
import re
import warnings

import numpy as np
import pytest
from scipy.stats import qmc

import dfvn
from dfvn import _core

SEQUENCES = [(qmc.Sobol, dfvn.Sobol), (qmc.Halton, dfvn.Halton)]
SET_ENGINES = [dfvn.CNJ, dfvn.Jitter, dfvn.JitterMatched, dfvn.PoissonDisk, dfvn.LatinHypercube]


def scipy_users_loop(engine_class, seed):
    """A SciPy user's loop over an engine; only the class differs between the two libraries."""
    engine = engine_class(d=4, scramble=True, seed=seed)
    assert engine.d == 4
    first = engine.random(64)
    second = engine.random(64)
    by_base2 = engine.random_base2(7) if hasattr(engine, "random_base2") else engine.random(128)
    engine.reset()
    replay = engine.random(128)
    engine.reset()
    engine.fast_forward(64)
    tail = engine.random(64)
    return first, second, by_base2, replay, tail


@pytest.mark.parametrize("scipy_class, dfvn_class", SEQUENCES, ids=["Sobol", "Halton"])
def test_a_scipy_loop_ports_by_changing_the_class_name(scipy_class, dfvn_class):
    for engine_class in (scipy_class, dfvn_class):
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # powers of 2 throughout: neither library may warn
            first, second, by_base2, replay, tail = scipy_users_loop(engine_class, seed=12345)
        for points, n in ((first, 64), (second, 64), (by_base2, 128), (replay, 128), (tail, 64)):
            assert points.shape == (n, 4) and points.dtype == np.float64
            assert points.min() >= 0.0 and points.max() < 1.0
        np.testing.assert_array_equal(replay, np.vstack([first, second]))  # reset() replays
        np.testing.assert_array_equal(tail, second)                       # fast_forward(64), then random(64)
        again = scipy_users_loop(engine_class, seed=12345)                 # the same seed, the same points
        for a, b in zip((first, second, by_base2, replay, tail), again):
            np.testing.assert_array_equal(a, b)
        other = scipy_users_loop(engine_class, seed=54321)[0]
        assert not np.array_equal(other, first)
        # The first 2^m points are balanced: every dyadic half of every axis (Sobol) holds half of them.
        if dfvn_class is dfvn.Sobol:
            assert ((replay < 0.5).sum(axis=0) == 64).all()


@pytest.mark.parametrize("engine_class, options", [(dfvn.Sobol, {"scramble": True}), (dfvn.Sobol, {"scramble": False}),
                                                   (dfvn.Halton, {"scramble": True}), (dfvn.Halton, {"scramble": False}),
                                                   (dfvn.Random, {})])
@pytest.mark.parametrize("k", [1, 5, 100, 4097])
def test_fast_forward_then_random_is_the_tail_of_one_long_draw(engine_class, options, k):
    """From point 0 the library's generators run; later starts compute points by their index alone."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        whole = engine_class(5, seed=99, **options).random(k + 300)
        engine = engine_class(5, seed=99, **options)
        engine.fast_forward(k)
        np.testing.assert_array_equal(engine.random(300), whole[k:])
        assert engine.num_generated == k + 300
        pieces = engine_class(5, seed=99, **options)
        np.testing.assert_array_equal(np.vstack([pieces.random(k), pieces.random(300)]), whole)


@pytest.mark.parametrize("method", ["sobol", "halton", "random"])
def test_sequences_start_far_into_the_sequence(method):
    later = _core._sequence(method, 3, 2**31 - 7, 16, 5, True)
    whole_block = _core._sequence(method, 3, 2**31 - 10, 19, 5, True)
    np.testing.assert_array_equal(later, whole_block[3:])
    assert later.min() >= 0.0 and later.max() < 1.0


def test_the_target_one_liner_cnj_with_a_generator_seed():
    e = dfvn.CNJ(d=3, seed=np.random.default_rng(1))
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # 1000 = 10^3: the lattice has the count asked, no warning
        points = e.random(1000)
    assert points.shape == (1000, 3) and points.dtype == np.float64
    assert points.min() >= 0.0 and points.max() < 1.0
    np.testing.assert_array_equal(points, dfvn.CNJ(d=3, seed=np.random.default_rng(1)).random(1000))
    assert not np.array_equal(points, dfvn.CNJ(d=3, seed=np.random.default_rng(2)).random(1000))


def test_a_generator_seed_is_drawn_from_the_generators_state():
    rng = np.random.default_rng(7)
    expected_seed = int(np.random.default_rng(7).integers(0, 2**64, dtype=np.uint64))
    engine = dfvn.Sobol(3, seed=rng)
    assert engine.rng_seed == expected_seed
    np.testing.assert_array_equal(engine.random(8), dfvn.Sobol(3, seed=expected_seed).random(8))
    assert dfvn.Sobol(3, seed=rng).rng_seed != expected_seed  # the generator moved on


def test_seed_none_draws_fresh_entropy():
    assert dfvn.Sobol(2).rng_seed != dfvn.Sobol(2).rng_seed
    assert not np.array_equal(dfvn.CNJ(2).random(grid=4), dfvn.CNJ(2).random(grid=4))


@pytest.mark.parametrize("seed, error, words", [
    ("one", TypeError, "seed must be None, an int or a numpy.random.Generator, not str"),
    (1.5, TypeError, "not float"),
    (True, TypeError, "not bool"),
    (np.random.RandomState(1), TypeError, "not RandomState"),
    (-1, ValueError, r"seed must be in \[0, 2\^64\)"),
    (2**64, ValueError, r"seed must be in \[0, 2\^64\)"),
])
@pytest.mark.parametrize("engine_class", [dfvn.Sobol, dfvn.CNJ])
def test_a_bad_seed_is_one_line_not_a_signature_dump(engine_class, seed, error, words):
    with pytest.raises(error, match=words) as raised:
        engine_class(3, seed=seed)
    assert "\n" not in str(raised.value) and "Invoked with" not in str(raised.value)


def test_numpy_integer_seeds_are_ints():
    np.testing.assert_array_equal(dfvn.Halton(3, seed=np.uint64(2**63 + 5)).random(4),
                                  dfvn.Halton(3, seed=2**63 + 5).random(4))


@pytest.mark.parametrize("engine_class", SET_ENGINES)
def test_set_engines_give_a_new_set_per_call_reset_replays_fast_forward_skips_sets(engine_class):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        engine = engine_class(3, seed=40)
        sets = [engine.random(grid=4) for _ in range(3)]
        assert engine.num_generated == 3
        assert not np.array_equal(sets[0], sets[1])
        engine.reset()
        np.testing.assert_array_equal(engine.random(grid=4), sets[0])
        engine.reset().fast_forward(2)
        np.testing.assert_array_equal(engine.random(grid=4), sets[2])
        # Set k is the set of seed + k, as `dfvn-sample --seed s --realizations R` numbers them.
        np.testing.assert_array_equal(engine_class(3, seed=41).random(grid=4), sets[1])
    for points in sets:
        assert points.dtype == np.float64 and points.shape[1] == 3
        assert points.min() >= 0.0 and points.max() <= 1.0


@pytest.mark.parametrize("engine_class, method, options", [
    (dfvn.CNJ, "cnj", {"cycles_per_spacing": 0.3, "domain": "cube", "bound": "ramp"}),
    (dfvn.CNJ, "cnj", {"domain": "ball"}),
    (dfvn.CNJ, "cnj", {"domain_mode": "drop"}),
    (dfvn.JitterMatched, "jitter-matched", {"domain": "cube"}),
    (dfvn.Jitter, "jitter", {}),
    (dfvn.PoissonDisk, "pds", {"radius": 0.15, "ncandidates": 10}),
    (dfvn.LatinHypercube, "lhs", {}),
    (dfvn.Sobol, "sobol", {"scramble": False}),
    (dfvn.Halton, "halton", {}),
    (dfvn.Random, "random", {}),
])
@pytest.mark.parametrize("protocol", ["unit", "paper"])
def test_sample_is_the_first_draw_of_the_engine_and_the_old_generator(engine_class, method, options, protocol):
    """dfvn.sample wraps the engines; both give the bits of the generator sample() called before (_generate)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for size in ({"grid": 5}, {"n": 200}):
            old = _core._generate(method, 3, seed=11, protocol=protocol, **size, **options)[0]
            np.testing.assert_array_equal(dfvn.sample(method, 3, seed=11, protocol=protocol, **size, **options), old)
            if protocol == "unit" and engine_class in (dfvn.Sobol, dfvn.Halton, dfvn.Random):
                count = size.get("n", 5**3)
                np.testing.assert_array_equal(engine_class(3, seed=11, **options).random(count), old)
            elif engine_class not in (dfvn.Sobol, dfvn.Halton, dfvn.Random):
                engine = engine_class(3, seed=11, protocol=protocol, **options)
                np.testing.assert_array_equal(engine.random(**size), old)


def test_every_count_that_differs_from_the_one_asked_warns_naming_both():
    with pytest.warns(UserWarning, match=r"CNJ: 512 points instead of the 500 asked .*8\^3 = 512"):
        assert len(dfvn.sample("cnj", 3, n=500)) == 512
    with pytest.warns(UserWarning, match=r"Jitter: 512 points instead of the 500 asked"):
        dfvn.Jitter(3, seed=1).random(500)
    with pytest.warns(UserWarning, match=r"CNJ: \d+ points instead of the 1000 asked .*ball"):
        dfvn.CNJ(3, seed=1, domain="ball").random(1000)
    with pytest.warns(UserWarning, match=r"CNJ: \d+ points instead of the 1000 asked .*dropped"):
        dfvn.CNJ(3, seed=1, domain_mode="drop").random(1000)
    with pytest.warns(UserWarning, match=r"PoissonDisk: \d+ points instead of the 1000 asked .*saturated at radius 0.2"):
        dfvn.PoissonDisk(2, seed=1, radius=0.2).random(1000)
    with pytest.warns(UserWarning, match=r"PoissonDisk: \d+ points instead of the 64 asked .*saturated"):
        dfvn.PoissonDisk(3, seed=1, radius=0.45).random(grid=4)
    with pytest.warns(UserWarning, match="power of 2"):
        dfvn.Sobol(3, seed=1).random(1000)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert len(dfvn.CNJ(3, seed=1).random(1000)) == 1000
        assert len(dfvn.LatinHypercube(3, seed=1).random(1000)) == 1000
        assert len(dfvn.Sobol(3, seed=1).random(1024)) == 1024


def test_sample_warns_at_its_callers_line():
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        dfvn.sample("jitter", 3, n=500)
    assert len(caught) == 1 and caught[0].filename == __file__


def test_sobol_random_base2_refuses_an_unbalanced_total_as_scipy_does():
    engine = dfvn.Sobol(2, seed=1)
    with pytest.warns(UserWarning):
        engine.random(3)
    with pytest.raises(ValueError, match=r"3 points have been previously generated, then: n=3\+2\*\*2=7"):
        engine.random_base2(2)
    assert dfvn.Sobol(2, seed=1).random_base2(4).shape == (16, 2)


@pytest.mark.parametrize("call, error, words", [
    (lambda: dfvn.Sobol(16), ValueError, "d must be in 1..15, got 16"),
    (lambda: dfvn.Halton(17), ValueError, "d must be in 1..16, got 17"),
    (lambda: dfvn.CNJ(9), ValueError, "d must be in 2..8, got 9"),
    (lambda: dfvn.CNJ(d=1.5), TypeError, "d must be an int"),
    (lambda: dfvn.CNJ(3, frequency=2.0), TypeError, "cycles_per_spacing .* cycles per unit length"),
    (lambda: dfvn.JitterMatched(3, frequency=2.0), TypeError, "cycles_per_spacing"),
    (lambda: dfvn.Jitter(3, scramble=True), TypeError, "unexpected keyword argument 'scramble'"),
    (lambda: dfvn.Sobol(3).random(-1), ValueError, "n must be at least 0"),
    (lambda: dfvn.Sobol(3).fast_forward(-1), ValueError, "n must be at least 0"),
    (lambda: dfvn.Sobol(3).random(4, workers=0), ValueError, "workers must be -1"),
    (lambda: dfvn.Sobol(3).fast_forward(2**32).random(1), ValueError, "at most 2\\^32"),
    (lambda: dfvn.CNJ(3, domain="klein").random(64), ValueError, "klein"),
    (lambda: dfvn.CNJ(3, domain="torus", bound="ramp").random(64), ValueError, "bound applies"),
    (lambda: dfvn.JitterMatched(3, domain="ball").random(64), ValueError, "jitter-matched"),
])
def test_engines_refuse_bad_arguments_in_one_line(call, error, words):
    with pytest.raises(error, match=words) as raised:
        call()
    assert "\n" not in str(raised.value)


@pytest.mark.parametrize("engine_class", [dfvn.Sobol, dfvn.Halton, dfvn.Random])
def test_workers_never_change_the_points(engine_class):
    a = engine_class(6, seed=3).random(2**14, workers=1)
    np.testing.assert_array_equal(a, engine_class(6, seed=3).random(2**14, workers=-1))
    # Past point 0 the points are computed by index, in blocks over the threads: the same bits.
    whole = engine_class(6, seed=3).random(3 * 2**14, workers=1)
    for workers in (1, 2, -1):
        later = engine_class(6, seed=3).fast_forward(2**14 + 3)
        np.testing.assert_array_equal(later.random(2**15 - 3, workers=workers), whole[2**14 + 3:])
    np.testing.assert_array_equal(dfvn.CNJ(3, seed=3).random(grid=6, workers=1),
                                  dfvn.CNJ(3, seed=3).random(grid=6, workers=2))


def test_cnj_domains_and_bounds_reach_the_generator():
    torus = dfvn.CNJ(3, seed=2).random(grid=6)
    cube = dfvn.CNJ(3, seed=2, domain="cube").random(grid=6)
    ramp = dfvn.CNJ(3, seed=2, domain="cube", bound="ramp").random(grid=6)
    assert len({torus.tobytes(), cube.tobytes(), ramp.tobytes()}) == 3
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ball = dfvn.CNJ(3, seed=2, domain="ball").random(grid=6)
    assert len(ball) < 6**3 and (np.linalg.norm(ball - 0.5, axis=1) <= 0.5).all()


@pytest.mark.parametrize("method", ["CD", "WD", "MD", "L2-star"])
@pytest.mark.parametrize("d", [1, 2, 5])
def test_discrepancy_is_scipys(method, d):
    points = np.random.default_rng(d).random((257, d))
    expected = qmc.discrepancy(points, method=method)
    assert dfvn.discrepancy(points, method=method) == pytest.approx(expected, rel=1e-10)
    assert dfvn.discrepancy(points.tolist(), method=method, workers=-1) == dfvn.discrepancy(points, method=method)


def test_discrepancy_defaults_and_errors_as_scipys():
    points = dfvn.Sobol(3, seed=4).random(128)
    assert dfvn.discrepancy(points) == pytest.approx(qmc.discrepancy(points), rel=1e-10)  # CD by default
    with pytest.raises(ValueError, match="Sample is not in unit hypercube"):
        dfvn.discrepancy(points + 0.5)
    with pytest.raises(ValueError, match="unknown discrepancy 'XD'"):
        dfvn.discrepancy(points, method="XD")
    with pytest.raises(NotImplementedError, match="update_discrepancy"):
        dfvn.discrepancy(points, iterative=True)


def test_every_engine_documents_every_parameter_with_its_default():
    import inspect
    for engine_class in [dfvn.Sobol, dfvn.Halton, dfvn.Random, *SET_ENGINES]:
        for name, parameter in inspect.signature(engine_class.__init__).parameters.items():
            if name in ("self", "refused"):
                continue
            assert name in engine_class.__doc__, f"{engine_class.__name__} does not explain {name}"
            if parameter.default is not inspect.Parameter.empty:
                pattern = rf"\b{name}\b[^.]{{0,40}}\(default"
                assert re.search(pattern, engine_class.__doc__), f"{engine_class.__name__}: {name} without its default"
