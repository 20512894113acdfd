"""The free four-bar functions check their lengths and assembly as `FourBar` does."""

import numpy as np
import pytest

from mech import AssemblyError, InputTypeError
from mech.planar import FourBar
from mech.planar.forces._force_gain import fourbar_dead_points
from mech.planar.structure._limit_positions import limit_positions
from mech.planar.forces._pressure_angle import fourbar_pressure_angle, transmission_extremes
from mech.planar.forces._transmission import min_transmission_angle, transmission_angle

TOO_LONG = [((1.0, 4.0, 3.0, 9.0), "d", "8.0", "9.0"),
            ((12.0, 4.0, 3.0, 5.0), "a", "12.0", "12.0"),
            ((1.0, 2.0, 3.0, 6.0), "d", "6.0", "6.0"),       # d equal to the rest: flat
            # the rest is 2**-1000 times the longest or less: scaled, it was shown as 0.0
            ((1e300, 40.0, 30.0, 35.0), "a", "105.0", "1e\\+300")]
FUNCTIONS = {
    "transmission_angle": lambda L: transmission_angle(*L, 0.3),
    "fourbar_pressure_angle": lambda L: fourbar_pressure_angle(*L, 0.3),
    "min_transmission_angle": lambda L: min_transmission_angle(*L),
    "transmission_extremes": lambda L: transmission_extremes(*L),
    "limit_positions": lambda L: limit_positions(*L),
    "fourbar_dead_points": lambda L: fourbar_dead_points(*L),
    "FourBar": lambda L: FourBar(*L),
}


@pytest.mark.parametrize("function", list(FUNCTIONS))
@pytest.mark.parametrize("lengths, name, rest, value", TOO_LONG)
def test_fourbar_functions_reject_a_link_too_long(function, lengths, name, rest, value):
    """Every function that takes four lengths names the link that is too long, with the
    same message as `FourBar`."""
    with pytest.raises(ValueError, match=f"Expected `{name}` shorter than the other three "
                                         f"links together \\({rest}\\), got {value}"):
        FUNCTIONS[function](lengths)


@pytest.mark.parametrize("function", [transmission_angle, fourbar_pressure_angle])
@pytest.mark.parametrize("lengths", [(3.0, 2.0, 2.5, 4.0), (10.0, 40.0, 30.0, 35.0),
                                     (4.0, 1.0, 2.0, 2.5), (2.0, 1.0, 1.0, 2.0)])
def test_fourbar_angle_nan_where_fourbar_invalid(function, lengths):
    """NaN exactly where `FourBar.solve` reports the pose invalid (a triple-rocker, a
    crank-rocker, a double-rocker and a kite that locks), over a sweep of 3601 angles."""
    theta = np.linspace(-np.pi, np.pi, 3601)
    valid = FourBar(*lengths).solve(theta).valid
    value = function(*lengths, theta)
    assert np.array_equal(np.isnan(value), ~valid)
    assert np.all((value[valid] >= 0) & (value[valid] <= np.pi / 2))


@pytest.mark.parametrize("function", [transmission_angle, fourbar_pressure_angle])
def test_fourbar_angle_strict_raises_like_fourbar(function):
    """strict=True raises AssemblyError naming the first angle that cannot be assembled."""
    lengths = (3.0, 2.0, 2.5, 4.0)
    with pytest.raises(AssemblyError, match="theta = 3.14159") as fourbar_error:
        FourBar(*lengths).solve([0.0, np.pi], strict=True)
    with pytest.raises(AssemblyError, match="theta = 3.14159"):
        function(*lengths, [0.0, np.pi], strict=True)
    assert "theta = 3.14159" in str(fourbar_error.value)
    assert np.isfinite(function(*lengths, 0.0, strict=True))
    with pytest.raises(InputTypeError, match="Expected `strict` to be True or False, got 'yes'"):
        function(*lengths, 0.0, strict="yes")
