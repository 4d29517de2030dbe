"""Engines shaped like scipy.stats.qmc's, one per method of dfvn-sample, and scipy's discrepancy.

Every engine takes the dimension as `d` and a `seed` that is None (fresh entropy), an int in
[0, 2^64) (the engine's seed itself: dfvn.CNJ(d=3, seed=5) makes the set of `dfvn-sample -d 3 --seed 5`)
or a numpy.random.Generator (the engine's 64-bit seed is drawn from it, so the points are determined by
the generator's state), and returns (n, d) float64 arrays from random(n).

Two kinds of engine:
- Sequences (Sobol, Halton, Random): as SciPy's, random(n) returns the next n points of one sequence in
  [0,1)^d; fast_forward(k) skips k points; reset() returns to point 0; num_generated counts points.
- Sets (CNJ, Jitter, JitterMatched, PoissonDisk, LatinHypercube): each random(n) call returns a new,
  independently seeded set of about n points; set k (k = 0, 1, ...) is the set of seed + k (mod 2^64),
  as `dfvn-sample --seed s --realizations R` numbers its realizations. reset() returns to set 0;
  fast_forward(k) skips k sets; num_generated counts sets.
Whenever a set holds another number of points than the n asked (the lattice methods take the K^d
lattice nearest to n, CNJ in the ball keeps the ball's sites, drop mode drops, Poisson disk sampling
saturates), a UserWarning names both counts.
"""
import numbers
import warnings

import numpy as np

from . import _core

__all__ = ["QMCEngine", "CNJ", "Jitter", "JitterMatched", "PoissonDisk", "LatinHypercube", "Sobol", "Halton",
           "Random", "discrepancy", "sample"]

_DEFAULTS = _core._cnj_defaults


def _stretch_spec(stretch):
    """None, 'U:S' or (U, S) as the command line's 'U:S'."""
    if stretch is None or isinstance(stretch, str):
        return stretch
    try:
        direction, factor = stretch
        return ",".join(repr(float(u)) for u in direction) + ":" + repr(float(factor))
    except (TypeError, ValueError):
        raise ValueError(f"stretch takes 'U:S' or (U, S), got {stretch!r}") from None
_MIN_D, _MAX_D = _DEFAULTS["min_d"], _DEFAULTS["max_d"]
_SEED_RANGE = 2 ** 64


def _engine_seed(seed):
    """The engine's 64-bit seed from None, an int or a numpy.random.Generator (TypeError otherwise)."""
    if seed is None:
        return int(np.random.default_rng().integers(0, _SEED_RANGE, dtype=np.uint64))
    if isinstance(seed, np.random.Generator):
        return int(seed.integers(0, _SEED_RANGE, dtype=np.uint64))
    if isinstance(seed, numbers.Integral) and not isinstance(seed, (bool, np.bool_)):
        if not 0 <= int(seed) < _SEED_RANGE:
            raise ValueError(f"seed must be in [0, 2^64), got {int(seed)}")
        return int(seed)
    raise TypeError(f"seed must be None, an int or a numpy.random.Generator, not {type(seed).__name__}")


def _count(value, name, minimum):
    """An int >= minimum (TypeError for a non-integer, ValueError below the minimum)."""
    if not isinstance(value, numbers.Integral) or isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name} must be an int, not {type(value).__name__}")
    if value < minimum:
        raise ValueError(f"{name} must be at least {minimum}, got {int(value)}")
    return int(value)


def _real(value, name):
    """A float from a real number (TypeError naming `name` for a str, None or a list, whose float() would not)."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        raise TypeError(f"{name} must be a real number, not {type(value).__name__}")
    return float(value)


def _dimension(d, lo, hi, name="d"):
    d = _count(d, name, 1)
    if not lo <= d <= hi:
        raise ValueError(f"{name} must be in {lo}..{hi}, got {d}")
    return d


def _threads(workers, default):
    """SciPy's workers (-1: all cores) as the library's threads (0: all cores); None: the engine's."""
    if workers is None:
        return default
    workers = _count(workers, "workers", -1)
    if workers == 0:
        raise ValueError("workers must be -1 (all cores) or at least 1, got 0")
    return 0 if workers == -1 else workers


