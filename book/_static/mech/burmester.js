// Rigid-body guidance through four and five poses for the live design page: the Burmester
// dyads of five poses and the circle-point and centre-point curves of four, by the route of
// mech.planar.synthesis (burmester, circle_point_curve). Written by hand around the
// generated kernel `crank_design_row` of derivations/planar/displacement.md, which holds
// the design equation (2-40); here is only linear algebra (a null space, a quartic's roots,
// Newton steps) and the package's rules (normalised data, verified cranks, roots kept once).
// A pose is theta (radians) and d = [x, y]; points are [x, y].

import * as dp from "../kernels/displacement.js";
import { LinkageInputError, finiteNumber, show } from "./core.js";

export { LinkageInputError };

// a solution farther than this (pose-set sizes) is a slider, not a crank
const FAR = 1e8;
// a root may move this far (relative) when polished onto the real line, and no farther
const DRIFT = 1e-2;

// --- complex numbers as [re, im] ------------------------------------------------------------
const cadd = (a, b) => [a[0] + b[0], a[1] + b[1]];
const csub = (a, b) => [a[0] - b[0], a[1] - b[1]];
const cmul = (a, b) => [a[0] * b[0] - a[1] * b[1], a[0] * b[1] + a[1] * b[0]];
const cscale = (a, s) => [a[0] * s, a[1] * s];
const cabs = (a) => Math.hypot(a[0], a[1]);
function cdiv(a, b) {
  // Smith's division: no overflow of |b|^2
  if (Math.abs(b[0]) >= Math.abs(b[1])) {
    const r = b[1] / b[0], den = b[0] + b[1] * r;
    return [(a[0] + a[1] * r) / den, (a[1] - a[0] * r) / den];
  }
  const r = b[0] / b[1], den = b[0] * r + b[1];
  return [(a[0] * r + a[1]) / den, (a[1] * r - a[0]) / den];
}
function csqrt(a) {
  const m = cabs(a);
  if (m === 0) return [0, 0];
  const re = Math.sqrt(0.5 * (m + Math.abs(a[0])));
  if (a[0] >= 0) return [re, a[1] / (2 * re)];
  return [Math.abs(a[1]) / (2 * re), a[1] >= 0 ? re : -re];
}

// --- poses -----------------------------------------------------------------------------------

function checkedPoses(theta, d, count) {
  if (theta == null || d == null || theta.length !== count || d.length !== count) {
    throw new LinkageInputError(`Expected ${count} poses (angles and translations of one length), ` +
      `got ${show(theta && theta.length)} angles and ${show(d && d.length)} translations`);
  }
  const th = theta.map((t, k) => finiteNumber(`theta[${k}]`, t));
  const ds = d.map((p, k) => {
    if (p == null || p.length !== 2) throw new LinkageInputError(`Expected \`d[${k}]\` to be a point [x, y], got ${show(p)}`);
    return [finiteNumber(`d[${k}][0]`, p[0]), finiteNumber(`d[${k}][1]`, p[1])];
  });
  for (let j = 0; j < count; j++) {
    for (let k = 0; k < j; k++) {
      const turn = th[j] - th[k];
      const whole = Math.abs(turn / (2 * Math.PI) - Math.round(turn / (2 * Math.PI))) < 1e-12;
      if (whole && ds[j][0] === ds[k][0] && ds[j][1] === ds[k][1]) {
        throw new LinkageInputError(`Expected distinct poses, got pose ${k + 1} and pose ${j + 1} the same`);
      }
    }
  }
  return [th, ds];
}

/** Poses moved to their centroid and divided by their size (no unit, nothing overflows). */
function normalised(d) {
  const n = d.length;
  const centre = [d.reduce((s, p) => s + p[0], 0) / n, d.reduce((s, p) => s + p[1], 0) / n];
  let size = Math.max(...d.map((p) => Math.hypot(p[0] - centre[0], p[1] - centre[1])));
  if (!(size > 0)) size = 1.0;
  return { centre, size, dn: d.map((p) => [(p[0] - centre[0]) / size, (p[1] - centre[1]) / size]) };
}

