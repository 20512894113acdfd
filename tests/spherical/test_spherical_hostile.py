"""Hostile values for the spherical design functions (issue 24): angles beyond 2**52 rad
(where float64 names no direction) are refused by name before any search, and orientations
that differ by 1e-200 rad give no RuntimeWarning."""

import warnings

import numpy as np
import pytest

from tests.test_public_inputs import CASES


@pytest.mark.parametrize("key, name", [("spherical.path_fourbar", "start"), ("spherical.path_watt1", "start"),
                                       ("spherical.path_stephenson2", "start"),
                                       ("spherical.optimal_guidance", "theta_input")])
@pytest.mark.parametrize("scale", [1e200, -1e300])
def test_angles_beyond_2_52_refused_by_name(key, name, scale):
    entry = CASES[key]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(ValueError, match=f"`{name}`.*2\\*\\*52"):
            entry.call(**{name: np.asarray(entry.kwargs[name], dtype=float) * scale + scale})


# solves a six-bar task (seconds): off `make test`
@pytest.mark.exhaustive
def test_crank_angles_1e_200_apart_are_quiet():
    entry = CASES["spherical.guidance_watt2"]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        try:
            entry.call(theta=np.asarray(entry.kwargs["theta"], dtype=float) * 1e-200)
        except ValueError as e:
            assert "`" in str(e)
