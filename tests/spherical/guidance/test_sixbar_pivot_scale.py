"""The crank pivot of the spherical six-bar guidance functions is a direction: a vector of
length 1e-200 or 1e200 gives the design of the unit vector, with no warning (issue 24; at
1e200 the norm overflowed, at 1e-200 it was taken for zero)."""

import warnings

import numpy as np
import pytest

from tests.test_public_inputs import CASES

NAMES = ["spherical.guidance_stephenson1", "spherical.guidance_stephenson3"]


# each call solves a six-bar task (seconds): an acceptance check, off `make test`
@pytest.mark.exhaustive
@pytest.mark.parametrize("name", NAMES)
@pytest.mark.parametrize("scale", [1e-200, 1e200])
def test_crank_pivot_length_does_not_matter(name, scale):
    entry = CASES[name]
    pivot = np.asarray(entry.kwargs["crank_pivot"], dtype=float)
    one = entry.call()
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        scaled = entry.call(crank_pivot=pivot * scale)
    assert len(scaled) == len(one)
    for a, b in zip(one, scaled):
        assert repr(a) == repr(b)
