// The spherical four-bar of the book's live figures, around the generated kernels: the
// rules of mech.spherical in the browser (arc checks, branch, assembly range, rate scaling,
// frame). Written by hand; the formulas are only in the kernels.

import * as sf from "../kernels/spherical_fourbar.js";
import * as st from "../kernels/spherical_types.js";
import { LinkageInputError, finiteArray, finiteNumber, keepPromise, number, show } from "./core.js";

export { LinkageInputError };

const NAMES = ["a", "b", "c", "d"];

/** `value` after checking that it is an arc in (0, pi). */
export function arc(name, value) {
  const x = number(name, value);
  if (!(x > 0 && x < Math.PI)) throw new LinkageInputError(`Expected \`${name}\` in (0, pi), got ${show(x)}`);
  return x;
}

function rotation(frame, tol = 1e-9) {
  if (frame == null || frame.length !== 3 || frame.some((row) => row == null || row.length !== 3)) {
    throw new LinkageInputError(`Expected \`frame\` to be a 3x3 rotation matrix, got ${show(frame)}`);
  }
  const R = frame.map((row, i) => row.map((v, j) => finiteNumber(`frame[${i}][${j}]`, v)));
  let worst = 0;
  for (let i = 0; i < 3; i++) {
    for (let j = 0; j < 3; j++) {
      worst = Math.max(worst, Math.abs(R[i][j]) - 1 > tol ? Infinity : 0);
      const dot = R[0][i] * R[0][j] + R[1][i] * R[1][j] + R[2][i] * R[2][j];
      worst = Math.max(worst, Math.abs(dot - (i === j ? 1 : 0)));
    }
  }
  const det = R[0][0] * (R[1][1] * R[2][2] - R[1][2] * R[2][1]) - R[0][1] * (R[1][0] * R[2][2] - R[1][2] * R[2][0])
    + R[0][2] * (R[1][0] * R[2][1] - R[1][1] * R[2][0]);
  if (worst > tol || det <= 0) {
    throw new LinkageInputError("Expected `frame` to be a proper rotation (R.T @ R = I, det R = +1), got " + JSON.stringify(R));
  }
  return R;
}

const SPH_VECTORS = [["B", "C", "P"], ["w_input", "w_coupler", "w_output", "vB", "vC", "vP"],
  ["dw_input", "dw_coupler", "dw_output", "aB", "aC", "aP"]];
const SPH_SCALARS = [["psi"], ["omega_output"], ["alpha_output"]];

/**
 * A spherical four-bar (arcs a, b, c, d in (0, pi)), as `mech.spherical.SphericalFourBar`.
 * Options: branch (+1 where det[B, D, C] > 0), coupler [r, gamma], frame (a rotation, rows
 * of a 3x3 array, applied to every vector), rtol (change-point tolerance).
 */
export class SphericalFourBar {
  constructor(a, b, c, d, { branch = 1, coupler = [0.0, 0.0], frame = null, rtol = 1e-12 } = {}) {
    [this.a, this.b, this.c, this.d] = [a, b, c, d].map((x, k) => arc(NAMES[k], x));
    const r = finiteNumber("rtol", rtol);
    if (!(r >= 0 && r < 1e-3)) throw new LinkageInputError(`Expected \`rtol\` in [0, 1e-3), got ${show(r)}`);
    const g0 = Math.abs(this.a - this.d);
    const gpi = Math.min(this.a + this.d, 2 * Math.PI - this.a - this.d);
    const tol = r * (this.a + this.b + this.c + this.d);
    const gaps = [g0 - (this.c - this.b), g0 - (this.b - this.c), this.b + this.c - gpi, 2 * Math.PI - this.b - this.c - gpi];
    this.changePoint = gaps.some((g) => Math.abs(g) <= tol);
    if (branch !== 1 && branch !== -1) throw new LinkageInputError(`Expected \`branch\` +1 or -1, got ${show(branch)}`);
    this.branch = branch;
    if (coupler == null || coupler.length !== 2) {
      throw new LinkageInputError(`Expected \`coupler\` to be 2 numbers, got ${show(coupler)}`);
    }
    this.coupler = [finiteNumber("coupler[0]", coupler[0]), finiteNumber("coupler[1]", coupler[1])];
    this.frame = frame == null ? null : rotation(frame);
  }

