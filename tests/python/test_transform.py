"""stretch=, time=, lift= and lift_ramp= (issue 27 items 1-2, issue 25 item 2) in dfvn.field, dfvn.trace,
dfvn.CNJ and dfvn.sample: (U, S) and 'U:S' are the same stretch, S = 1 is the unstretched field bit for
bit, the module gives the command line's numbers, the lift's 2D field is divergence-free (central
differences), and bad values are a ValueError."""
import subprocess
import os

import numpy as np
import pytest

import dfvn

POINTS = np.random.default_rng(3).random((200, 3)) * 5.0


def test_stretch_spellings_and_identity():
    a, fa = dfvn.field(POINTS, stretch=((1, -2, 0.5), 3))
    b, fb = dfvn.field(POINTS, stretch="1,-2,0.5:3")
    assert np.array_equal(a, b) and np.array_equal(fa, fb)
    c0, f0 = dfvn.field(POINTS)
    c1, f1 = dfvn.field(POINTS, stretch=((1, -2, 0.5), 1.0))
    assert np.array_equal(c0, c1) and np.array_equal(f0, f1)
    assert np.max(np.abs(a - c0)) > 1e-2


def test_time_is_continuous_and_traces_take_it():
    c0, _ = dfvn.field(POINTS, time=0.3)
    c1, _ = dfvn.field(POINTS, time=0.3 + 1e-6)
    assert 0.0 < np.max(np.abs(c1 - c0)) < 1e-4
    ends = dfvn.trace(POINTS, 0.1, time=0.3, steps=4)
    assert ends.shape == POINTS.shape and np.all(np.isfinite(ends))


def test_lift_is_divergence_free():
    x = np.random.default_rng(4).uniform(-2.0, 2.0, (2000, 2))
    h = 1e-5
    div = np.zeros(len(x))
    scale = np.zeros(len(x))
    for j in range(2):
        e = np.zeros(2)
        e[j] = h
        cp, _ = dfvn.field(x + e, lift="bump:1.5,2", lift_ramp=0.4)
        cm, _ = dfvn.field(x - e, lift="bump:1.5,2", lift_ramp=0.4)
        d = (cp - cm) / (2 * h)
        div += d[:, j]
        scale += np.sum(d * d, axis=1)
    assert np.median(np.abs(div) / np.sqrt(scale)) < 1e-8


def test_cnj_and_sample_take_stretch_and_time():
    a = dfvn.sample("cnj", 2, grid=8, domain="cube", stretch=((1, 1), 3))
    b = dfvn.CNJ(2, seed=1, domain="cube", stretch="1,1:3").random(grid=8)
    assert np.array_equal(a, b)
    assert not np.array_equal(a, dfvn.sample("cnj", 2, grid=8, domain="cube"))
    assert dfvn.sample("cnj", 3, grid=5, time=0.5).shape == (125, 3)


def test_matches_the_command_line(tmp_path):
    binary = os.environ.get("DFVN_SAMPLE")
    if not binary:
        pytest.skip("DFVN_SAMPLE not set")
    np.savetxt(tmp_path / "p.csv", POINTS, delimiter=",")
    out = subprocess.run([binary, "field", "--input", str(tmp_path / "p.csv"), "--stretch", "1,-2,0.5:3", "--time", "0.7"],
                         check=True, capture_output=True, text=True).stdout
    table = np.loadtxt(out.splitlines()[1:], delimiter=",")
    c, f = dfvn.field(POINTS, stretch="1,-2,0.5:3", time=0.7)
    assert np.array_equal(table[:, 3:6], c) and np.array_equal(table[:, 6:], f)


@pytest.mark.parametrize("bad", [dict(stretch="0,0,0:2"), dict(stretch=((1, 0, 0), 0.0)), dict(stretch="1,0:2"),
                                 dict(stretch=(1, 2)), dict(time=float("nan")), dict(lift="plane:1,0"),
                                 dict(lift_ramp=1.0)])
def test_bad_values_raise(bad):
    with pytest.raises(ValueError):
        dfvn.field(POINTS, **bad)
