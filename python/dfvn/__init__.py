"""Divergence-free vector noise (DFVN) in 2..8 dimensions, curl-noise jittering and point-set statistics
(after 'Improving Curl Noise', SIGGRAPH Asia 2025).

Point sets are (points, d) float64 arrays; results depend only on the inputs and the seed, never on the
thread count. The samplers are scipy.stats.qmc engines (subclasses of scipy.stats.qmc.QMCEngine when SciPy
is importable: dfvn.CNJ, dfvn.Jitter, dfvn.JitterMatched, dfvn.PoissonDisk, dfvn.Sobol, dfvn.Random,
dfvn.Halton, dfvn.LatinHypercube), dfvn.discrepancy and dfvn.update_discrepancy are SciPy's, and
dfvn.sample(method, dim, ...) is one set as `dfvn-sample --points` writes it. docs/PYTHON.md has the details.
"""
from . import _core
from ._core import __version__, field, nn_stats, rdf, trace
from .qmc import (CNJ, Halton, Jitter, JitterMatched, LatinHypercube, PoissonDisk, QMCEngine, Random, Sobol,
                  discrepancy, sample, update_discrepancy)

__all__ = ["CNJ", "Halton", "Jitter", "JitterMatched", "LatinHypercube", "PoissonDisk", "QMCEngine", "Random",
           "Sobol", "discrepancy", "field", "nn_stats", "rdf", "sample", "trace", "update_discrepancy", "__version__"]
