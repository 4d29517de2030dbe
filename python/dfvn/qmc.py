"""scipy.stats.qmc engines over libdfvn, one per method of dfvn-sample, and SciPy's discrepancy functions.

With SciPy importable every engine is a scipy.stats.qmc.QMCEngine (SciPy's consumers, MultivariateNormalQMC,
MultinomialQMC and qmc_quad, take them; the optimizers 'random-cd' and 'lloyd' run through SciPy's base
class); without it the module still imports and the engines keep the same API (optimization aside). They
follow SciPy's contract: `__init__(d, *, ..., optimization=None, seed=None)` with SciPy's keyword names
and defaults, random(n) as an (n, d) float64 array, integers(), reset(), fast_forward(n), num_generated in
points, .rng (SciPy's Generator of the seed), d = 0 giving (n, 0), ValueError where SciPy raises one.

Seeds are what SciPy takes (None, any int >= 0, numpy.random.Generator or RandomState) and also a
numpy.random.SeedSequence. The points come from the library's counter-based generators, keyed by one
64-bit seed (`library_seed`): an int seed below 2^64 is that seed itself (dfvn.CNJ(d=3, seed=5) makes the
set of `dfvn-sample -d 3 --seed 5`); any other seed gives a 64-bit word drawn from SciPy's Generator of it
(np.random.default_rng(seed), or the Generator or RandomState itself, which moves on, as SciPy's engines
move it). The points depend only on the seed, never on the thread count (`workers`, `threads`).

Two kinds of engine:
- Sequences (Sobol, Halton, Random): random(n) returns exactly the next n points of one sequence in
  [0,1)^d; fast_forward(k) skips k points; reset() returns to point 0. They run on one thread unless
  asked for more (threads=, workers=: -1 or 0 all cores), as SciPy's default workers=1.
- Sets (CNJ, Jitter, JitterMatched, LatinHypercube; PoissonDisk, one growing sample): never more than the
  n points asked, as each class's docstring states.
"""
import abc
import copy
import math
import numbers
import warnings

import numpy as np

from . import _core

try:
    from scipy.stats import qmc as _scipy_qmc
except ImportError:  # the engines keep their API; optimization needs SciPy
    _scipy_qmc = None

__all__ = ["QMCEngine", "CNJ", "Jitter", "JitterMatched", "PoissonDisk", "LatinHypercube", "Sobol", "Halton",
           "Random", "discrepancy", "update_discrepancy", "sample"]

_DEFAULTS = _core._cnj_defaults
_MIN_D, _MAX_D = _DEFAULTS["min_d"], _DEFAULTS["max_d"]
_SEED_RANGE = 2 ** 64


def _stretch_spec(stretch):
    """None, 'U:S' or (U, S) as the command line's 'U:S'."""
    if stretch is None or isinstance(stretch, str):
        return stretch
    try:
        direction, factor = stretch
        return ",".join(repr(float(u)) for u in direction) + ":" + repr(float(factor))
    except (TypeError, ValueError):
        raise ValueError(f"stretch takes 'U:S' or (U, S), got {stretch!r}") from None


def _is_int(value):
    return isinstance(value, numbers.Integral) and not isinstance(value, (bool, np.bool_))


def _count(value, name, minimum):
    """An int >= minimum (TypeError for a non-integer, ValueError below the minimum)."""
    if not _is_int(value):
        raise TypeError(f"{name} must be an int, not {type(value).__name__}")
    if value < minimum:
        raise ValueError(f"{name} must be at least {minimum}, got {int(value)}")
    return int(value)