/** Rows [kx, ky, kp, kq, k1, k2, k0] of (2-40), each of unit length, from the kernel. */
function designRows(th, dn) {
  const rows = [];
  for (let j = 1; j < th.length; j++) {
    const r = dp.crank_design_row(th[0], dn[0][0], dn[0][1], th[j], dn[j][0], dn[j][1]);
    const norm = Math.hypot(...r);
    rows.push(r.map((v) => v / norm));
  }
  return rows;
}

/** The crank's largest spread of radii over the poses, in pose-set sizes (mech._task). */
export function dyadError(th, dn, z, A) {
  const radii = th.map((t, k) => {
    const c = Math.cos(t), s = Math.sin(t);
    return Math.hypot(c * z[0] - s * z[1] + dn[k][0] - A[0], s * z[0] + c * z[1] + dn[k][1] - A[1]);
  });
  const err = Math.max(...radii) - Math.min(...radii);
  return Number.isFinite(err) ? err : Infinity;
}

// --- small dense linear algebra ---------------------------------------------------------

/** Solve the square system M x = b by Gaussian elimination with partial pivoting; null if singular. */
function solve(M, b) {
  const n = b.length;
  const A = M.map((row, i) => row.slice().concat([b[i]]));
  for (let k = 0; k < n; k++) {
    let p = k;
    for (let i = k + 1; i < n; i++) if (Math.abs(A[i][k]) > Math.abs(A[p][k])) p = i;
    if (A[p][k] === 0 || !Number.isFinite(A[p][k])) return null;
    [A[k], A[p]] = [A[p], A[k]];
    for (let i = k + 1; i < n; i++) {
      const f = A[i][k] / A[k][k];
      for (let j = k; j <= n; j++) A[i][j] -= f * A[k][j];
    }
  }
  const x = new Array(n);
  for (let i = n - 1; i >= 0; i--) {
    let s = A[i][n];
    for (let j = i + 1; j < n; j++) s -= A[i][j] * x[j];
    x[i] = s / A[i][i];
  }
  return x;
}

const dot = (u, v) => u.reduce((s, x, i) => s + x * v[i], 0);

/**
 * Orthonormal bases of the row space (4 vectors) and the null space (2 vectors) of the 4x6
 * matrix M, by Gram-Schmidt applied twice, and the ratio of its smallest to largest
 * pivot (the rank test).
 */
function spaces(M) {
  const basis = [];
  const pivots = [];
  const orth = (v) => {
    let w = v.slice();
    for (let pass = 0; pass < 2; pass++) {
      for (const q of basis) {
        const c = dot(w, q);
        w = w.map((x, i) => x - c * q[i]);
      }
    }
    return w;
  };
  for (const row of M) {
    const w = orth(row);
    const n = Math.hypot(...w);
    pivots.push(n);
    basis.push(w.map((x) => x / n));
  }
  const rowSpace = basis.slice();
  const unit = (i) => Array.from({ length: 6 }, (_, j) => (i === j ? 1 : 0));
  for (let k = 0; k < 2; k++) {
    let best = null;
    for (let i = 0; i < 6; i++) {
      const w = orth(unit(i));
      const n = Math.hypot(...w);
      if (best === null || n > best[0]) best = [n, w];
    }
    basis.push(best[1].map((x) => x / best[0]));
  }
  return { rowSpace, nullSpace: basis.slice(4), rank: Math.min(...pivots) / Math.max(...pivots) };
}

// --- five poses ------------------------------------------------------------------------------

/** Coefficients [1, l, m, l^2, l m, m^2] of sign X_j X_k on the plane X = X0 + N [l, m]. */
function product(X0, N, j, k, sign) {
  const a = [X0[j], N[j][0], N[j][1]], b = [X0[k], N[k][0], N[k][1]];
  return [a[0] * b[0], a[0] * b[1] + a[1] * b[0], a[0] * b[2] + a[2] * b[0],
    a[1] * b[1], a[1] * b[2] + a[2] * b[1], a[2] * b[2]].map((v) => sign * v);
}

