"""The slider-crank atlas: design space, store and search (``mechanism="slider-crank"``).

References are independent of the vectorised code in ``mech.atlas._planar._slider``: coupler points
from ``mech.planar.Linkage`` (a crank and an RRP group with a point on the rod), the
minimum transmission angle from ``mech.planar.forces.slider_crank_min_transmission_angle``
(F57) and from a dense scan of the rod's angle to the guide's normal taken from
``Linkage`` poses, the input range from ``mech.planar.SliderCrank.solve``.
"""

import numpy as np
import pytest

from mech.atlas import (Atlas, PlacedSliderCrank, SliderCrankSamples, build_atlas, query, refine,
                        sample_slider_cranks)
from mech.planar import Guide, Linkage, SliderCrank
from mech.planar.forces import slider_crank_min_transmission_angle


def _linkage(a, b, e, p, q, branch):
    """A slider-crank with the coupler point P on the rod, built from Assur groups."""
    return (Linkage({"A": 0})
            .crank("crank", pivot="A", tip="B", length=a)
            .rrp(("rod", "slider"), pin="B", guide=Guide("ground", e * 1j, 0.0), joint="C", length=b,
                 branch=branch)
            .point("P", link="rod", at=complex(p, q)))


def _linkage_points(a, b, e, p, q, theta, side):
    """P at crank angles `theta` with C on `side` of B (+1: C - B points along +x)."""
    out = np.full(theta.shape, np.nan + 0j)
    for mode in (1, -1):
        sol = _linkage(a, b, e, p, q, mode).solve(theta)
        rod = sol.points["C"] - sol.points["B"]
        pick = np.isfinite(rod) & (np.sign(rod.real) == side)
        out = np.where(pick, sol.points["P"], out)
    return out


@pytest.fixture(scope="module")
def samples():
    return sample_slider_cranks(3000, seed=21)


@pytest.fixture(scope="module")
def atlas():
    return build_atlas(6000, seed=4, mechanism="slider-crank")


def test_sample_slider_cranks_space_and_types(samples):
    assert np.all(samples.a == 1.0)
    assert samples.b.min() >= 0.3 and samples.b.max() <= 5.0
    assert samples.e.min() >= -2.0 and samples.e.max() <= 2.0
    assert np.array_equal(samples.full_turn, samples.b >= 1 + np.abs(samples.e))
    assert np.array_equal(samples.movable, np.abs(samples.e) < 1 + samples.b)
    assert set(samples.kind[samples.full_turn]) == {"crank-slider"}
    assert set(samples.kind[~samples.full_turn]) == {"rocker-slider"}
    for i in np.flatnonzero(samples.movable)[::29]:
        assert SliderCrank(samples.a[i], samples.b[i], samples.e[i]).crank_turns == bool(samples.full_turn[i])


def test_gamma_min_against_f57_and_a_dense_scan(samples):
    full = np.flatnonzero(samples.full_turn)[:40]
    theta = np.linspace(0, 2 * np.pi, 20001)
    for i in full:
        a, b, e = samples.a[i], samples.b[i], samples.e[i]
        ref, _ = slider_crank_min_transmission_angle(a, b, e)
        assert samples.gamma_min[i] == pytest.approx(ref, abs=1e-12)
        sol = _linkage(a, b, e, 0.0, 0.0, 1).solve(theta)
        rod = sol.points["C"] - sol.points["B"]
        mu = np.arccos(np.abs(rod.imag) / b)         # the rod's angle to the guide's normal
        assert samples.gamma_min[i] == pytest.approx(mu.min(), abs=1e-6)
    assert np.all(samples.gamma_min[~samples.full_turn] == 0.0)


def test_input_range_ends_are_dead_centres(samples):
    rocking = np.flatnonzero(samples.movable & ~samples.full_turn)
    assert rocking.size > 100
    for i in rocking[:60]:
        mech = SliderCrank(samples.a[i], samples.b[i], samples.e[i])
        lo, hi = samples.theta_lo[i], samples.theta_hi[i]
        assert lo < hi
        for end, out in ((lo, -1e-6), (hi, 1e-6)):
            assert abs(samples.e[i] - samples.a[i] * np.sin(end)) == pytest.approx(samples.b[i], rel=1e-12)
            assert not bool(mech.solve(end + out).valid)
        inside = np.linspace(lo, hi, 41)[1:-1]
        assert np.all(mech.solve(inside).valid)