def _refuse(name, extra):
    """TypeError for keywords an engine does not take; `frequency` gets the name that replaced it."""
    if "frequency" in extra:
        raise TypeError(f"{name} takes cycles_per_spacing (CNJ's noise cycles per lattice spacing), not frequency: "
                        "in dfvn, frequency means cycles per unit length (as dfvn.field's)")
    if extra:
        raise TypeError(f"{name} got an unexpected keyword argument '{sorted(extra)[0]}'")


class QMCEngine:
    """What every engine has: d, the 64-bit seed it was given or drew (rng_seed), num_generated,
    reset() and fast_forward(n). Not used directly: see dfvn.Sobol, dfvn.CNJ, ..."""

    _name = "QMCEngine"

    def __init__(self, d, *, seed=None, threads=0):
        self.d = d
        self.rng_seed = _engine_seed(seed)
        self.threads = _count(threads, "threads", 0)
        self.num_generated = 0

    def reset(self):
        """Back to the start (point 0 of a sequence, set 0 of a set engine). Returns the engine."""
        self.num_generated = 0
        return self

    def fast_forward(self, n):
        """Skips n points (sequences) or n sets (set engines). Returns the engine."""
        self.num_generated += _count(n, "n", 0)
        return self

    def __repr__(self):
        return f"dfvn.{self._name}(d={self.d}, seed={self.rng_seed})"


# Sequences ----------------------------------------------------------------------------------------------

class _Sequence(QMCEngine):
    _method = ""

    def _points(self, n, workers):
        n = _count(n, "n", 0)
        if n == 0:
            return np.empty((0, self.d))
        points = _core._sequence(self._method, self.d, self.num_generated, n, self.rng_seed,
                                 getattr(self, "scramble", True), _threads(workers, self.threads))
        self.num_generated += n
        return points

    def random(self, n=1, *, workers=None):
        """The next n points of the sequence, an (n, d) float64 array in [0,1)^d.

        n: points (default 1). workers: threads, -1 = all cores (default None: the engine's `threads`);
        the points never depend on it."""
        return self._points(n, workers)


class Sobol(_Sequence):
    """Sobol' points (Joe-Kuo direction numbers), as scipy.stats.qmc.Sobol.

    d: dimension, 1..15 (the direction table's rows). scramble (default True): hash-based nested Owen
    scrambling (Burley 2020), seeded; False: the plain sequence, point 0 the origin. seed (default None):
    None, an int in [0, 2^64) or a numpy.random.Generator. threads (default 0: all cores): the points
    never depend on it. The sequence holds 2^32 points.

    random(n) continues the sequence and warns, as SciPy does, unless n and the points drawn before are
    powers of 2 (Sobol' points are balanced only at 2^m); random_base2(m) draws 2^m points and refuses a
    total that is not a power of 2; fast_forward(k) skips k points; reset() returns to point 0. Point i is
    the same whichever calls led to it: Sobol(d, seed=s).random(n) is `dfvn.sample("sobol", d, n=n, seed=s)`.
    """
    _name = "Sobol"
    _method = "sobol"
    MAXDIM = 15

    def __init__(self, d, *, scramble=True, seed=None, threads=0):
        super().__init__(_dimension(d, 1, self.MAXDIM), seed=seed, threads=threads)
        self.scramble = bool(scramble)

    def random(self, n=1, *, workers=None):
        """The next n Sobol' points, an (n, d) float64 array in [0,1)^d; warns (UserWarning, SciPy's
        words) unless n and the points drawn before are powers of 2.

        n: points (default 1). workers: threads, -1 = all cores (default None: the engine's `threads`)."""
        n = _count(n, "n", 0)
        drawn = self.num_generated
        if n & (n - 1) != 0 or (drawn > 0 and drawn & (drawn - 1) != 0):
            warnings.warn("The balance properties of Sobol' points require n to be a power of 2.", UserWarning,
                          stacklevel=2)
        return self._points(n, workers)

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
        return self._points(n, None)