  /** The input angles where the linkage assembles: {fullTurn, intervals: [[lo, hi], ...]}. */
  assemblyRange() {
    const { a, b, c, d } = this;
    const gLo = Math.abs(a - d), gHi = Math.min(a + d, 2 * Math.PI - a - d);
    const wLo = Math.abs(b - c), wHi = Math.min(b + c, 2 * Math.PI - b - c);
    const lo = Math.max(gLo, wLo), hi = Math.min(gHi, wHi);
    if (lo > hi) return { fullTurn: false, intervals: [] };
    const tLo = wLo <= gLo ? 0.0 : sf.spherical_fourbar_limit_theta(a, d, lo);
    const tHi = wHi >= gHi ? Math.PI : sf.spherical_fourbar_limit_theta(a, d, hi);
    if (tLo === 0.0 && tHi === Math.PI) return { fullTurn: true, intervals: [] };
    if (tLo === 0.0) return { fullTurn: false, intervals: [[-tHi, tHi]] };
    if (tHi === Math.PI) return { fullTurn: false, intervals: [[tLo, 2 * Math.PI - tLo]] };
    return { fullTurn: false, intervals: [[-tHi, -tLo], [tLo, tHi]] };
  }

  /**
   * Poses at the input angles `theta`: psi, B, C, P (each an array of [x, y, z]) and
   * `valid` (every solved field a number: false where it cannot assemble and, with
   * rates, at a limit position, where they are infinite); order 1 adds omega_output and the angular velocities and velocities, order 2
   * the accelerations. A change-point linkage (its branches meet at theta = 0 or pi) is
   * solved by the Python package's half-angle form, not yet here: it raises.
   */
  solve(theta, { order = 0, omega = 1.0, alpha = 0.0 } = {}) {
    if (this.changePoint) {
      throw new LinkageInputError("A spherical four-bar whose branches meet (a change point, s + l = p + q) " +
        "is not solved in the page yet; the Python package solves it (mech.spherical.SphericalFourBar)");
    }
    const th = finiteArray("theta", theta);
    if (order !== 0 && order !== 1 && order !== 2) throw new LinkageInputError(`Expected \`order\` 0, 1 or 2, got ${show(order)}`);
    const w0 = finiteNumber("omega", omega), al0 = finiteNumber("alpha", alpha);
    // rates solved for omega / m and alpha / m^2, then scaled back: no overflow inside
    let m = order === 1 ? Math.abs(w0) : Math.max(Math.abs(w0), Math.sqrt(Math.abs(al0)));
    if (!(m > 0)) m = 1.0;
    const w = w0 / m, al = al0 / m / m;
    const { a, b, c, d } = this;
    const [r, gamma] = this.coupler;
    const out = { theta: th, valid: new Array(th.length) };
    const vectors = SPH_VECTORS.slice(0, order + 1).flat();
    const scalars = SPH_SCALARS.slice(0, order + 1).flat();
    for (const name of vectors) out[name] = [];
    for (const name of scalars) out[name] = new Float64Array(th.length);
    const R = this.frame;
    const place = (x, y, z) => (R ? [R[0][0] * x + R[0][1] * y + R[0][2] * z, R[1][0] * x + R[1][1] * y + R[1][2] * z,
      R[2][0] * x + R[2][1] * y + R[2][2] * z] : [x, y, z]);
    for (let i = 0; i < th.length; i++) {
      const pos = sf.spherical_fourbar_position(a, b, c, d, r, gamma, th[i], -this.branch);
      out.psi[i] = pos[0];
      // valid: every solved field holds a number (false at a limit position with rates)
      const valid = pos[0] === pos[0];
      out.B.push(place(pos[1], pos[2], pos[3]));
      out.C.push(place(pos[4], pos[5], pos[6]));
      out.P.push(place(pos[7], pos[8], pos[9]));
      out.valid[i] = valid;
      if (order < 1) continue;
      const points = pos.slice(1);
      const vel = sf.spherical_fourbar_velocity(d, ...points, w);
      out.omega_output[i] = vel[0] * m;
      const v = (k) => place(vel[k] * m, vel[k + 1] * m, vel[k + 2] * m);
      out.w_input.push(place(0, 0, w * m));
      out.w_coupler.push(v(2));
      out.w_output.push(v(5));
      out.vB.push(v(8));
      out.vC.push(v(11));
      out.vP.push(v(14));
      if (order < 2) continue;
      const acc = sf.spherical_fourbar_acceleration(d, ...points, w, al, vel[0], vel[1]);
      const mm = (x) => x * m * m;
      out.alpha_output[i] = mm(acc[0]);
      const u = (k) => place(mm(acc[k]), mm(acc[k + 1]), mm(acc[k + 2]));
      out.dw_input.push(place(0, 0, mm(al)));
      out.dw_coupler.push(u(1));
      out.dw_output.push(u(4));
      out.aB.push(u(7));
      out.aC.push(u(10));
      out.aP.push(u(13));
    }
    return keepPromise(out);
  }

