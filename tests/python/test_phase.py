"""phase= (issue 25 item 1, rotating gradients) in dfvn.field, dfvn.trace, dfvn.CNJ and dfvn.sample: 0 is the
phase-free result bit for bit, the field has period 2 pi and flips its f_i at pi, the module gives the
command line's numbers at a phase, and a non-finite phase is a ValueError."""
import io
import math

import numpy as np
import pytest

import dfvn

POINTS = np.random.default_rng(5).random((300, 4)) * 7.0


@pytest.mark.parametrize("noise", ["turning-bands", "simplex", "quintic-gradient"])
def test_field_period_sign_and_phase_zero(noise):
    c0, f0 = dfvn.field(POINTS, noise=noise)
    cz, fz = dfvn.field(POINTS, noise=noise, phase=0.0)
    assert np.array_equal(c0, cz) and np.array_equal(f0, fz)
    c1, f1 = dfvn.field(POINTS, noise=noise, phase=1.0)
    c2, f2 = dfvn.field(POINTS, noise=noise, phase=1.0 + 2.0 * math.pi)
    cp, fp = dfvn.field(POINTS, noise=noise, phase=1.0 + math.pi)
    assert np.max(np.abs(f1 - f2)) < 1e-12 and np.max(np.abs(c1 - c2)) < 1e-12
    assert np.max(np.abs(f1 + fp)) < 1e-12
    assert np.max(np.abs(f1 - f0)) > 1e-3  # the phase does something


def test_field_matches_the_command_line_at_a_phase(cli, tmp_path):
    path = tmp_path / "points.csv"
    np.savetxt(path, POINTS, delimiter=",")
    table = np.loadtxt(io.StringIO(cli("field", "--input", path, "--phase", "2.5")), delimiter=",", skiprows=1)
    c, f = dfvn.field(POINTS, phase=2.5)
    assert np.array_equal(table[:, 4:8], c) and np.array_equal(table[:, 8:], f)


def test_cnj_and_sample_take_the_phase():
    base = dfvn.sample("cnj", 2, grid=8, seed=3)
    assert np.array_equal(base, dfvn.sample("cnj", 2, grid=8, seed=3, phase=0.0))
    assert np.array_equal(base, dfvn.CNJ(2, seed=3, phase=0.0).random(grid=8))
    moved = dfvn.sample("cnj", 2, grid=8, seed=3, phase=1.0)
    assert np.array_equal(moved, dfvn.CNJ(2, seed=3, phase=1.0).random(grid=8))
    assert not np.array_equal(base, moved)
    ends = dfvn.trace(POINTS, 0.1, phase=1.0)
    assert not np.array_equal(ends, dfvn.trace(POINTS, 0.1))


@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf])
def test_non_finite_phase_is_refused(bad):
    with pytest.raises(ValueError, match="phase must be a finite number"):
        dfvn.field(POINTS, phase=bad)
    with pytest.raises(ValueError, match="phase must be a finite number"):
        dfvn.sample("cnj", 2, grid=4, phase=bad)
    with pytest.raises(ValueError, match="phase must be a finite number"):
        dfvn.CNJ(2, phase=bad).random(grid=4)