class Halton(_Sequence):
    """Halton points (radical inverses in the first d primes), as scipy.stats.qmc.Halton.

    d: dimension, 1..16. scramble (default True): random digit permutations (Braaten-Weller, SciPy's
    scheme), seeded; False: the plain sequence. seed (default None): None, an int in [0, 2^64) or a
    numpy.random.Generator. threads (default 0: all cores).

    random(n) continues the sequence; fast_forward(k) skips k points; reset() returns to point 0.
    Halton(d, seed=s).random(n) is `dfvn.sample("halton", d, n=n, seed=s)`."""
    _name = "Halton"
    _method = "halton"

    def __init__(self, d, *, scramble=True, seed=None, threads=0):
        super().__init__(_dimension(d, 1, 16), seed=seed, threads=threads)
        self.scramble = bool(scramble)


class Random(_Sequence):
    """Uniform random points in [0,1)^d, a counter-based sequence (point i depends on the seed and i only).

    d: dimension, at least 1. seed (default None): None, an int in [0, 2^64) or a numpy.random.Generator.
    threads (default 0: all cores). random(n) continues the sequence; fast_forward(k) skips k points;
    reset() returns to point 0. Random(d, seed=s).random(n) is `dfvn.sample("random", d, n=n, seed=s)`."""
    _name = "Random"
    _method = "random"

    def __init__(self, d, *, seed=None, threads=0):
        super().__init__(_dimension(d, 1, 1 << 20), seed=seed, threads=threads)


# Sets ---------------------------------------------------------------------------------------------------

class _SetEngine(QMCEngine):
    _method = ""

    def __init__(self, d, *, seed=None, protocol="unit", threads=0, max_memory_gib=0.0, **options):
        super().__init__(_dimension(d, _MIN_D, _MAX_D), seed=seed, threads=threads)
        self.protocol = protocol
        self.max_memory_gib = _real(max_memory_gib, "max_memory_gib")
        self._options = options

    def _set_seed(self):
        return (self.rng_seed + self.num_generated) % _SEED_RANGE

    def random(self, n=1, *, grid=None, workers=None):
        """A new, independently seeded set (the next one: set k is seed + k) as an (points, d) float64 array.

        n: the points asked for (default 1); the lattice methods take the K^d lattice nearest to n, and a
        UserWarning names both counts whenever the set holds another number than n. grid: K instead of n
        (the K^d lattice, or K^d points for the methods without a lattice); give one of n and grid.
        workers: threads, -1 = all cores (default None: the engine's `threads`); the set never depends on it.
        """
        if grid is not None:
            if n != 1:
                raise ValueError("give one of n (a point count) and grid (K: the K^d lattice), not both")
            size = dict(grid=_count(grid, "grid", 0))
        else:
            size = dict(n=_count(n, "n", 0))
        points, requested, k, _side, saturated, radius = _core._generate(
            self._method, self.d, seed=self._set_seed(), protocol=self.protocol,
            threads=_threads(workers, self.threads), max_memory_gib=self.max_memory_gib, **size, **self._options)
        self.num_generated += 1
        got = len(points)
        if grid is None and got != n:
            why = []
            if requested != n:
                why.append(self._why_requested(requested, k))
            if got < requested:
                why.append(self._why_fewer(requested - got, saturated, radius))
            warnings.warn(f"{self._name}: {got} points instead of the {n} asked ({'; '.join(why)})", UserWarning,
                          stacklevel=2)
        elif grid is not None and saturated:
            warnings.warn(f"{self._name}: {got} points instead of the {requested} asked ("
                          f"{self._why_fewer(requested - got, saturated, radius)})", UserWarning, stacklevel=2)
        return points

    def _why_requested(self, requested, k):
        return f"the K^d lattice nearest to n: {k}^{self.d} = {requested}"

    def _why_fewer(self, missing, saturated, radius):
        return f"{missing} fewer"