  /** The coupler point over the assembly range on this branch: {theta, P}, n angles over
   *  the full turn or spread over the intervals with a NaN row between intervals. */
  couplerCurve(n = 721) {
    const rng = this.assemblyRange();
    let theta = [];
    if (rng.fullTurn) {
      theta = Array.from({ length: n }, (_, i) => -Math.PI + (2 * Math.PI * i) / (n - 1));
    } else {
      const total = rng.intervals.reduce((acc, [s, e]) => acc + (e - s), 0) || 1.0;
      rng.intervals.forEach(([start, end], k) => {
        const count = Math.max(2, Math.round((n * (end - start)) / total));
        const inset = 1e-10 * (end - start);
        if (k > 0) theta.push(NaN);
        for (let j = 0; j < count; j++) theta.push(start + inset + ((end - inset - (start + inset)) * j) / (count - 1));
      });
    }
    const ok = theta.filter((t) => t === t);
    const pose = ok.length ? this.solve(ok) : { P: [] };
    let j = 0;
    const P = theta.map((t) => (t === t ? pose.P[j++] : [NaN, NaN, NaN]));
    return { theta, P };
  }
}

// --- classification ----------------------------------------------------------------------

/** The acute normal form of the arcs by antipode moves (as mech.spherical antipode_reduction). */
function reducedArcs(arcs) {
  const target = arcs.map((x) => (x <= Math.PI / 2 ? x : Math.PI - x));
  const obtuse = arcs.filter((x) => x > Math.PI / 2).length;
  if (obtuse % 2) {
    const keep = target.indexOf(Math.max(...target)); // nearest to pi/2
    target[keep] = Math.PI - target[keep];
  }
  return target;
}

/**
 * Classify a spherical four-bar by its fully rotatable joints, ground d (as
 * mech.spherical.classify): {kind, grashof, changePoint, revolving}. Throws a
 * LinkageInputError when it cannot be assembled at any input angle.
 */
export function classify(a, b, c, d, { tol = 1e-12 } = {}) {
  const arcs = [a, b, c, d].map((x, k) => arc(NAMES[k], x));
  const reduced = reducedArcs(arcs);
  const total = reduced[0] + reduced[1] + reduced[2] + reduced[3];
  for (let k = 0; k < 4; k++) {
    if (reduced[k] >= total - reduced[k]) {
      throw new LinkageInputError(`Expected every arc below the sum of the other three after the antipode ` +
        `reduction, got reduced arc \`${NAMES[k]}\` = ${reduced[k]} >= ${total - reduced[k]}: the linkage cannot be assembled`);
    }
  }
  const t = finiteNumber("tol", tol);
  const [ab, ac, ad, n] = st.spherical_type_slacks(...arcs).map((s) => (Math.abs(s) <= t ? 0 : Math.sign(s)));
  const joints = {
    A: ab * ac >= 0 && ad * n >= 0,
    B: ac * ad >= 0 && ab * n >= 0,
    C: ab * ac <= 0 && ad * n <= 0,
    D: ac * ad <= 0 && ab * n <= 0,
  };
  const revolving = Object.keys(joints).filter((j) => joints[j]);
  let kind;
  if (!revolving.length) kind = "triple-rocker";
  else if (joints.A && joints.D) kind = "double-crank";
  else if (joints.A) kind = "crank-rocker";
  else if (joints.D) kind = "rocker-crank";
  else kind = "double-rocker";
  return { kind, grashof: revolving.length > 0, changePoint: [ab, ac, ad, n].includes(0), revolving };
}