function constraintConics(X0, N) {
  const lin = (i) => [X0[i], N[i][0], N[i][1], 0, 0, 0];
  const add = (...terms) => terms.reduce((s, t) => s.map((v, i) => v + t[i]));
  const [x, y, p, q, s1, s2] = [0, 1, 2, 3, 4, 5];
  return [add(lin(s1), product(X0, N, x, p, -1), product(X0, N, y, q, -1)),
    add(lin(s2), product(X0, N, y, p, -1), product(X0, N, x, q, 1))];
}

// conics evaluated at complex (l, m)
function conicAt(Q, l, m) {
  const ll = cmul(l, l), lm = cmul(l, m), mm = cmul(m, m);
  return cadd(cadd(cadd([Q[0], 0], cscale(l, Q[1])), cadd(cscale(m, Q[2]), cscale(ll, Q[3]))),
    cadd(cscale(lm, Q[4]), cscale(mm, Q[5])));
}
function conicGrad(Q, l, m) {
  return [cadd(cadd([Q[1], 0], cscale(l, 2 * Q[3])), cscale(m, Q[4])),
    cadd(cadd([Q[2], 0], cscale(l, Q[4])), cscale(m, 2 * Q[5]))];
}

function rotateConic(Q, c, s) {
  const [q0, ql, qm, qll, qlm, qmm] = Q;
  return [q0, ql * c + qm * s, -ql * s + qm * c, qll * c * c + qlm * c * s + qmm * s * s,
    -2 * qll * c * s + qlm * (c * c - s * s) + 2 * qmm * c * s, qll * s * s - qlm * c * s + qmm * c * c];
}

// polynomials as coefficient arrays, lowest degree first
function pmul(f, g) {
  const out = new Array(f.length + g.length - 1).fill(0);
  f.forEach((a, i) => g.forEach((b, j) => { out[i + j] += a * b; }));
  return out;
}
function psub(f, g) {
  const n = Math.max(f.length, g.length);
  return Array.from({ length: n }, (_, i) => (f[i] || 0) - (g[i] || 0));
}
const pscale = (f, s) => f.map((v) => v * s);
const pval = (f, x) => f.reduceRight((acc, c) => cadd(cmul(acc, x), [c, 0]), [0, 0]);

/**
 * Every complex root of the real polynomial `c` (lowest degree first, leading coefficient
 * not 0), by the Aberth-Ehrlich iteration from points on a circle of the Cauchy radius.
 */
export function polyRoots(c) {
  const n = c.length - 1;
  if (n < 1) return [];
  const lead = c[n];
  const monic = c.map((v) => v / lead);
  const radius = 1 + Math.max(...monic.slice(0, n).map(Math.abs));
  const deriv = monic.slice(1).map((v, i) => v * (i + 1));
  let z = Array.from({ length: n }, (_, k) => {
    const a = (2 * Math.PI * k) / n + 0.4;
    return [0.5 * radius * Math.cos(a), 0.5 * radius * Math.sin(a)];
  });
  for (let iter = 0; iter < 500; iter++) {
    let moved = 0;
    const next = z.map((zk, k) => {
      const p = pval(monic, zk);
      if (p[0] === 0 && p[1] === 0) return zk;
      const ratio = cdiv(p, pval(deriv, zk));
      let sum = [0, 0];
      z.forEach((zj, j) => { if (j !== k) sum = cadd(sum, cdiv([1, 0], csub(zk, zj))); });
      const step = cdiv(ratio, csub([1, 0], cmul(ratio, sum)));
      moved = Math.max(moved, cabs(step) / Math.max(1, cabs(zk)));
      return csub(zk, step);
    });
    z = next;
    if (moved <= 1e-15) break; // the quartic's roots are polished by Newton's method after
  }
  return z;
}