class CNJ(_SetEngine):
    """Curl-noise jittering: the K^d lattice moved along a divergence-free noise field (the paper's method).

    d: dimension, 2..8. seed (default None): None, an int in [0, 2^64) or a numpy.random.Generator; set k
    is made with seed + k. protocol (default 'unit'): 'unit' (the lattice of spacing 1/K in [0,1)^d) or
    'paper' (the paper's Section 5.1, spacing 0.1, as `dfvn-sample --protocol paper`).
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

    random(n) rounds n to the nearest K^d (a UserWarning names both counts when they differ; in the
    ball, the ball's sites; in drop mode, the points kept); random(grid=K) takes K itself."""
    _name = "CNJ"
    _method = "cnj"
    __doc__ = __doc__.format(**_DEFAULTS)

    def __init__(self, d, *, seed=None, protocol="unit", noise=_DEFAULTS["noise"],
                 cycles_per_spacing=_DEFAULTS["cycles_per_spacing"], step_scale=_DEFAULTS["step_scale"],
                 integrator=_DEFAULTS["integrator"], reprojection=None, steps=_DEFAULTS["steps"],
                 domain=None, domain_mode=_DEFAULTS["domain_mode"], bound=None, threads=0, max_memory_gib=0.0,
                 field=_DEFAULTS["field"], phase=0.0, stretch=None, time=None, **refused):
        _refuse(self._name, refused)
        super().__init__(d, seed=seed, protocol=protocol, threads=threads, max_memory_gib=max_memory_gib,
                         noise=noise, cycles_per_spacing=_real(cycles_per_spacing, "cycles_per_spacing"),
                         step_scale=_real(step_scale, "step_scale"),
                         integrator=integrator, reprojection=reprojection, steps=_count(steps, "steps", -(1 << 31)),
                         domain=domain, domain_mode=domain_mode, bound=bound, field=field, phase=_real(phase, "phase"),
                         stretch=_stretch_spec(stretch), time=None if time is None else _real(time, "time"))

    def _why_requested(self, requested, k):
        if self._options["domain"] == "ball":
            return f"the ball's sites of the {k}^{self.d} lattice nearest to n: {requested}"
        return super()._why_requested(requested, k)

    def _why_fewer(self, missing, saturated, radius):
        return f"{missing} dropped: they left the {self._options['domain'] or 'cube'} (domain_mode='drop')"


class Jitter(_SetEngine):
    """Jittered lattice: each point of the K^d lattice moved uniformly inside its cell (the paper's jitter).

    d: dimension, 2..8. seed (default None): None, an int in [0, 2^64) or a numpy.random.Generator; set k
    is made with seed + k. protocol (default 'unit'): 'unit' (spacing 1/K in [0,1)^d, half-width 1/(2K))
    or 'paper' (spacing 0.1, half-width 0.05). threads (default 0: all cores). max_memory_gib (default 0:
    80% of the machine's). random(n) rounds n to the nearest K^d (with a UserWarning naming both counts
    when they differ); random(grid=K) takes K itself."""
    _name = "Jitter"
    _method = "jitter"

    def __init__(self, d, *, seed=None, protocol="unit", threads=0, max_memory_gib=0.0, **refused):
        _refuse(self._name, refused)
        super().__init__(d, seed=seed, protocol=protocol, threads=threads, max_memory_gib=max_memory_gib)


class JitterMatched(CNJ):
    __doc__ = """Jitter at CNJ's RMS displacement: the control of the paper's comparison. Standalone it traces CNJ
    with the same seed and options (without keeping CNJ's points) and jitters CNJ's lattice by the uniform
    offset whose RMS displacement equals CNJ's, wrapped on the torus or reflected at the cube's faces.

    The ball is refused (its clipped lattice has no cells to jitter in). The parameters are CNJ's:

    """ + CNJ.__doc__[CNJ.__doc__.index("d: dimension"):]
    _name = "JitterMatched"
    _method = "jitter-matched"


