"""The constraint count of spatial linkages (F67) against cases counted by hand."""

import pytest

from mech.spatial._mobility import mobility


@pytest.mark.parametrize(
    "n, pairs, expected",
    [
        (3, "RSSR", 2),       # the textbook's count 3 x 6 - 2 x 3 - 2 x 5 (F67)
        (3, "RCCC", 1),       # 18 - 5 - 3 x 4
        (3, "RRRR", -2),      # the planar four-bar read as a spatial chain: redundant constraints
        (1, "R", 1),          # a crank
        (4, "RRPR", 4),       # the open manipulator of example 2-25: 24 - 4 x 5
    ],
)
def test_mobility_counts(n, pairs, expected):
    assert mobility(n, pairs) == expected


def test_mobility_rejects_bad_input():
    with pytest.raises(ValueError, match="pair letters"):
        mobility(3, "RXSR")
    with pytest.raises(ValueError, match="moving_links"):
        mobility(-1, "R")