function quadraticRoots(a, b, c) {
  // roots of a x^2 + b x + c, complex b and c, real a != 0; cancellation-free form
  const disc = csqrt(csub(cmul(b, b), cscale(c, 4 * a)));
  const sign = b[0] * disc[0] + b[1] * disc[1] >= 0 ? 1 : -1;
  const q = cscale(cadd(b, cscale(disc, sign)), -0.5);
  if (q[0] === 0 && q[1] === 0) return [[0, 0], [0, 0]];
  return [cscale(q, 1 / a), cdiv(c, q)];
}

function intersectConics(Q1, Q2) {
  let best = null;
  for (let k = 0; k < 12; k++) {
    const angle = (Math.PI * k) / 12;
    const R1 = rotateConic(Q1, Math.cos(angle), Math.sin(angle)), R2 = rotateConic(Q2, Math.cos(angle), Math.sin(angle));
    const n1 = Math.hypot(...R1.slice(3)), n2 = Math.hypot(...R2.slice(3));
    const score = Math.min(n1 > 0 ? Math.abs(R1[3]) / n1 : 0, n2 > 0 ? Math.abs(R2[3]) / n2 : 0);
    if (best === null || score > best[0]) best = [score, angle, R1, R2];
  }
  const [, angle, R1, R2] = best;
  const a1 = R1[3], b1 = [R1[1], R1[4]], c1 = [R1[0], R1[2], R1[5]];
  const a2 = R2[3], b2 = [R2[1], R2[4]], c2 = [R2[0], R2[2], R2[5]];
  const e1 = psub(pscale(c2, a1), pscale(c1, a2));
  const e2 = psub(pscale(b2, a1), pscale(b1, a2));
  const e3 = psub(pmul(b1, c2), pmul(b2, c1));
  let quartic = psub(pmul(e1, e1), pmul(e2, e3));
  const top = Math.max(...quartic.map(Math.abs));
  if (!(top > 0)) {
    throw new LinkageInputError("Expected five poses with finitely many Burmester dyads, got poses whose " +
      "two conditions share a whole curve of solutions");
  }
  quartic = quartic.map((v) => v / top);
  while (quartic.length > 1 && quartic[quartic.length - 1] === 0) quartic.pop();
  const points = [];
  for (const m of polyRoots(quartic)) {
    const cands = [];
    for (const [a, b, c] of [[a1, b1, c1], [a2, b2, c2]]) {
      const bm = pval(b, m), cm = pval(c, m);
      if (Math.abs(a) > 0) cands.push(...quadraticRoots(a, bm, cm));
      else if (bm[0] !== 0 || bm[1] !== 0) cands.push(cscale(cdiv(cm, bm), -1));
    }
    if (!cands.length) continue;
    const fit = (v) => cabs(conicAt(R1, v, m)) + cabs(conicAt(R2, v, m));
    let l = cands.reduce((u, v) => (fit(v) < fit(u) ? v : u));
    let mm = m;
    let kept = [Infinity, l, mm];
    for (let it = 0; it < 7; it++) {
      const f = [conicAt(R1, l, mm), conicAt(R2, l, mm)];
      const size = Math.max(...f.map(cabs));
      if (!Number.isFinite(size)) break;
      if (size < kept[0]) kept = [size, l, mm];
      const [g11, g12] = conicGrad(R1, l, mm), [g21, g22] = conicGrad(R2, l, mm);
      const det = csub(cmul(g11, g22), cmul(g12, g21));
      if (det[0] === 0 && det[1] === 0) break;
      const dl = cdiv(csub(cmul(g22, f[0]), cmul(g12, f[1])), det);
      const dm = cdiv(csub(cmul(g11, f[1]), cmul(g21, f[0])), det);
      l = csub(l, dl);
      mm = csub(mm, dm);
    }
    [, l, mm] = kept;
    const c = Math.cos(angle), s = Math.sin(angle);
    points.push([csub(cscale(l, c), cscale(mm, s)), cadd(cscale(l, s), cscale(mm, c))]);
  }
  return points;
}

