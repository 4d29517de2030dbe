"""The compiled-in Sobol direction numbers (data/new-joe-kuo-6.21201.bin, data/joe_kuo_directions.md) against
SciPy's copy of the same table, every one of the 21201 rows."""
import pathlib

import numpy as np
import pytest

from dfvn import _core

scipy_stats = pytest.importorskip("scipy.stats")
SCIPY_TABLE = pathlib.Path(scipy_stats.__file__).parent / "_sobol_direction_numbers.npz"


def test_every_row_is_scipys():
    if not SCIPY_TABLE.exists():
        pytest.skip(f"SciPy's table is not at {SCIPY_TABLE}")
    scipy_table = np.load(SCIPY_TABLE)
    poly, vinit = _core._joe_kuo_table()
    assert poly.shape == (21201,) and vinit.shape == (21201, 18)
    np.testing.assert_array_equal(poly, scipy_table["poly"])
    np.testing.assert_array_equal(vinit, scipy_table["vinit"])