def test_coupler_curves_match_linkage_analysis(samples):
    n = 48
    u = 2 * np.pi * (np.arange(n) + 0.5) / n
    rows = np.flatnonzero(samples.movable)
    chosen = np.concatenate([rows[samples.full_turn[rows]][:15], rows[~samples.full_turn[rows]][:15]])
    curves = samples.take(chosen).curves(n)
    for row, curve in zip(chosen, curves):
        a, b, e, p, q = (samples.a[row], samples.b[row], samples.e[row], samples.p[row], samples.q[row])
        br = int(samples.branch[row])
        if samples.full_turn[row]:
            theta, side = u, np.full(n, br)
        else:
            lo, hi = samples.theta_lo[row], samples.theta_hi[row]
            theta = 0.5 * (lo + hi) + 0.5 * (hi - lo) * np.sin(u)
            side = br * np.where(np.cos(u) >= 0, 1, -1)
        ref = _linkage_points(a, b, e, p, q, theta, side)
        ok = np.isfinite(ref)
        assert ok.mean() > 0.9                          # all but poses on a dead centre
        assert np.max(np.abs(curve[ok] - ref[ok])) < 1e-9 * (1 + abs(p) + abs(q) + b)


def test_slider_atlas_parquet_round_trip(tmp_path):
    built = build_atlas(120, seed=3, mechanism="slider-crank", block=64)
    built.to_parquet(tmp_path / "s")
    back = Atlas.from_parquet(tmp_path / "s")
    assert isinstance(back.linkages, SliderCrankSamples)
    assert back.settings["mechanism"] == "slider-crank"
    np.testing.assert_array_equal(back.signatures, built.signatures)
    np.testing.assert_array_equal(back.linkages.e, built.linkages.e)
    with pytest.raises(ValueError, match="mechanism"):
        build_atlas(50, seed=9, block=64).to_parquet(tmp_path / "s", append=True)


def test_bad_mechanism_and_refine_named():
    with pytest.raises(ValueError, match="`mechanism`"):
        build_atlas(10, mechanism="crank-rocker")
    small = build_atlas(40, seed=2, mechanism="slider-crank")
    match = query(small, small.curves(3)[0], k=1)[0]
    with pytest.raises(ValueError, match="`match`"):
        refine(match, small.curves(3)[0])


def _target(atlas, row, rng, noise=1e-3, m=400):
    """The closed curve of an atlas slider-crank, recomputed by Linkage, moved, and noisy."""
    lk = atlas.linkages
    a, b, e, p, q, br = (lk.a[row], lk.b[row], lk.e[row], lk.p[row], lk.q[row], int(lk.branch[row]))
    theta = rng.uniform(0, 2 * np.pi) + np.linspace(0, 2 * np.pi, m, endpoint=False)
    z = _linkage(a, b, e, p, q, br).solve(theta).points["P"]
    z = z[::int(rng.choice([-1, 1]))]
    z = complex(*rng.normal(0, 5, 2)) + np.exp(1j * rng.uniform(0, 2 * np.pi)) * 10 ** rng.uniform(-1, 2) * z
    radius = np.sqrt(np.mean(np.abs(z - z.mean()) ** 2))
    return z + noise * radius * (rng.normal(size=m) + 1j * rng.normal(size=m)) / np.sqrt(2)


def _recomputed(placed, m=8192):
    """The placed slider-crank's closed coupler curve by Linkage analysis over a full turn."""
    sc = placed.slider
    theta = np.linspace(0, 2 * np.pi, m, endpoint=False)
    z = _linkage(sc.a, sc.b, sc.e, *placed.coupler, sc.branch).solve(theta).points["P"]
    return placed.place(z)


def test_query_finds_slider_crank_first_and_places_it(atlas):
    rng = np.random.default_rng(8)
    full = np.flatnonzero(atlas.linkages.full_turn)
    rows = rng.choice(full, 60, replace=False)
    found, worst = 0, 0.0
    for row in rows:
        target = _target(atlas, int(row), rng)
        best = query(atlas, target, k=1)[0]
        found += best.index == row
        assert isinstance(best.linkage, PlacedSliderCrank) and len(best.cognates) == 1
        assert best.kind == "crank-slider" and best.full_turn
        curve = _recomputed(best.linkage)
        radius = np.sqrt(np.mean(np.abs(target - target.mean()) ** 2))
        # each target point lies within the noise of the recomputed curve
        gap = np.min(np.abs(target[:, None] - curve[None, :]), axis=1)
        worst = max(worst, np.sqrt(np.mean(gap ** 2)) / radius)
    assert found == len(rows)
    assert worst < 2e-3