class PoissonDisk(_SetEngine):
    """Poisson disk sampling (Bridson's dart throwing): no two points closer than `radius`.

    d: dimension, 2..8. radius (default 0: the protocol's, 1/K for the K^d lattice nearest to n under
    'unit', 0.1 under 'paper'). ncandidates (default 30): candidates tried around each active point.
    seed (default None): None, an int in [0, 2^64) or a numpy.random.Generator; set k is made with seed + k.
    protocol (default 'unit'): 'unit' ([0,1)^d) or 'paper' ([0, 0.1 K]^d). threads (default 0: all cores).
    max_memory_gib (default 0: 80% of the machine's).

    random(n) places n points, or fewer when the domain is full at this radius, with a UserWarning naming
    both counts."""
    _name = "PoissonDisk"
    _method = "pds"

    def __init__(self, d, *, radius=0.0, ncandidates=30, seed=None, protocol="unit", threads=0, max_memory_gib=0.0,
                 **refused):
        _refuse(self._name, refused)
        super().__init__(d, seed=seed, protocol=protocol, threads=threads, max_memory_gib=max_memory_gib,
                         radius=_real(radius, "radius"), ncandidates=_count(ncandidates, "ncandidates", -(1 << 31)))

    def _why_fewer(self, missing, saturated, radius):
        return f"Poisson disk sampling saturated at radius {radius:g}; a lower radius gives more"


class LatinHypercube(_SetEngine):
    """Latin hypercube sampling, as scipy.stats.qmc.LatinHypercube's default (scramble=True): on each axis
    the n points take the n strata [m/n, (m+1)/n) in a random order, each at a uniform place in its stratum.

    d: dimension, 2..8. seed (default None): None, an int in [0, 2^64) or a numpy.random.Generator; set k
    is made with seed + k. protocol (default 'unit'): 'unit' ([0,1)^d) or 'paper' ([0, 0.1 K]^d).
    threads (default 0: all cores). max_memory_gib (default 0: 80% of the machine's).
    random(n) returns exactly n points."""
    _name = "LatinHypercube"
    _method = "lhs"

    def __init__(self, d, *, seed=None, protocol="unit", threads=0, max_memory_gib=0.0, **refused):
        _refuse(self._name, refused)
        super().__init__(d, seed=seed, protocol=protocol, threads=threads, max_memory_gib=max_memory_gib)


# The engines by dfvn-sample's method names.
ENGINES = {"cnj": CNJ, "jitter-matched": JitterMatched, "jitter": Jitter, "pds": PoissonDisk, "sobol": Sobol,
           "random": Random, "halton": Halton, "lhs": LatinHypercube}


