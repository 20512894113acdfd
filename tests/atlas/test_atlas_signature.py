"""Shape signatures (``mech.atlas.curve_signature``): the invariances of the derivation page
``derivations/atlas/shape_signature.md``, property by property, to 1e-12.

"Exact resampling" is a band-limited curve (a trigonometric polynomial of degree 6) sampled
at N = 64 equal steps of its parameter, passed with ``resampled=True``: then a start shift by
any fraction of a step acts exactly on the coefficients. Arc-length resampling of polylines
is tested separately: it commutes exactly with similarities and with a reversal that keeps
the first point, and an open arc reversed is a restart of its closed double. Translations
are drawn in units of the curve's scale (up to 50 times it): far larger ones lose digits in
the coordinates themselves.
"""

import numpy as np
import pytest
from hypothesis import assume, given, settings, strategies as st

from mech.atlas import curve_signature, read_points, resample
from mech.atlas._planar._signature import normal_form

N, DEGREE = 64, 6
_coef = st.floats(-1.0, 1.0, allow_nan=False, allow_infinity=False)
_curve = st.lists(st.tuples(_coef, _coef), min_size=2 * DEGREE + 1, max_size=2 * DEGREE + 1)
_similarity = st.tuples(st.floats(-50, 50), st.floats(-50, 50), st.floats(-np.pi, np.pi),
                        st.floats(1e-3, 1e3))


def _band_limited(pairs, tau=0.0, reverse=False):
    """Samples at t_j = j/N + tau of sum_k c_k exp(2 pi i k t), k = -DEGREE..DEGREE."""
    c = np.array([complex(*p) for p in pairs])
    k = np.arange(-DEGREE, DEGREE + 1)
    t = np.arange(N) / N + tau
    if reverse:
        t = -t
    return np.exp(2j * np.pi * np.outer(t, k)) @ c


def _well_posed(z, gap=1e-8):
    """c_1 and c_-1 not tiny, and a clear winner among the four normal forms (no key tie)."""
    C = np.fft.fft(z) / z.size
    S = np.sqrt(np.sum(np.abs(C[1:]) ** 2))
    if not S > 1e-6 or min(abs(C[1]), abs(C[-1])) < 0.05 * S:
        return False
    form = normal_form(z[None, :], 8)
    cands = form.candidates[0]
    keys = cands @ (1.0 / (1.0 + np.arange(32)))
    best = np.argmax(keys)
    other = np.max(np.abs(cands - cands[best]), axis=1) > 1e-10     # a different normal form
    return not other.any() or keys[best] - keys[other].max() > gap


def _move(z, sim):
    """A similarity; its translation is in units of the scale (a curve of size 1e-3 moved by
    50 keeps only 12 of its 16 digits in floating point, whatever the signature does)."""
    x, y, beta, rho = sim
    return rho * complex(x, y) + rho * np.exp(1j * beta) * z


@settings(max_examples=300, deadline=None)
@given(pairs=_curve, sim=_similarity, tau=st.floats(0.0, 1.0), reverse=st.booleans())
def test_curve_signature_invariant_all_at_once(pairs, sim, tau, reverse):
    z = _band_limited(pairs)
    assume(_well_posed(z))
    s0 = curve_signature(z, resampled=True)
    s1 = curve_signature(_move(_band_limited(pairs, tau, reverse), sim), resampled=True)
    assert np.max(np.abs(s1 - s0)) < 1e-12


@pytest.mark.parametrize("nuisance", ["translation", "rotation", "scale", "start", "direction"])
@settings(max_examples=60, deadline=None)
@given(pairs=_curve, value=st.floats(0.0, 1.0))
def test_curve_signature_invariant_each(nuisance, pairs, value):
    z = _band_limited(pairs)
    assume(_well_posed(z))
    moved = {
        "translation": lambda: z + 100.0 * complex(value, -value),
        "rotation": lambda: np.exp(2j * np.pi * value) * z,
        "scale": lambda: 10.0 ** (6 * value - 3) * z,
        "start": lambda: _band_limited(pairs, tau=value),
        "direction": lambda: _band_limited(pairs, reverse=True),
    }[nuisance]()
    assert np.max(np.abs(curve_signature(moved, resampled=True) - curve_signature(z, resampled=True))) < 1e-12