function polish(rows, X) {
  let [x, y, p, q] = X;
  for (let it = 0; it < 8; it++) {
    const s1 = x * p + y * q, s2 = y * p - x * q;
    const F = rows.map((r) => r[0] * x + r[1] * y + r[2] * p + r[3] * q + r[4] * s1 + r[5] * s2 + r[6]);
    const J = rows.map(([kx, ky, kp, kq, k1, k2]) => [kx + k1 * p - k2 * q, ky + k1 * q + k2 * p,
      kp + k1 * x + k2 * y, kq + k1 * y - k2 * x]);
    const step = solve(J, F);
    if (step === null) break;
    const big = Math.max(1, Math.abs(x), Math.abs(y), Math.abs(p), Math.abs(q));
    if (!step.every(Number.isFinite) || Math.max(...step.map(Math.abs)) > big) break;
    x -= step[0]; y -= step[1]; p -= step[2]; q -= step[3];
    if (Math.max(...step.map(Math.abs)) <= 1e-16 * Math.max(1, Math.abs(x), Math.abs(y), Math.abs(p), Math.abs(q))) break;
  }
  return [x, y, p, q];
}

/** Which polished roots are distinct real solutions (mech._task.single_roots). */
function singleRoots(points, drifts, close) {
  const n = points.length;
  let group = Array.from({ length: n }, (_, i) => i);
  for (let i = 0; i < n; i++) {
    for (let j = 0; j < i; j++) {
      if (close(points[i], points[j])) {
        const old = group[i], now = group[j];
        group = group.map((g) => (g === old ? now : g));
      }
    }
  }
  const kept = [];
  for (const g of [...new Set(group)].sort((u, v) => u - v)) {
    const members = group.map((h, k) => [h, k]).filter(([h]) => h === g).map(([, k]) => k)
      .sort((u, v) => drifts[u] - drifts[v]);
    if (members.length === 1 || 2 * drifts[members[0]] < drifts[members[1]]) kept.push(members[0]);
  }
  return kept.sort((u, v) => u - v);
}

/**
 * The Burmester dyads of five poses (mech.planar.synthesis.burmester): every crank whose
 * circle point (body frame) has its five positions on a circle about its centre point.
 * Returns {dyads: [{circlePoint, movingPivot, centrePoint, length}], nComplex, nInfinite,
 * residual}, the dyads sorted by crank length. Throws a LinkageInputError for bad poses
 * or dependent design equations.
 */