def sample(method, dim, *, grid=None, n=None, seed=1, protocol="unit", scramble=True, radius=0.0, ncandidates=30,
           noise=_DEFAULTS["noise"], cycles_per_spacing=_DEFAULTS["cycles_per_spacing"],
           step_scale=_DEFAULTS["step_scale"], integrator=_DEFAULTS["integrator"],
           reprojection=None, steps=_DEFAULTS["steps"], domain=None,
           domain_mode=_DEFAULTS["domain_mode"], bound=None, threads=0, max_memory_gib=0.0, field=_DEFAULTS["field"],
           phase=0.0, stretch=None, time=None, **refused):
    """One point set as an (n, dim) float64 array, the same bits as `dfvn-sample --points DIR --format npy`:
    the first set (or the first points) of the method's engine (dfvn.CNJ, dfvn.Sobol, ...).

    method: 'cnj' (curl noise jittering), 'jitter', 'jitter-matched' (jitter at CNJ's RMS displacement),
    'pds' (Poisson disk), 'sobol', 'random', 'halton', 'lhs'. dim: 2..8 (the engines call it d).
    Exactly one of grid (K: cnj and jitter move the K^dim lattice, the others take its count) or n (a point
    count: pds, sobol, random, halton and lhs give n points, or pds fewer when it saturates; cnj and
    jitter use the lattice K^dim nearest to n; a UserWarning names both counts whenever they differ;
    sobol warns unless n is a power of 2). seed (default 1): None, an int in [0, 2^64) or a
    numpy.random.Generator. protocol (default 'unit'): 'unit' (every method in [0,1]^dim at the density of
    a cell-centred lattice) or 'paper' (the paper's Section 5.1, as `dfvn-sample --protocol paper`).
    scramble (default True): Owen-scrambled Sobol, digit-permuted Halton (False: neither). radius
    (default 0: the protocol's), ncandidates (default 30): Poisson disk's. noise, cycles_per_spacing,
    step_scale, integrator, reprojection, steps (default 0: the domain's count), domain (default None),
    domain_mode (default 'conformant'), bound (default None), field (default 'dfvn'), phase (default 0.0),
    stretch (default None), time (default None): CNJ's options, defaults and meaning as
    dfvn.CNJ's (`frequency` is refused: it is now cycles_per_spacing). threads (default 0: all cores; the
    result never depends on it). max_memory_gib (default 0: 80% of the machine's memory): a larger set
    raises ValueError before any work."""
    _refuse("sample", refused)
    if method not in ENGINES:
        raise ValueError(f"unknown method {method!r} (allowed: {', '.join(ENGINES)})")
    dim = _dimension(dim, _MIN_D, _MAX_D, name="dim")
    if (grid is None) == (n is None):
        raise ValueError("give exactly one of grid (K: a K^N lattice) or n (a point count)")
    if n is not None:
        n = _count(n, "n", 1)
    engine = ENGINES[method]
    cnj = dict(noise=noise, cycles_per_spacing=cycles_per_spacing, step_scale=step_scale, integrator=integrator,
               reprojection=reprojection, steps=steps, domain=domain, domain_mode=domain_mode, bound=bound, field=field,
               phase=_real(phase, "phase"), stretch=_stretch_spec(stretch),
               time=None if time is None else _real(time, "time"))
    pds = dict(radius=radius, ncandidates=ncandidates)
    if issubclass(engine, _Sequence):
        # The count and the domain under the protocol (Sobol under 'paper' lives on [0, 0.1 K]^dim);
        # validates every option as the command line does, those of the other methods included.
        requested, _k, lo, side = _core._plan(method, dim, grid=grid, n=n, seed=0, protocol=protocol,
                                              scramble=bool(scramble), threads=threads, max_memory_gib=max_memory_gib,
                                              **cnj, **pds)
        assert lo == 0.0
        options = dict(scramble=scramble) if method != "random" else {}
        made = engine(dim, seed=seed, threads=threads, **options)
        points = _caller_warned(lambda: made.random(requested))
        if side != 1.0:
            points *= side  # as the library's lo + side * u with lo = 0: the same bits
        return points
    options = {"cnj": cnj, "jitter-matched": cnj, "pds": pds}.get(method, {})
    made = engine(dim, seed=seed, protocol=protocol, threads=threads, max_memory_gib=max_memory_gib, **options)
    return _caller_warned(lambda: made.random(n) if grid is None else made.random(grid=grid))


def _caller_warned(draw):
    """Runs draw() and warns its warnings again, naming sample's caller rather than this module."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        points = draw()
    for w in caught:
        warnings.warn(w.message, w.category, stacklevel=3)
    return points


def discrepancy(sample, *, iterative=False, method="CD", workers=1):
    """The discrepancy of a sample in [0,1]^d, as scipy.stats.qmc.discrepancy (same names and defaults).

    sample: (n, d) array_like in the unit hypercube (ValueError otherwise). iterative (default False):
    SciPy's form for updating a discrepancy point by point; True raises NotImplementedError (dfvn has no
    update_discrepancy). method (default 'CD'): 'CD' (centered), 'WD' (wrap-around), 'MD' (mixture), all
    three squared as SciPy returns them, or 'L2-star' (its square root, as SciPy). workers (default 1):
    threads, -1 = all cores; the value never depends on it. Exact closed-form double sums, O(n^2 d)."""
    if iterative:
        raise NotImplementedError("discrepancy(iterative=True) is SciPy's form for update_discrepancy, which dfvn "
                                  "does not have; use iterative=False")
    points = np.asarray(sample, dtype=np.float64)
    if points.ndim != 2:
        raise ValueError(f"Sample is not a 2D array (got {points.ndim} dimension(s))")
    if not ((points >= 0.0) & (points <= 1.0)).all():
        raise ValueError("Sample is not in unit hypercube")
    return _core._discrepancy(np.ascontiguousarray(points), str(method), _threads(workers, 1))
