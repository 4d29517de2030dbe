"""SciPy's own tests of its QMC engines, run on dfvn's (STYLE.md: where an ecosystem publishes its contract
as tests, run those tests on our code).

The test classes are imported from the installed SciPy (scipy/stats/tests/test_qmc.py) and subclassed with
dfvn's engine set: QMCEngineTests on every engine, TestSobol, TestHalton, TestLHS and TestPoisson on
their counterparts, TestUtils on dfvn.discrepancy and dfvn.update_discrepancy, and the module's base-class
tests (test_subclassing_QMCEngine, test_raises, test_integers, test_integers_nd) on dfvn.QMCEngine. Where
SciPy's tests name an engine through the module (qmc.Sobol(...)) or a function as a global
(update_discrepancy), a fixture hands them dfvn's for the test's duration.

NOT_APPLICABLE lists the tests that cannot hold for dfvn, each with its reason; every other test must
pass. SciPy's own skips (a set is not a sequence, ...) stay SciPy's.
"""
import types

import pytest

import dfvn

scipy_tests = pytest.importorskip("scipy.stats.tests.test_qmc")
from scipy.stats import qmc  # noqa: E402 (after the skip: only with SciPy's tests installed)

QMC_WITH_DFVN = types.SimpleNamespace(**{name: getattr(qmc, name) for name in dir(qmc) if not name.startswith("__")})
QMC_WITH_DFVN.__dict__.update(Sobol=dfvn.Sobol, Halton=dfvn.Halton, LatinHypercube=dfvn.LatinHypercube,
                              PoissonDisk=dfvn.PoissonDisk, discrepancy=dfvn.discrepancy,
                              update_discrepancy=dfvn.update_discrepancy)


class RandomEngine(dfvn.QMCEngine):
    """SciPy's RandomEngine (test_qmc.py), subclassing dfvn's base class instead of SciPy's."""

    def __init__(self, d, optimization=None, seed=None):
        super().__init__(d=d, optimization=optimization, seed=seed)

    def _random(self, n=1, *, workers=1):
        return self.rng.random((n, self.d))


SCRAMBLED_REFERENCE = ("SciPy's scrambled reference values: SciPy's own scrambling and generator, not dfvn's "
                       "(the unscrambled references pass)")
LATTICE_DIMENSIONS = "a sweep past the lattice engines' 2..8 dimensions"
NOT_A_SEQUENCE = "Not applicable: not a sequence (a new set per call, as SciPy's LatinHypercube)."
NOT_APPLICABLE = {
    ("TestSobol", "test_sample[Scrambled]"): SCRAMBLED_REFERENCE,
    ("TestHalton", "test_sample[Scrambled]"): SCRAMBLED_REFERENCE,
    ("TestHalton", "test_workers"): SCRAMBLED_REFERENCE,
    ("TestPoisson", "test_mindist"): "dimension 1 and hypersphere='surface': dfvn's Poisson disk sampling is "
                                     "2..8-dimensional, with candidates in the volume only",
    ("TestUtils", "test_discrepancy_parallel"): "its last part fakes os.cpu_count() = None: dfvn asks OpenMP for "
                                                "the cores, so workers=-1 still works (the rest passes: see "
                                                "test_qmc.py's test_discrepancy_workers_are_scipys)",
    ("TestCNJ", "test_optimizers[lloyd-<lambda>]"): "SciPy's Lloyd moves only points whose Voronoi cell is bounded, "
                                                    "and this seed's closest CNJ pair lies on the hull: both stay, the "
                                                    "metric is equal, not worse (Jitter's and the others' pass)",
    ("TestUtils", "test_scale"): "qmc.scale is SciPy's: dfvn has none",
    ("TestUtils", "test_scale_random"): "qmc.scale is SciPy's: dfvn has none",
    ("TestUtils", "test_scale_errors"): "qmc.scale is SciPy's: dfvn has none",
    ("TestUtils", "test_n_primes"): "SciPy's private n_primes: dfvn's primes are the library's (halton_bases)",
    ("TestUtils", "test_primes"): "SciPy's private primes_from_2_to: dfvn's primes are the library's",
}
NOT_APPLICABLE[("TestRandom", "test_sample[Unscrambled]")] = ("no reference sample: SciPy has no uniform random "
                                                                "engine to hold one")
for engine in ("TestCNJ", "TestJitter", "TestJitterMatched"):
    NOT_APPLICABLE[(engine, "test_bounds[Unscrambled]")] = LATTICE_DIMENSIONS + " (d = 100)"
    NOT_APPLICABLE[(engine, "test_continuing[Unscrambled]")] = NOT_A_SEQUENCE
    NOT_APPLICABLE[(engine, "test_fast_forward[Unscrambled]")] = NOT_A_SEQUENCE
    NOT_APPLICABLE[(engine, "test_sample[Unscrambled]")] = ("Not applicable: the value of reference sample is "
                                                            "implementation dependent (as SciPy's TestLHS)")


@pytest.fixture(autouse=True)
def dfvn_in_scipys_tests(request, monkeypatch):
    """dfvn's engines and functions wherever SciPy's tests name them; the listed tests skipped."""
    owner = request.node.cls.__name__ if request.node.cls else ""
    reason = NOT_APPLICABLE.get((owner, request.node.name))
    if reason:
        pytest.skip(reason)
    monkeypatch.setattr(scipy_tests, "qmc", QMC_WITH_DFVN)
    monkeypatch.setattr(scipy_tests, "update_discrepancy", dfvn.update_discrepancy)
    monkeypatch.setattr(scipy_tests, "RandomEngine", RandomEngine)


class TestSobol(scipy_tests.TestSobol):
    qmce = dfvn.Sobol


class TestHalton(scipy_tests.TestHalton):
    qmce = dfvn.Halton


class TestLHS(scipy_tests.TestLHS):
    qmce = dfvn.LatinHypercube


class TestPoisson(scipy_tests.TestPoisson):
    qmce = dfvn.PoissonDisk


class TestRandom(scipy_tests.QMCEngineTests):
    qmce = dfvn.Random
    can_scramble = False


class TestCNJ(scipy_tests.QMCEngineTests):
    qmce = dfvn.CNJ
    can_scramble = False


class TestJitter(scipy_tests.QMCEngineTests):
    qmce = dfvn.Jitter
    can_scramble = False


class TestJitterMatched(scipy_tests.QMCEngineTests):
    qmce = dfvn.JitterMatched
    can_scramble = False


class TestUtils(scipy_tests.TestUtils):
    pass


test_subclassing_QMCEngine = scipy_tests.test_subclassing_QMCEngine
test_raises = scipy_tests.test_raises
test_integers = scipy_tests.test_integers
test_integers_nd = scipy_tests.test_integers_nd


def test_the_list_of_tests_that_do_not_apply_names_real_tests(request):
    """A misspelt entry would skip nothing and hide nothing: every entry is a collected test."""
    collected = {(item.cls.__name__ if item.cls else "", item.name) for item in request.session.items
                 if item.module.__name__ == __name__}
    if len(collected) < 50:
        pytest.skip("run with the whole file to check the list")
    assert set(NOT_APPLICABLE) <= collected, sorted(set(NOT_APPLICABLE) - collected)