export function burmester(theta, d, { imagTol = 1e-7, rankTol = 1e-12 } = {}) {
  const [th, ds] = checkedPoses(theta, d, 5);
  const { centre, size, dn } = normalised(ds);
  const rows = designRows(th, dn);
  const M = rows.map((r) => r.slice(0, 6));
  const { rowSpace, nullSpace, rank } = spaces(M);
  if (!(rank > rankTol)) {
    throw new LinkageInputError(`Expected five poses whose design equations (2-40) are independent, got ` +
      `a pivot ratio of ${rank} for theta = [${th.join(", ")}]`);
  }
  // the least-norm solution of M X = -k0 lies in the row space: X0 = Q y, (M Q) y = -k0
  const MQ = M.map((r) => rowSpace.map((q) => dot(r, q)));
  const yv = solve(MQ, rows.map((r) => -r[6]));
  if (yv === null) throw new LinkageInputError("Expected five poses whose design equations (2-40) are independent");
  const X0 = Array.from({ length: 6 }, (_, i) => rowSpace.reduce((s, q, k) => s + q[i] * yv[k], 0));
  const N = Array.from({ length: 6 }, (_, i) => [nullSpace[0][i], nullSpace[1][i]]);
  const [Q1, Q2] = constraintConics(X0, N);
  const roots = intersectConics(Q1, Q2);
  const found = [];
  let nComplex = 0, nInfinite = 4 - roots.length;
  for (const [l, m] of roots) {
    const Xr = X0.map((v, i) => v + N[i][0] * l[0] + N[i][1] * m[0]);
    const Xi = X0.map((_, i) => N[i][0] * l[1] + N[i][1] * m[1]);
    if (!Xr.every(Number.isFinite) || !Xi.every(Number.isFinite)) {
      nInfinite++;
      continue;
    }
    const [x, y, p, q] = polish(rows, Xr.slice(0, 4));
    const far = Math.max(Math.hypot(x, y), Math.hypot(p, q));
    if (!(far < FAR)) {
      nInfinite++;
      continue;
    }
    const error = dyadError(th, dn, [x, y], [p, q]);
    const drift = Math.max(...[x, y, p, q].map((v, i) => Math.hypot(Xr[i] - v, Xi[i]))) / Math.max(1, far);
    if (error <= imagTol && drift <= DRIFT) found.push({ z: [x, y], A: [p, q], error, drift });
    else nComplex++;
  }
  const close = (a, b) => Math.hypot(a.z[0] - b.z[0], a.z[1] - b.z[1]) + Math.hypot(a.A[0] - b.A[0], a.A[1] - b.A[1]) <=
    1e-6 * Math.max(1, Math.hypot(...a.z), Math.hypot(...a.A));
  const keep = singleRoots(found, found.map((f) => f.drift), close);
  nComplex += found.length - keep.length;
  let worst = 0;
  const dyads = keep.map((k) => {
    const { z, A, error } = found[k];
    worst = Math.max(worst, error);
    return placedDyad(th[0], ds[0], [z[0] * size, z[1] * size], [centre[0] + A[0] * size, centre[1] + A[1] * size]);
  });
  dyads.sort((u, v) => u.length - v.length);
  return { dyads, nComplex, nInfinite, residual: worst };
}

function placedDyad(theta1, d1, z, A) {
  const c = Math.cos(theta1), s = Math.sin(theta1);
  const Z1 = [c * z[0] - s * z[1] + d1[0], s * z[0] + c * z[1] + d1[1]];
  return { circlePoint: z, movingPivot: Z1, centrePoint: A, length: Math.hypot(Z1[0] - A[0], Z1[1] - A[1]) };
}

// --- four poses: Burmester's cubics, traced as curves -------------------------------------

/** The three rows of (2-40) at the circle point z as a linear system [p, q | constant] in A. */
function rowsAt(rows, z) {
  return rows.map(([kx, ky, kp, kq, k1, k2, k0]) => [kp + k1 * z[0] + k2 * z[1], kq + k1 * z[1] - k2 * z[0],
    kx * z[0] + ky * z[1] + k0]);
}

function det3(M) {
  return M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
    M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
}

/**
 * The circle-point curve of four poses and its centre points (mech.planar.synthesis
 * circle_point_curve): lines through the pole of the two poses that turn most meet the
 * cubic in two more points. Returns {phi, circlePoint, movingPivot, centrePoint, length,
 * valid} with one [k = 0, k = 1] pair per direction, and the pole (body frame).
 */