@settings(max_examples=100, deadline=None)
@given(pairs=_curve, sim=_similarity, tau=st.floats(0.0, 1.0), reverse=st.booleans())
def test_normal_forms_are_an_invariant_set(pairs, sim, tau, reverse):
    """Without any tie-break: each of the four normal forms reappears after the move."""
    z = _band_limited(pairs)
    C = np.fft.fft(z) / N
    S = np.sqrt(np.sum(np.abs(C[1:]) ** 2))
    assume(S > 1e-6 and min(abs(C[1]), abs(C[-1])) > 0.05 * S)
    a = normal_form(z[None], 8).candidates[0]
    b = normal_form(_move(_band_limited(pairs, tau, reverse), sim)[None], 8).candidates[0]
    gaps = np.max(np.abs(a[:, None, :] - b[None, :, :]), axis=2)
    assert np.max(np.min(gaps, axis=1)) < 1e-12


_vertex = st.tuples(st.floats(-10, 10), st.floats(-10, 10))


@settings(max_examples=100, deadline=None)
@given(vertices=st.lists(_vertex, min_size=4, max_size=30), sim=_similarity, reverse=st.booleans())
def test_curve_signature_polyline_resampled(vertices, sim, reverse):
    """Arc-length resampling commutes with a similarity and a reversal from the same point."""
    z = np.array([complex(*v) for v in vertices])
    assume(np.min(np.abs(np.diff(np.append(z, z[0])))) > 1e-3)     # no repeated vertex
    assume(_well_posed(resample(z, 128)))
    w = np.roll(z[::-1], 1) if reverse else z
    s0, s1 = curve_signature(z), curve_signature(_move(w, sim))
    assert np.max(np.abs(s1 - s0)) < 1e-12


@settings(max_examples=100, deadline=None)
@given(vertices=st.lists(_vertex, min_size=3, max_size=20), sim=_similarity)
def test_curve_signature_open_arc_direction(vertices, sim):
    z = np.array([complex(*v) for v in vertices])
    assume(np.min(np.abs(np.diff(z))) > 1e-3)
    s0 = curve_signature(z, closed=False)
    s1 = curve_signature(_move(z[::-1], sim), closed=False)
    doubled = resample(z, 65, closed=False)[list(range(65)) + list(range(63, 0, -1))]
    assume(_well_posed(doubled))
    assert np.max(np.abs(s1 - s0)) < 1e-12


def test_curve_signature_tells_shapes_apart():
    t = np.linspace(0, 2 * np.pi, 300, endpoint=False)
    ellipse = np.cos(t) + 0.5j * np.sin(t)
    egg = ellipse + 0.2 * np.exp(2j * t)
    eight = np.sin(t) + 0.5j * np.sin(2 * t)
    s = curve_signature(np.stack([ellipse, egg, eight]))
    d = np.linalg.norm(s[:, None] - s[None, :], axis=2)
    assert np.min(d[~np.eye(3, dtype=bool)]) > 0.05


def test_curve_signature_start_at_a_vertex_is_close():
    """A restart between arc-length samples moves the signature by the resampling error only."""
    t = np.linspace(0, 2 * np.pi, 2000, endpoint=False)
    egg = np.cos(t) + 0.6j * np.sin(t) + 0.2 * np.exp(2j * t)
    assert np.max(np.abs(curve_signature(np.roll(egg, 777)) - curve_signature(egg))) < 1e-4