def test_cli_builds_and_queries_a_slider_crank_atlas(tmp_path, capsys):
    from mech.atlas.__main__ import main

    folder = tmp_path / "sliders"
    assert main(["build", str(folder), "-n", "300", "--seed", "4", "--mechanism", "slider-crank", "--quiet"]) == 0
    atlas = Atlas.from_parquet(folder)
    row = int(np.flatnonzero(atlas.linkages.full_turn)[0])
    curve = 2 - 1j + 3 * atlas.curves(row)[0]
    np.savetxt(tmp_path / "t.csv", np.c_[curve.real, curve.imag], delimiter=",")
    assert main(["query", str(folder), str(tmp_path / "t.csv"), "-k", "2", "--plot", str(tmp_path / "p.png")]) == 0
    out = capsys.readouterr().out
    assert f"#0  row {row}  crank-slider" in out and "guide through" in out
    assert (tmp_path / "p.png").is_file()


def test_open_half_turn_arcs_of_slider_cranks_found(atlas):
    from mech.atlas._planar._sampling import coupler_points

    rng = np.random.default_rng(31)
    rows = rng.choice(np.flatnonzero(atlas.linkages.full_turn), 20, replace=False)
    found = 0
    for row in rows:
        u0 = rng.uniform(0, 2 * np.pi)
        u = (u0 + np.pi * np.linspace(0, 1, 200))[None, :]
        arc = coupler_points(atlas.linkages.take([int(row)]).columns(), u)[0]
        arc = (1 + 2j + 3 * np.exp(1j * rng.uniform(0, 6)) * arc)[::int(rng.choice([-1, 1]))]
        radius = np.sqrt(np.mean(np.abs(arc - arc.mean()) ** 2))
        arc = arc + 1e-3 * radius * (rng.normal(size=200) + 1j * rng.normal(size=200)) / np.sqrt(2)
        best = query(atlas, arc, k=1, closed=False)[0]
        assert isinstance(best.linkage, PlacedSliderCrank) and best.arc is not None
        found += best.index == row
    assert found >= 18, found


def test_slider_cognate_traces_the_same_curve_pose_by_pose(atlas):
    rng = np.random.default_rng(3)
    rows = np.concatenate([rng.choice(np.flatnonzero(atlas.linkages.full_turn), 6, replace=False),
                           rng.choice(np.flatnonzero(~atlas.linkages.full_turn), 4, replace=False)])
    for row in rows:
        target = 1 - 2j + 2.5 * np.exp(0.7j) * atlas.curves(int(row), 300)[0]
        best = query(atlas, target, k=1)[0]
        (cog,) = best.cognates
        placed, sc, g = best.linkage, best.linkage.slider, cog.slider
        assert (g.a, g.b) == pytest.approx((abs(complex(*placed.coupler)) / sc.b * sc.b,
                                             abs(complex(*placed.coupler)) / sc.b * sc.a))
        lo, hi = best.theta_range
        theta = np.linspace(lo, hi, 301)[1:-1]
        pts = []
        for mode in (1, -1):
            sol = _linkage(sc.a, sc.b, sc.e, *placed.coupler, mode).solve(theta)
            rod = sol.points["C"] - sol.points["B"]
            # away from the cognate's dead centres (cos theta = 0), where its rod's position
            # has only half the digits (a square root of a rounding-sized radicand)
            ok = np.isfinite(rod) & (np.abs(np.cos(theta)) > 1e-3)
            phi = np.angle(rod[ok])
            mine = placed.place(sol.points["P"][ok])
            # the cognate driven at the original rod's angle, on branch sign(cos theta)
            other = _linkage_points(g.a, g.b, g.e, *cog.coupler, phi, np.sign(np.cos(theta[ok])))
            pts.append(np.abs(cog.origin + np.exp(1j * cog.rotation) * other - mine))
        gap = np.concatenate(pts)
        assert np.isfinite(gap).mean() > 0.95
        assert np.nanmax(gap) < 1e-9 * (1 + np.max(np.abs(target)))