def _real(value, name):
    """A float from a real number (TypeError naming `name` for a str, None or a list, whose float() would not)."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        raise TypeError(f"{name} must be a real number, not {type(value).__name__}")
    return float(value)


def _threads(workers, default):
    """SciPy's workers (-1: all cores, else >= 1) as the library's threads (0: all cores); None: the default."""
    if workers is None:
        return default
    if not _is_int(workers) or (workers != -1 and workers < 1):
        raise ValueError(f"Invalid number of workers: {workers!r}, must be -1 or > 0")
    return 0 if workers == -1 else int(workers)


def _check_seed(seed):
    """ValueError naming the seed for a negative int (numpy's own words do not name it)."""
    if isinstance(seed, (numbers.Integral, np.integer)) and not isinstance(seed, bool) and int(seed) < 0:
        raise ValueError(f"seed must be a non-negative integer, got {int(seed)}")
    return seed


def _check_random_state(seed):
    """scipy.stats._qmc.check_random_state: a Generator from None or an int; a Generator or RandomState as is."""
    _check_seed(seed)
    if seed is None or isinstance(seed, (numbers.Integral, np.integer)):
        return np.random.default_rng(seed)
    if isinstance(seed, (np.random.RandomState, np.random.Generator)):
        return seed
    raise ValueError(f"{seed!r} cannot be used to seed a numpy.random.Generator instance")


def _library_seed(seed, rng):
    """The library's 64-bit seed: an int seed below 2^64 itself, else a word drawn from rng (SciPy's Generator
    or RandomState of the seed)."""
    if isinstance(seed, (numbers.Integral, np.integer)) and 0 <= int(seed) < _SEED_RANGE:
        return int(seed)
    if isinstance(rng, np.random.RandomState):
        return int(rng.randint(0, _SEED_RANGE, dtype=np.uint64))
    return int(rng.integers(0, _SEED_RANGE, dtype=np.uint64))


def _refuse(name, extra):
    """TypeError for keywords an engine does not take; `frequency` gets the name that replaced it."""
    if "frequency" in extra:
        raise TypeError(f"{name} takes cycles_per_spacing (CNJ's noise cycles per lattice spacing), not frequency: "
                        "in dfvn, frequency means cycles per unit length (as dfvn.field's)")
    if extra:
        raise TypeError(f"{name} got an unexpected keyword argument '{sorted(extra)[0]}'")


if _scipy_qmc is not None:
    _Base = _scipy_qmc.QMCEngine
else:
    class _Base(abc.ABC):
        """scipy.stats.qmc.QMCEngine's state without SciPy: d, rng, rng_seed, num_generated, no optimizer."""

        @abc.abstractmethod
        def __init__(self, d, *, optimization=None, seed=None):
            if not np.issubdtype(type(d), np.integer) or d < 0:
                raise ValueError("d must be a non-negative integer value")
            if optimization is not None:
                raise ValueError(f"optimization={optimization!r} needs SciPy (scipy.stats.qmc's optimizers); "
                                 "install python3-scipy")
            self.d = d
            self.rng = _check_random_state(seed)
            self.rng_seed = copy.deepcopy(seed)
            self.num_generated = 0
            self.optimization_method = None

        @abc.abstractmethod
        def _random(self, n=1, *, workers=1):
            ...


class QMCEngine(_Base):
    """The base of dfvn's engines: scipy.stats.qmc.QMCEngine (when SciPy is importable) with dfvn's seeds
    and threads. Subclass it as SciPy's: __init__(d, ..., seed=None) calling super().__init__ and
    _random(n, *, workers) drawing n points.

    d: dimension (an integer >= 0, else ValueError). optimization (default None): SciPy's 'random-cd' or
    'lloyd' post-processing of every draw (needs SciPy). seed (default None): None, an int >= 0, a
    numpy.random.SeedSequence, Generator or RandomState; .rng is SciPy's Generator of it. threads (default
    0: all cores): the library's threads when random() gets no `workers`; the points never depend on it."""

    def __init__(self, d, *, optimization=None, seed=None, threads=0):
        if isinstance(seed, np.random.SeedSequence):
            seed = np.random.default_rng(seed)  # SciPy takes a Generator, not a SeedSequence
        _check_seed(seed)
        super().__init__(d=d, optimization=optimization, seed=seed)
        self.d = int(self.d)
        self.threads = _count(threads, "threads", 0)

    def _seed_library(self, seed):
        """Sets library_seed from the seed the engine was given (after SciPy's base made self.rng)."""
        self.library_seed = _library_seed(seed, self.rng)

    def random(self, n=1, *, workers=None):
        """The next n points, an (n, d) float64 array in [0,1)^d (set engines: at most n; see the class).

        n: points (default 1). workers: threads, -1 = all cores (default None: the engine's `threads`);
        the points never depend on it. The engine's optimizer (optimization=...) runs on the draw."""
        n = _count(n, "n", 0)
        threads = _threads(workers, self.threads)
        points = self._random(n, workers=threads) if self.d > 0 else np.empty((n, 0))
        if self.optimization_method is not None:
            points = self.optimization_method(points)
        self.num_generated += len(points)
        return points

    def integers(self, l_bounds, *, u_bounds=None, n=1, endpoint=False, workers=None):
        """n points as integers in [l_bounds, u_bounds) (endpoint=True: [l_bounds, u_bounds]), as SciPy's:
        floor(random(n) * (u - l) + l), an (n, d) int64 array.

        l_bounds: int or d ints (the upper bounds when u_bounds is None, with 0 below). u_bounds (default
        None), n (default 1), endpoint (default False), workers (default None: the engine's `threads`)."""
        if u_bounds is None:
            u_bounds, l_bounds = l_bounds, 0
        upper, lower = np.atleast_1d(u_bounds), np.atleast_1d(l_bounds)
        if endpoint:
            upper = upper + 1
        if not np.issubdtype(lower.dtype, np.integer) or not np.issubdtype(upper.dtype, np.integer):
            raise ValueError("'u_bounds' and 'l_bounds' must be integers or array-like of integers")
        try:
            lower, upper = np.broadcast_to(lower, self.d), np.broadcast_to(upper, self.d)
        except ValueError:
            raise ValueError("'l_bounds' and 'u_bounds' must be broadcastable and respect the sample dimension") from None
        if not np.all(lower < upper):
            raise ValueError("Bounds are not consistent 'l_bounds' < 'u_bounds'")
        points = self.random(n=n, workers=workers)
        return np.floor(points * (upper - lower) + lower).astype(np.int64)

    def reset(self):
        """Back to the start (point 0, or the first set). Returns the engine."""
        self.rng = _check_random_state(copy.deepcopy(self.rng_seed))
        self.num_generated = 0
        return self

    def fast_forward(self, n):
        """Skips n points: draws random(n) and drops it (sequences skip without drawing). Returns the engine."""
        self.random(n=_count(n, "n", 0))
        return self

    def __repr__(self):
        return f"dfvn.{type(self).__name__}(d={self.d})"


# Sequences ----------------------------------------------------------------------------------------------

class _Sequence(QMCEngine):
    _method = ""
    _digits = 32

    def _random(self, n=1, *, workers=0):
        if n == 0:
            return np.empty((0, self.d))
        return _core._sequence(self._method, self.d, self.num_generated, n, self.library_seed,
                               getattr(self, "scramble", True), self._digits, workers)

    def fast_forward(self, n):
        """Skips n points (without computing them). Returns the engine."""
        self.num_generated += _count(n, "n", 0)
        return self


class Sobol(_Sequence):
    """Sobol' points (Joe and Kuo's direction numbers new-joe-kuo-6.21201), as scipy.stats.qmc.Sobol.

    d: dimension, 0..21201 (MAXDIM). scramble (default True): hash-based nested Owen scrambling (Burley
    2020), seeded (SciPy scrambles by LMS+shift: other points, the same law); False: the plain sequence,
    point 0 the origin, SciPy's points bit for bit. bits (default None: 32): the digits of the generator,
    1..64, at most 2^bits points (ValueError past them, as SciPy's); bits <= 32 is the 32-digit sequence of
    `dfvn-sample` (scrambled: 32 scrambled digits and 20 random bits below them), 33..64 the sequence
    carried to 64 digits (coordinates: the top 53). optimization (default None): 'random-cd' or 'lloyd'
    (SciPy's). seed (default None): see the module; the points depend on it only. threads (default 1, as
    SciPy's workers=1; 0: all cores): the threads of random() without `workers`; the points never depend on it.

    random(n) returns the next n points and warns, as SciPy does, unless n and the points drawn before
    are powers of 2 (Sobol' points are balanced only at 2^m); random_base2(m) draws 2^m points and
    refuses a total that is not a power of 2; fast_forward(k) skips k points; reset() returns to point 0.
    Point i is the same whichever calls led to it: Sobol(d, seed=s).random(n) is
    `dfvn.sample("sobol", d, n=n, seed=s)`."""
    MAXDIM = _core._sobol_max_dimensions
    _method = "sobol"

    def __init__(self, d, *, scramble=True, bits=None, seed=None, optimization=None, threads=1):
        super().__init__(d, optimization=optimization, seed=seed, threads=threads)
        self._init_quad = {"d": self.d, "scramble": True, "bits": bits, "optimization": optimization}
        if self.d > self.MAXDIM:
            raise ValueError(f"Maximum supported dimensionality is {self.MAXDIM}.")
        if bits is None:
            bits = 32
        bits = _count(bits, "bits", 1)
        if bits > 64:
            raise ValueError("Maximum supported 'bits' is 64")
        self.bits = bits
        self.maxn = 2 ** bits
        self._digits = 64 if bits > 32 else 32
        self.scramble = bool(scramble)
        self._seed_library(seed)

    def _random(self, n=1, *, workers=0):
        total = self.num_generated + n
        if total > self.maxn:
            raise ValueError(f"At most 2**{self.bits}={self.maxn} distinct points can be generated. "
                             f"{self.num_generated} points have been previously generated, then: "
                             f"n={self.num_generated}+{n}={total}. "
                             + ("Consider increasing `bits`." if self.bits != 64 else ""))
        return super()._random(n, workers=workers)

    def random(self, n=1, *, workers=None):
        """The next n Sobol' points, an (n, d) float64 array in [0,1)^d; warns (UserWarning, SciPy's
        words) unless n and the points drawn before are powers of 2.

        n: points (default 1). workers: threads, -1 = all cores (default None: the engine's `threads`)."""
        n = _count(n, "n", 0)
        drawn = self.num_generated
        if n & (n - 1) != 0 or (drawn > 0 and drawn & (drawn - 1) != 0):
            warnings.warn("The balance properties of Sobol' points require n to be a power of 2.", UserWarning,
                          stacklevel=2)
        return super().random(n, workers=workers)

    def random_base2(self, m):
        """The next 2^m points; ValueError (SciPy's words) unless the points drawn in all are 2^k.

        m: the log2 of the count (no default)."""
        m = _count(m, "m", 0)
        if m > 32:  # before 2 ** m: m = 2**63 computed that power for ever
            raise ValueError(f"m must be at most 32 (Sobol supports at most 2^32 points), got {m}")
        n = 2 ** m
        total = self.num_generated + n
        if total & (total - 1) != 0:
            raise ValueError("The balance properties of Sobol' points require n to be a power of 2. "
                             f"{self.num_generated} points have been previously generated, then: "
                             f"n={self.num_generated}+2**{m}={total}. If you still want to do this, the function "
                             "'Sobol.random()' can be used.")
        return super().random(n)


class Halton(_Sequence):
    """Halton points (radical inverses in the first d primes), as scipy.stats.qmc.Halton.

    d: dimension, 0 or more (the primes are generated). scramble (default True): random digit permutations
    (Braaten-Weller, SciPy's scheme), seeded; False: the plain sequence, SciPy's points. optimization
    (default None): 'random-cd' or 'lloyd' (SciPy's). seed (default None): see the module. threads
    (default 1, as SciPy's workers=1; 0: all cores): the points never depend on it.

    random(n) returns the next n points; fast_forward(k) skips k points; reset() returns to point 0.
    Halton(d, seed=s).random(n) is `dfvn.sample("halton", d, n=n, seed=s)`."""
    _method = "halton"

    def __init__(self, d, *, scramble=True, optimization=None, seed=None, threads=1):
        super().__init__(d, optimization=optimization, seed=seed, threads=threads)
        self._init_quad = {"d": self.d, "scramble": True, "optimization": optimization}
        if self.d > _core._halton_max_dimensions:
            raise ValueError(f"Halton points are available in at most {_core._halton_max_dimensions} dimensions")
        self.scramble = bool(scramble)
        self._seed_library(seed)


class Random(_Sequence):
    """Uniform random points in [0,1)^d, a counter-based sequence (point i depends on the seed and i only).

    d: dimension, 0 or more. optimization (default None): 'random-cd' or 'lloyd' (SciPy's). seed (default
    None): see the module. threads (default 1, as SciPy's workers=1; 0: all cores). random(n) returns the next n points;
    fast_forward(k) skips k points; reset() returns to point 0. Random(d, seed=s).random(n) is
    `dfvn.sample("random", d, n=n, seed=s)`."""
    _method = "random"

    def __init__(self, d, *, optimization=None, seed=None, threads=1):
        super().__init__(d, optimization=optimization, seed=seed, threads=threads)
        self._init_quad = {"d": self.d, "optimization": optimization}
        self._seed_library(seed)


# Sets ---------------------------------------------------------------------------------------------------

def _set_dimension(engine, lo=_MIN_D, hi=_MAX_D):
    if engine.d != 0 and not lo <= engine.d <= hi:
        raise ValueError(f"d must be 0 or in {lo}..{hi} for {type(engine).__name__}, got {engine.d}")


class _LatticeEngine(QMCEngine):
    """CNJ, Jitter and JitterMatched: one K^d lattice per call, a new set per call."""
    _method = ""

    def __init__(self, d, *, optimization=None, seed=None, protocol="unit", threads=0, max_memory_gib=0.0,
                 **options):
        super().__init__(d, optimization=optimization, seed=seed, threads=threads)
        _set_dimension(self)
        self.protocol = protocol
        self.max_memory_gib = _real(max_memory_gib, "max_memory_gib")
        self._options = options
        self._init_quad = {"d": self.d, "optimization": optimization, "protocol": protocol, "threads": threads,
                           "max_memory_gib": max_memory_gib, **options}
        self._seed_library(seed)
        self._sets = 0
        self._grid = None

    def reset(self):
        super().reset()
        self._sets = 0
        return self

    def _lattice_side(self, n):
        """The largest K with K^d <= n (exact in integers)."""
        k = int(round(n ** (1.0 / self.d)))
        while k > 0 and k ** self.d > n:
            k -= 1
        while (k + 1) ** self.d <= n:
            k += 1
        return k

    def random(self, n=1, *, grid=None, workers=None):
        """The next set (a new one per call: set k is made with library_seed + k), an (m, d) float64 array.

        n: the points asked for (default 1): the set is the K^d lattice with the largest K such that
        K^d <= n, so never more than n points (a UserWarning names both counts when they differ; n < 1
        gives an empty (0, d) array, 1 <= n < 2^d one uniform point: the one-cell lattice). grid: K itself
        instead of n (K^d points, K >= 2; give one of n and grid).
        workers: threads, -1 = all cores (default None: the engine's `threads`); the set never depends on it."""
        if grid is not None:
            if n != 1:
                raise ValueError("give one of n (a point count) and grid (K: the K^d lattice), not both")
            self._grid = _count(grid, "grid", 2)
            n = self._grid ** self.d if self.d else 1
        try:
            return super().random(n, workers=workers)
        finally:
            self._grid = None

    def _random(self, n=1, *, workers=0):
        k = self._grid if self._grid is not None else self._lattice_side(n)
        if k == 0:
            return np.empty((0, self.d))
        seed = (self.library_seed + self._sets) % _SEED_RANGE
        if k == 1:
            # The one-cell lattice (the library's lattices start at K = 2): its point jittered, or moved by
            # a volume-preserving field on the torus, is uniform in the cell, i.e. in [0,1)^d.
            points, requested = _core._sequence("random", self.d, 0, 1, seed, True, 32, workers), 1
        else:
            points, requested, _k, _side, _saturated, _radius = _core._generate(
                self._method, self.d, grid=k, seed=seed, protocol=self.protocol, threads=workers,
                max_memory_gib=self.max_memory_gib, **self._options)
        self._sets += 1
        if self._grid is None and len(points) != n:
            why = [f"the largest K^d <= n: {k}^{self.d} = {k ** self.d}"] if k ** self.d != n else []
            if len(points) < k ** self.d:
                why.append(self._why_fewer(requested, len(points)))
            # stacklevel: this, QMCEngine.random, _LatticeEngine.random, the caller.
            warnings.warn(f"{type(self).__name__}: {len(points)} points instead of the {n} asked ({'; '.join(why)})",
                          UserWarning, stacklevel=4)
        return points

    def _why_fewer(self, requested, got):
        return f"{requested - got} fewer"


class CNJ(_LatticeEngine):
    """Curl-noise jittering: the K^d lattice moved along a divergence-free noise field (the paper's method).

    d: dimension, 2..8 (or 0). optimization (default None): 'random-cd' or 'lloyd' (SciPy's). seed
    (default None): see the module; set k (the k-th call since reset) is made with library_seed + k.
    protocol (default 'unit'): 'unit' (the lattice of spacing 1/K in [0,1)^d) or 'paper' (the paper's
    Section 5.1, spacing 0.1, as `dfvn-sample --protocol paper`).
    noise (default '{noise}'): the noise basis. cycles_per_spacing (default {cycles_per_spacing}): the
    noise's cycles per lattice spacing (the field's cycles per unit length are cycles_per_spacing / spacing,
    `dfvn-sample`'s field_frequency); `frequency` is refused, since in dfvn it means cycles per unit length.
    step_scale (default {step_scale}): the trace time in mean spacings. integrator (default '{integrator}'),
    reprojection (default '{reprojection}'; 'none' with field='curl'): how points are traced along the
    field. steps (default 0: the domain's count, 2 on the torus and 1 in a bounded domain).
    field (default '{field}'): the field traced along, 'dfvn' (the paper's) or 'curl' (Bridson et al.
    2007's curl noise, d = 2 and 3 only, as `dfvn-sample sample --field curl`): it has no reprojection
    (any other than 'none' is refused) and no boundary (the torus or domain_mode='drop').
    domain (default None: the torus, or the cube with drop mode or a bound): 'torus' ([0,1)^d with
    opposite faces identified, every point kept), 'cube' or 'ball'. domain_mode (default 'conformant'):
    'conformant' (the field bounded by the domain, every point kept) or 'drop' (the free field, points
    that leave are dropped; not on the torus). bound (default None: 'eq13' where it applies): how the
    bounded field meets the boundary, 'eq13' or 'ramp'. As `dfvn-sample sample --domain/--domain-mode/--bound`.
    phase (default 0.0): the field's noise phase in radians, any finite real (rotating gradients, as
    `dfvn-sample sample --phase`): period 2 pi; 0 is the field without a phase, bit for bit.
    stretch (default None): 'U:S' or (U, S), the field's noise read at A x, A = I + (S - 1) u u^T
    (`dfvn-sample sample --stretch`; not on the torus). time (default None): the (N+1)D basis at
    (x, time), d <= 7 (`--time`).
    threads (default 0: all cores; the set never depends on it). max_memory_gib (default 0: 80% of the
    machine's): a set that would need more raises ValueError before any work.

    random(n) is the K^d lattice with the largest K such that K^d <= n, moved: never more than n points
    (in the ball only the ball's sites, in drop mode the points kept; a UserWarning names both counts when
    they differ from n); random(grid=K) takes K itself; random(0) is an empty (0, d) array and n below
    2^d one uniform point (the one-cell lattice: its point moved on the torus stays uniform). Each call is a
    new set; reset() returns to the first; num_generated counts the points returned."""
    _method = "cnj"
    __doc__ = __doc__.format(**_DEFAULTS)

    def __init__(self, d, *, optimization=None, seed=None, protocol="unit", noise=_DEFAULTS["noise"],
                 cycles_per_spacing=_DEFAULTS["cycles_per_spacing"], step_scale=_DEFAULTS["step_scale"],
                 integrator=_DEFAULTS["integrator"], reprojection=None, steps=_DEFAULTS["steps"],
                 domain=None, domain_mode=_DEFAULTS["domain_mode"], bound=None, threads=0, max_memory_gib=0.0,
                 field=_DEFAULTS["field"], phase=0.0, stretch=None, time=None, **refused):
        _refuse(type(self).__name__, refused)
        super().__init__(d, optimization=optimization, seed=seed, protocol=protocol, threads=threads,
                         max_memory_gib=max_memory_gib, noise=noise,
                         cycles_per_spacing=_real(cycles_per_spacing, "cycles_per_spacing"),
                         step_scale=_real(step_scale, "step_scale"), integrator=integrator, reprojection=reprojection,
                         steps=_count(steps, "steps", -(1 << 31)), domain=domain, domain_mode=domain_mode,
                         bound=bound, field=field, phase=_real(phase, "phase"), stretch=_stretch_spec(stretch),
                         time=None if time is None else _real(time, "time"))

    def _why_fewer(self, requested, got):
        if self._options["domain"] == "ball":
            return f"the ball's sites of that lattice: {requested}"
        return f"{requested - got} dropped: they left the {self._options['domain'] or 'cube'} (domain_mode='drop')"


class Jitter(_LatticeEngine):
    """Jittered lattice: each point of the K^d lattice moved uniformly inside its cell (the paper's jitter).

    d: dimension, 2..8 (or 0). optimization (default None): 'random-cd' or 'lloyd' (SciPy's). seed (default
    None): see the module; set k (the k-th call since reset) is made with library_seed + k. protocol
    (default 'unit'): 'unit' (spacing 1/K in [0,1)^d, half-width 1/(2K)) or 'paper' (spacing 0.1,
    half-width 0.05). threads (default 0: all cores). max_memory_gib (default 0: 80% of the machine's).

    random(n) is the K^d lattice with the largest K such that K^d <= n, jittered: never more than n points
    (a UserWarning names both counts when they differ); random(grid=K) takes K itself; random(0) is an
    empty (0, d) array and n below 2^d one uniform point (the one-cell lattice, jittered). Each call is a new set; reset() returns to the first."""
    _method = "jitter"

    def __init__(self, d, *, optimization=None, seed=None, protocol="unit", threads=0, max_memory_gib=0.0,
                 **refused):
        _refuse(type(self).__name__, refused)
        super().__init__(d, optimization=optimization, seed=seed, protocol=protocol, threads=threads,
                         max_memory_gib=max_memory_gib)


class JitterMatched(CNJ):
    __doc__ = """Jitter at CNJ's RMS displacement: the control of the paper's comparison. Standalone it traces CNJ
    with the same seed and options (without keeping CNJ's points) and jitters CNJ's lattice by the uniform
    offset whose RMS displacement equals CNJ's, wrapped on the torus or reflected at the cube's faces.

    The ball is refused (its clipped lattice has no cells to jitter in). The parameters and the count
    contract are CNJ's:

    """ + CNJ.__doc__[CNJ.__doc__.index("d: dimension"):]
    _method = "jitter-matched"


class LatinHypercube(QMCEngine):
    """Latin hypercube sampling, as scipy.stats.qmc.LatinHypercube: on each axis the n points take the n
    strata [m/n, (m+1)/n) in a random order.

    d: dimension, 0 or more. centered (default False): SciPy 1.10's deprecated name for scramble=False
    (warns as SciPy does). scramble (default True): each point at a uniform place in its stratum (the
    library's generator, `dfvn-sample --methods lhs`'s points); False: at the stratum's centre.
    strength (default 1): 1, a plain LHS; 2, an orthogonal-array LHS (Tang 1993, SciPy's construction):
    n must be p^2 for a prime p, and d <= p + 1 (ValueError otherwise). optimization (default None):
    'random-cd' or 'lloyd' (SciPy's). seed (default None): see the module; the k-th call since reset is
    drawn with library_seed + k. threads (default 0: all cores).

    random(n) returns exactly n points, a new design per call (as SciPy's); random(0) is an empty (0, d)
    array; reset() returns to the first design."""

    def __init__(self, d, *, centered=False, scramble=True, strength=1, optimization=None, seed=None, threads=0):
        if centered:
            scramble = False
            warnings.warn("'centered' is deprecated and will be removed in SciPy 1.12. Please use 'scramble' "
                          "instead. 'centered=True' corresponds to 'scramble=False'.", stacklevel=2)
        super().__init__(d, optimization=optimization, seed=seed, threads=threads)
        self._init_quad = {"d": self.d, "scramble": True, "strength": strength, "optimization": optimization}
        if strength not in (1, 2) or isinstance(strength, bool):
            raise ValueError(f"{strength!r} is not a valid strength. It must be one of {{1, 2}}")
        self.scramble = bool(scramble)
        self.strength = int(strength)
        self._seed_library(seed)
        self._sets = 0

    def reset(self):
        super().reset()
        self._sets = 0
        return self

    def _random(self, n=1, *, workers=0):
        seed = (self.library_seed + self._sets) % _SEED_RANGE
        if self.strength == 2:
            points = self._orthogonal_array_lhs(n, seed)
        elif n == 0:
            points = np.empty((0, self.d))
        else:
            points = _core._latin_hypercube(self.d, n, seed, workers)
            if not self.scramble:
                # The centre of each point's stratum: its rank on the axis (the strata are disjoint).
                ranks = np.argsort(np.argsort(points, axis=0, kind="stable"), axis=0, kind="stable")
                points = (ranks + 0.5) / n
        self._sets += 1
        return points

    def _orthogonal_array_lhs(self, n, seed):
        """SciPy's OA-LHS of strength 2 (Owen 1992, Tang 1993): the Bush array of strength 2 over p
        symbols (columns i, j and i + k j mod p), its symbols permuted per column, each symbol's p rows
        spread by a 1D LHS of p points; divided by p. Randomness: a numpy Generator of (seed, 'oa-lhs')."""
        p = math.isqrt(n)
        if p < 2 or p * p != n or any(p % q == 0 for q in range(2, math.isqrt(p) + 1)):
            close = [q * q for q in range(max(p - 1, 2), 1, -1)
                     if all(q % r for r in range(2, math.isqrt(q) + 1))][:2][::-1]
            raise ValueError(f"n is not the square of a prime number. Close values are {close}")
        if self.d > p + 1:
            raise ValueError("n is too small for d. Must be n > (d-1)**2")
        rng = np.random.default_rng([seed, 0x0A])
        columns = p + 1
        array = np.zeros((n, columns), dtype=int)
        array[:, :2] = np.stack(np.meshgrid(np.arange(p), np.arange(p)), axis=-1).reshape(-1, 2)
        for k in range(1, p):
            array[:, 1 + k] = (array[:, 0] + k * array[:, 1]) % p
        permuted = np.empty_like(array)
        for j in range(columns):
            permuted[:, j] = rng.permutation(p)[array[:, j]]
        points = np.zeros((n, columns))
        for j in range(columns):
            for symbol in range(p):
                rows = permuted[:, j] == symbol
                within = rng.permutation(p) + (rng.random(p) if self.scramble else 0.5)
                points[rows, j] = (within / p + symbol)
        return points[:, :self.d] / p


class PoissonDisk(QMCEngine):
    """Poisson disk sampling (Bridson's dart throwing): no two points closer than `radius`, as
    scipy.stats.qmc.PoissonDisk: one sample that grows, call after call.

    d: dimension, 2..8 (or 0). radius (default 0.05, SciPy's): the minimum distance. hypersphere (default
    'volume'): candidates uniform in the volume around a point, as SciPy's 'volume' (dfvn throws them in
    the annulus [r, 2r], SciPy's ball of radius 2r without the part that always conflicts); SciPy's
    'surface' is not available (ValueError). ncandidates (default 30): candidates per visit of a point.
    optimization (default None): 'random-cd' or 'lloyd' (SciPy's; it moves the points, so the radius no
    longer holds). seed (default None): see the module. threads (default 0: all cores; the points never
    depend on it).

    random(n) adds at most n points to the sample and returns them: fewer once the domain is full at this
    radius (with a UserWarning); random(a) then random(b) are the first a + b points of one process, so
    their union keeps the radius. fill_space() adds points until the domain is full and returns them.
    random(0) is an empty (0, d) array; reset() empties the sample (the same process replays);
    num_generated counts the points placed. The points lie in [0, 1]^d."""

    def __init__(self, d, *, radius=0.05, hypersphere="volume", ncandidates=30, optimization=None, seed=None,
                 threads=0):
        super().__init__(d, optimization=optimization, seed=seed, threads=threads)
        self._init_quad = {"d": self.d, "radius": radius, "hypersphere": hypersphere, "ncandidates": ncandidates,
                           "optimization": optimization}
        if hypersphere not in ("volume", "surface"):
            raise ValueError(f"{hypersphere!r} is not a valid hypersphere sampling method. It must be one of "
                             f"{{'volume', 'surface'}}")
        if hypersphere == "surface":
            raise ValueError("hypersphere='surface' is not available: dfvn's Poisson disk sampling throws its "
                             "candidates in the volume (the annulus [r, 2r]), as SciPy's 'volume'")
        _set_dimension(self)
        self.radius = _real(radius, "radius")
        if not math.isfinite(self.radius) or self.radius <= 0.0:
            raise ValueError(f"radius must be a finite number > 0, got {radius!r}")
        self.hypersphere = hypersphere
        self.ncandidates = _count(ncandidates, "ncandidates", 1)
        self._seed_library(seed)
        self._placed = 0

    def reset(self):
        super().reset()
        self._placed = 0
        return self

    def _random(self, n=1, *, workers=0, fill=False):
        if n == 0 and not fill:
            return np.empty((0, self.d))
        most = _SEED_RANGE - 1 if fill else self._placed + n
        points, saturated = _core._poisson_disk(self.d, self.radius, self.ncandidates, most, self.library_seed,
                                                workers)
        added = points[self._placed:]
        self._placed = len(points)
        if saturated and not fill and len(added) < n:
            warnings.warn(f"PoissonDisk: {len(added)} points instead of the {n} asked (the domain is full at radius "
                          f"{self.radius:g}: Poisson disk sampling saturated; a lower radius gives more)",
                          UserWarning, stacklevel=3)
        return added

    def fill_space(self, *, workers=None):
        """Adds points until the domain is full at this radius; returns them, an (m, d) float64 array.

        workers: threads, -1 = all cores (default None: the engine's `threads`)."""
        threads = _threads(workers, self.threads)
        points = self._random(0, workers=threads, fill=True) if self.d > 0 else np.empty((0, 0))
        if self.optimization_method is not None:
            points = self.optimization_method(points)
        self.num_generated += len(points)
        return points


# The engines by dfvn-sample's method names.
ENGINES = {"cnj": CNJ, "jitter-matched": JitterMatched, "jitter": Jitter, "pds": PoissonDisk, "sobol": Sobol,
           "random": Random, "halton": Halton, "lhs": LatinHypercube}


def sample(method, dim, *, grid=None, n=None, seed=1, protocol="unit", scramble=True, radius=0.0, ncandidates=30,
           noise=_DEFAULTS["noise"], cycles_per_spacing=_DEFAULTS["cycles_per_spacing"],
           step_scale=_DEFAULTS["step_scale"], integrator=_DEFAULTS["integrator"],
           reprojection=None, steps=_DEFAULTS["steps"], domain=None,
           domain_mode=_DEFAULTS["domain_mode"], bound=None, threads=0, max_memory_gib=0.0, field=_DEFAULTS["field"],
           phase=0.0, stretch=None, time=None, **refused):
    """One point set as an (n, dim) float64 array, the same bits as `dfvn-sample --points DIR --format npy`.

    method: 'cnj' (curl noise jittering), 'jitter', 'jitter-matched' (jitter at CNJ's RMS displacement),
    'pds' (Poisson disk), 'sobol', 'random', 'halton', 'lhs'. dim: 2..8.
    Exactly one of grid (K: cnj and jitter move the K^dim lattice, the others take its count) or n (a point
    count: pds, sobol, random, halton and lhs give n points, or pds fewer when it saturates; cnj and
    jitter use the lattice K^dim nearest to n, as the command line; a UserWarning names both counts
    whenever they differ; sobol warns unless n is a power of 2). seed (default 1): None, an int >= 0, a
    numpy.random.SeedSequence, Generator or RandomState (as the engines' library_seed).
    protocol (default 'unit'): 'unit' (every method in [0,1]^dim at the density of a cell-centred lattice)
    or 'paper' (the paper's Section 5.1, as `dfvn-sample --protocol paper`). scramble (default True):
    Owen-scrambled Sobol, digit-permuted Halton (False: neither). radius (default 0: the protocol's, 1/K
    under 'unit'), ncandidates (default 30): Poisson disk's. noise, cycles_per_spacing, step_scale,
    integrator, reprojection, steps (default 0: the domain's count), domain (default None), domain_mode
    (default 'conformant'), bound (default None), field (default 'dfvn'), phase (default 0.0), stretch
    (default None), time (default None): CNJ's options, defaults and meaning as dfvn.CNJ's (`frequency`
    is refused: it is now cycles_per_spacing). threads (default 0: all cores; the result never depends on
    it). max_memory_gib (default 0: 80% of the machine's memory): a larger set raises ValueError before
    any work."""
    _refuse("sample", refused)
    if method not in ENGINES:
        raise ValueError(f"unknown method {method!r} (allowed: {', '.join(ENGINES)})")
    if not _is_int(dim):
        raise TypeError(f"dim must be an int, not {type(dim).__name__}")
    if not _MIN_D <= dim <= _MAX_D:
        raise ValueError(f"dim must be in {_MIN_D}..{_MAX_D}, got {int(dim)}")
    if (grid is None) == (n is None):
        raise ValueError("give exactly one of grid (K: a K^N lattice) or n (a point count)")
    if n is not None:
        n = _count(n, "n", 1)
    if grid is not None:
        grid = _count(grid, "grid", 1)
    if isinstance(seed, np.random.SeedSequence):
        seed = np.random.default_rng(seed)
    library_seed = _library_seed(seed, _check_random_state(seed))
    points, requested, k, _side, saturated, pds_radius = _core._generate(
        method, int(dim), grid=grid, n=n, seed=library_seed, protocol=protocol, scramble=bool(scramble),
        radius=radius, ncandidates=ncandidates, noise=noise, cycles_per_spacing=cycles_per_spacing,
        step_scale=step_scale, integrator=integrator, reprojection=reprojection, steps=steps, domain=domain,
        domain_mode=domain_mode, bound=bound, threads=threads, max_memory_gib=max_memory_gib, field=field,
        phase=_real(phase, "phase"), stretch=_stretch_spec(stretch), time=None if time is None else _real(time, "time"))
    asked = n if n is not None else requested
    got = len(points)
    why = []
    if n is not None and requested != n:
        lattice = k ** dim
        why.append(f"the K^d lattice nearest to n: {k}^{dim} = {lattice}" if requested == lattice else
                   f"the ball's sites of the {k}^{dim} lattice nearest to n: {requested}")
    if got < requested:
        why.append(f"Poisson disk sampling saturated at radius {pds_radius:g}; a lower radius gives more" if saturated
                   else f"{requested - got} dropped: they left the {domain or 'cube'} (domain_mode='drop')")
    if got != asked or (n is None and got < requested):
        warnings.warn(f"{ENGINES[method].__name__}: {got} points instead of the {asked} asked ({'; '.join(why)})",
                      UserWarning, stacklevel=2)
    if method == "sobol" and n is not None and n & (n - 1) != 0:
        warnings.warn("The balance properties of Sobol' points require n to be a power of 2.", UserWarning,
                      stacklevel=2)
    return points


# Discrepancy --------------------------------------------------------------------------------------------

# Per method: the first sum's factor per coordinate z = |x - 1/2| (None: the method has no first sum),
# the constant A and the first sum's weight w in D(n) = A - (w / n) S1 + S2 / n^2 (Zhou et al. 2013;
# L2-star is the square root of its form, with x itself in the first sum, Warnock 1972).
_DISCREPANCY_FORMS = {
    "CD": (lambda x: 1 + 0.5 * abs(x - 0.5) - 0.5 * (x - 0.5) ** 2, lambda d: (13 / 12) ** d, lambda d: 2.0),
    "WD": (None, lambda d: -(4 / 3) ** d, lambda d: 0.0),
    "MD": (lambda x: 5 / 3 - 0.25 * abs(x - 0.5) - 0.25 * (x - 0.5) ** 2, lambda d: (19 / 12) ** d, lambda d: 2.0),
    "L2-star": (lambda x: 1 - x ** 2, lambda d: 3.0 ** -d, lambda d: 2.0 ** (1 - d)),
}


def discrepancy(sample, *, iterative=False, method="CD", workers=1):
    """The discrepancy of a sample in [0,1]^d, as scipy.stats.qmc.discrepancy (same names and defaults).

    sample: (n, d) array_like (ValueError unless 2-D and, NaN aside, in the unit hypercube; a NaN gives
    nan, as SciPy's). iterative (default False): True computes it as if the sample had n + 1 points
    (SciPy's form for update_discrepancy, which adds the last one). method (default 'CD', spelt exactly
    as SciPy's): 'CD' (centered), 'WD' (wrap-around), 'MD' (mixture), all three squared as SciPy returns
    them, or 'L2-star' (its square root, as SciPy). workers (default 1): threads, -1 = all cores; the
    value never depends on it. Exact closed-form double sums, O(n^2 d)."""
    points = np.asarray(sample, dtype=np.float64, order="C")
    if points.ndim != 2:
        raise ValueError("Sample is not a 2D array")
    if points.max() > 1.0 or points.min() < 0.0:
        raise ValueError("Sample is not in unit hypercube")
    threads = _threads(workers, 1)
    if not isinstance(method, str) or method not in _DISCREPANCY_FORMS:
        raise ValueError(f"{method!r} is not a valid method. It must be one of {set(_DISCREPANCY_FORMS)!r}")
    if np.isnan(points).any():
        return float("nan")
    value = _core._discrepancy(points, str(method), threads)
    if not iterative:
        return value
    # The same sums over n + 1 in place of n: S2 from D(n) and S1, then D(n + 1).
    n, d = points.shape
    first, constant, weight = _DISCREPANCY_FORMS[method]
    s1 = float(np.prod(first(points), axis=1).sum()) if first is not None else 0.0
    squared = value ** 2 if method == "L2-star" else value
    s2 = n * n * (squared - constant(d)) + weight(d) * n * s1
    squared = constant(d) - weight(d) / (n + 1) * s1 + s2 / (n + 1) ** 2
    return math.sqrt(squared) if method == "L2-star" else squared


def update_discrepancy(x_new, sample, initial_disc):
    """The centered discrepancy of `sample` with `x_new` added, from `initial_disc`, the sample's
    discrepancy(sample, iterative=True), as scipy.stats.qmc.update_discrepancy (Fang et al. 2006): O(n d).

    x_new: (d,) array_like in [0,1]^d. sample: (n, d) array_like in [0,1]^d. initial_disc: a float.
    ValueError (SciPy's words) for another shape or a point outside the hypercube."""
    points = np.asarray(sample, dtype=np.float64, order="C")
    x_new = np.asarray(x_new, dtype=np.float64, order="C")
    if points.ndim != 2:
        raise ValueError("Sample is not a 2D array")
    if points.max() > 1.0 or points.min() < 0.0:
        raise ValueError("Sample is not in unit hypercube")
    if x_new.ndim != 1:
        raise ValueError("x_new is not a 1D array")
    if not (np.all(x_new >= 0) and np.all(x_new <= 1)):
        raise ValueError("x_new is not in unit hypercube")
    if x_new.shape[0] != points.shape[1]:
        raise ValueError("x_new and sample must be broadcastable")
    n = len(points) + 1
    z_new, z = abs(x_new - 0.5), abs(points - 0.5)
    own = np.prod(1 + 0.5 * z_new - 0.5 * z_new ** 2)
    pairs = np.prod(1 + 0.5 * z_new + 0.5 * z - 0.5 * abs(x_new - points), axis=1).sum()
    itself = np.prod(1 + z_new)
    return float(initial_disc - 2.0 / n * own + 2.0 / n ** 2 * pairs + itself / n ** 2)
