"""noise='steerable' with steer= and steer_k= in dfvn.field (issue 27 item 3, seed 002): the module gives the
command line's bytes, U and -U are the same field, the field is divergence-free by central differences, and
bad values are a ValueError."""
import os
import subprocess

import numpy as np
import pytest

import dfvn

POINTS = np.random.default_rng(5).random((200, 3)) * 5.0


def test_steerable_matches_the_command_line(tmp_path):
    c, f = dfvn.field(POINTS, noise="steerable", steer=(1, -2, 3), steer_k=0.3)
    minus, fm = dfvn.field(POINTS, noise="steerable", steer=(-1, 2, -3), steer_k=0.3)
    assert np.array_equal(c, minus) and np.array_equal(f, fm)
    binary = os.environ.get("DFVN_SAMPLE")
    if not binary:
        pytest.skip("DFVN_SAMPLE not set")
    path = tmp_path / "p.csv"
    np.savetxt(path, POINTS, delimiter=",", fmt="%.17g")
    out = subprocess.run([binary, "field", "--input", str(path), "--noise", "steerable", "--steer-dir", "1,-2,3",
                          "--steer-k", "0.3"], capture_output=True, text=True, check=True).stdout
    table = np.loadtxt(out.splitlines()[1:], delimiter=",")
    assert np.array_equal(table[:, 3:6], c) and np.array_equal(table[:, 6:], f)


def test_circular_field_is_divergence_free():
    h = 1e-5
    x = POINTS[:50]
    div = np.zeros(len(x))
    scale = np.zeros(len(x))
    for j in range(3):
        e = np.zeros(3)
        e[j] = h
        cp, _ = dfvn.field(x + e, noise="steerable", steer="circular")
        cm, _ = dfvn.field(x - e, noise="steerable", steer="circular")
        column = (cp - cm) / (2 * h)
        div += column[:, j]
        scale += np.sum(column**2, axis=1)
    assert np.median(np.abs(div) / np.sqrt(scale)) < 1e-8


@pytest.mark.parametrize("kwargs", [
    dict(noise="steerable"),
    dict(noise="steerable", steer=(0, 0, 0)),
    dict(noise="steerable", steer=(1, 0)),
    dict(noise="steerable", steer=(1, 0, 0), steer_k=1.5),
    dict(noise="steerable", steer="spiral"),
    dict(steer=(1, 0, 0)),
    dict(steer_k=0.3),
])
def test_bad_steering_is_a_value_error(kwargs):
    with pytest.raises(ValueError):
        dfvn.field(POINTS, **kwargs)


def test_steerable_refuses_five_dimensions():
    with pytest.raises(ValueError):
        dfvn.field(np.zeros((3, 5)), noise="steerable", steer="circular")