export function circlePointCurve(theta, d, { samples = 360 } = {}) {
  const [th, ds] = checkedPoses(theta, d, 4);
  const { centre, size, dn } = normalised(ds);
  let pair = null;
  for (let j = 0; j < 4; j++) {
    for (let k = j + 1; k < 4; k++) {
      const gap = Math.hypot(Math.cos(th[j]) - Math.cos(th[k]), Math.sin(th[j]) - Math.sin(th[k]));
      if (pair === null || gap > pair[0]) pair = [gap, j, k];
    }
  }
  const [gap, j, k] = pair;
  if (gap === 0) throw new LinkageInputError(`Expected poses that turn relative to each other, got theta = [${th.join(", ")}]`);
  const wj = [Math.cos(th[j]), Math.sin(th[j])], wk = [Math.cos(th[k]), Math.sin(th[k])];
  const z0 = cdiv(csub(dn[k], dn[j]), csub(wj, wk));
  const rows = designRows(th, dn);
  const out = { phi: [], circlePoint: [], movingPivot: [], centrePoint: [], length: [], valid: [],
    pole: [z0[0] * size, z0[1] * size] };
  for (let i = 0; i < samples; i++) {
    const phi = (i * Math.PI) / samples;
    const v = [Math.cos(phi), Math.sin(phi)];
    // det of the rows along z0 + r v is a cubic in r with the root r = 0 (the pole)
    const cubicAt = (r) => det3(rowsAt(rows, [z0[0] + r * v[0], z0[1] + r * v[1]]));
    // exact cubic coefficients from four samples (the entries are affine in r)
    const f0 = cubicAt(0), f1 = cubicAt(1), fm = cubicAt(-1), f2 = cubicAt(2);
    const C = cubicCoefficients(f0, f1, fm, f2);
    const [, c1, c2, cc3] = C;
    const disc = c2 * c2 - 4 * cc3 * c1;
    const pts = [], cps = [], mps = [], lens = [], oks = [];
    let rs = [NaN, NaN];
    if (disc >= 0) {
      const q = -0.5 * (c2 + (c2 >= 0 ? 1 : -1) * Math.sqrt(disc));
      rs = [q / cc3, c1 / q];
    }
    for (const r of rs) {
      let ok = Number.isFinite(r);
      const z = ok ? [z0[0] + r * v[0], z0[1] + r * v[1]] : z0;
      const sys = rowsAt(rows, z);
      const A = leastSquares2(sys);
      const zb = [z[0] * size, z[1] * size];
      const Ab = [centre[0] + A[0] * size, centre[1] + A[1] * size];
      const placed = placedDyad(th[0], ds[0], zb, Ab);
      ok = ok && Number.isFinite(placed.length) && placed.length > 0;
      if (ok) {
        const radii = th.map((t, m) => {
          const c = Math.cos(t), s = Math.sin(t);
          return Math.hypot(c * z[0] - s * z[1] + dn[m][0] - A[0], s * z[0] + c * z[1] + dn[m][1] - A[1]);
        });
        const top = Math.max(...radii);
        ok = top - Math.min(...radii) <= 1e-7 * Math.max(1, top);
      }
      pts.push(ok ? zb : [NaN, NaN]);
      cps.push(ok ? Ab : [NaN, NaN]);
      mps.push(ok ? placed.movingPivot : [NaN, NaN]);
      lens.push(ok ? placed.length : NaN);
      oks.push(ok);
    }
    out.phi.push(phi);
    out.circlePoint.push(pts);
    out.centrePoint.push(cps);
    out.movingPivot.push(mps);
    out.length.push(lens);
    out.valid.push(oks);
  }
  return out;
}

/** Coefficients [c0, c1, c2, c3] of the cubic through f(0), f(1), f(-1), f(2). */
function cubicCoefficients(f0, f1, fm, f2) {
  const c0 = f0;
  const c2 = (f1 + fm) / 2 - f0;
  const odd1 = (f1 - fm) / 2; // c1 + c3
  const c3 = ((f2 - f0 - 4 * c2) / 2 - odd1) / 3; // (c1 + 4 c3) - (c1 + c3) = 3 c3
  return [c0, odd1 - c3, c2, c3];
}

/** Least-squares solution [p, q] of three equations a p + b q + c = 0 (the rows of rowsAt). */
function leastSquares2(sys) {
  let s11 = 0, s12 = 0, s22 = 0, t1 = 0, t2 = 0;
  for (const [a, b, c] of sys) {
    s11 += a * a; s12 += a * b; s22 += b * b; t1 -= a * c; t2 -= b * c;
  }
  const det = s11 * s22 - s12 * s12;
  return [(t1 * s22 - t2 * s12) / det, (s11 * t2 - s12 * t1) / det];
}
