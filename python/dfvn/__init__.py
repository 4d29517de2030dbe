"""Divergence-free vector noise (DFVN) in 2..8 dimensions, curl-noise jittering and point-set statistics
(after 'Improving Curl Noise', SIGGRAPH Asia 2025).

Point sets are (points, d) float64 arrays; results depend only on the inputs and the seed, never on the
thread count. The samplers are engines shaped like scipy.stats.qmc's (dfvn.CNJ, dfvn.Jitter,
dfvn.JitterMatched, dfvn.PoissonDisk, dfvn.Sobol, dfvn.Random, dfvn.Halton, dfvn.LatinHypercube: each
with random(n), reset() and fast_forward(k); Sobol with random_base2(m)), and dfvn.discrepancy is
scipy.stats.qmc.discrepancy's. dfvn.sample(method, dim, ...) is the one-call form of the engines.
"""
from . import _core
from ._core import __version__, field, nn_stats, rdf, trace
from .qmc import (CNJ, Halton, Jitter, JitterMatched, LatinHypercube, PoissonDisk, QMCEngine, Random, Sobol,
                  discrepancy, sample)

__all__ = ["CNJ", "Halton", "Jitter", "JitterMatched", "LatinHypercube", "PoissonDisk", "QMCEngine", "Random",
           "Sobol", "discrepancy", "field", "nn_stats", "rdf", "sample", "trace", "__version__"]