@pytest.mark.parametrize("shape", [(), (3,), (2, 2)])
def test_curve_signature_broadcast(shape):
    t = np.linspace(0, 2 * np.pi, 50, endpoint=False)
    egg = np.cos(t) + 0.6j * np.sin(t) + 0.2 * np.exp(2j * t)
    stack = np.broadcast_to(egg, (*shape, 50))
    out = curve_signature(stack, harmonics=5)
    assert out.shape == (*shape, 20)
    assert np.allclose(out, curve_signature(egg, harmonics=5), rtol=0, atol=1e-15)


def test_resample_square_and_open():
    sq = resample([0, 1, 1 + 1j, 1j], 8)
    assert np.allclose(sq, [0, 0.5, 1, 1 + 0.5j, 1 + 1j, 0.5 + 1j, 1j, 0.5j], atol=1e-15)
    arc = resample([0, 1, 3], 4, closed=False)
    assert np.allclose(arc, [0, 1, 2, 3], atol=1e-15)


@pytest.mark.parametrize("call, message", [
    (lambda: curve_signature([1, 1, 1]), "Expected `points` that are not all equal"),
    (lambda: curve_signature([0, 1]), "Expected `points` of shape"),
    (lambda: curve_signature([0, 1, np.nan]), "Expected finite `points`"),
    (lambda: curve_signature([0, 1, 1j], harmonics=0), "Expected `harmonics`"),
    (lambda: curve_signature([0, 1, 1j], samples=16, harmonics=8), "Expected `samples` > 2"),
    (lambda: curve_signature([0, 1, 1j], closed=False, samples=33), "Expected an even `samples`"),
    (lambda: curve_signature([0, 1, 1j], resampled=True), "Expected more than 2 \\* harmonics"),
    (lambda: curve_signature([0, 1, 1j], closed=1), "Expected `closed`"),
    (lambda: resample([0, 1, 1j], 3), "Expected `samples`"),
    (lambda: resample([[0, 1, 1j], [2, 2, 2]], 8), "not all equal \\(curve 1\\)"),
])
def test_signature_bad_inputs_named(call, message):
    with pytest.raises(ValueError, match=message):
        call()


def test_read_points_header_and_comments(tmp_path):
    path = tmp_path / "curve.csv"
    path.write_text("# digitised\nx, y\n0, 0\n1.5, 0\n1.5, 2\n")
    assert np.array_equal(read_points(path), [0, 1.5, 1.5 + 2j])


@pytest.mark.parametrize("text, message", [
    ("0,0\n1,x\n", "rows of two numbers"),
    ("0,0\n1,2,3\n", "rows of two finite numbers"),
    ("0,0\n1,nan\n", "rows of two finite numbers"),
    ("x,y\n0,0\n", "at least 2 points"),
])
def test_read_points_bad_file(tmp_path, text, message):
    path = tmp_path / "bad.csv"
    path.write_text(text)
    with pytest.raises(ValueError, match=f"`path`.*{message}|{message}.*`path`"):
        read_points(path)


def test_read_points_missing_and_not_a_path(tmp_path):
    with pytest.raises(ValueError, match="Expected `path` to name a readable CSV"):
        read_points(tmp_path / "missing.csv")
    with pytest.raises(TypeError, match="Expected `path`"):
        read_points(3.0)


def test_curve_signature_huge_curve_no_overflow():
    """A curve of size 1e299 has the signature of its unit copy, without an overflow warning
    (the norm of the harmonics is scaled by the largest; issue 11)."""
    import warnings
    t = np.linspace(0.0, 2.0 * np.pi, 200, endpoint=False)
    z = np.cos(t) + 0.3j * np.sin(2 * t) + 0.5 + 0.1j * np.cos(3 * t)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        big = curve_signature(z * 1e299)
    np.testing.assert_allclose(big, curve_signature(z), atol=1e-14)


def test_build_atlas_huge_coupler_range_quiet():
    """`coupler` spanning -1e300 builds without a RuntimeWarning (issue 11)."""
    import warnings
    from mech.atlas import build_atlas
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        atlas = build_atlas(20, seed=1, coupler=(-1e300, 2.0, -1.5, 1.5))
    assert atlas is not None
