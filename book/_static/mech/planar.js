// The planar linkages of the book's live figures, around the generated kernels: the rules
// of mech.planar in the browser. Written by hand; the formulas are only in the kernels.
//
// What this layer adds to the kernels:
// - input checks with a readable message naming the argument and the value (never a
//   silent NaN for input the linkage cannot take);
// - scale handling: lengths divided by the power of two that brings the longest link into
//   [1/2, 1), so any finite positive lengths work and angles do not depend on the unit;
//   points are scaled back by the same power (exact);
// - the branch rule: the kernels keep one branch through change points (signed area term),
//   the kite a = d, b = c passes B = D along its branch, and inputs within 2**-46 of a dead
//   point are that dead point;
// - validity masks: `valid[i]` is false exactly where a solved field is not a number.

import * as fb from "../kernels/fourbar_position.js";
import * as gr from "../kernels/grashof.js";
import * as ta from "../kernels/transmission_angle.js";
import * as lp from "../kernels/fourbar_limit_positions.js";
import * as ic from "../kernels/instant_centres.js";
import * as sc from "../kernels/slider_crank.js";
import {
  DEAD_POINT_RTOL, LinkageInputError, finiteArray, finiteNumber, frexpExponent, fsum, keepPromise, ldexp,
  positiveLength, show,
} from "./core.js";

export { LinkageInputError };

const NAMES = ["a", "b", "c", "d"];

/**
 * Check four link lengths and scale them so that the longest lies in [1/2, 1).
 * Returns {scaled, exponent}: the lengths divided by 2**exponent (exact).
 */
export function fourbarLengths(a, b, c, d) {
  const raw = [a, b, c, d].map((x, k) => positiveLength(NAMES[k], x));
  const exponent = frexpExponent(Math.max(...raw));
  const scaled = raw.map((x) => ldexp(x, -exponent));
  const total = fsum(scaled);
  for (let k = 0; k < 4; k++) {
    if (scaled[k] >= total - scaled[k]) {
      const rest = fsum(raw.filter((_, j) => j !== k));
      throw new LinkageInputError(
        `Expected \`${NAMES[k]}\` shorter than the other three links together (${rest}), got ${raw[k]}`);
    }
  }
  return { scaled, exponent };
}

// --- the planar four-bar ----------------------------------------------------------------

/** Gaps g2, g3, g4 of scaled lengths, each 0 within rtol (a + b + c + d). */
function assemblyGaps(a, b, c, d, rtol) {
  const total = a + b + c + d;
  return fb.fourbar_assembly_gaps(a, b, c, d).map((g) => (Math.abs(g) <= rtol * total ? 0 : g));
}

/** Velocity ratios and their theta-derivatives of a change-point linkage (not a kite). */
function ratioSlopes(a, b, c, d, s, ch, T, dT, sigma) {
  const sinT = 2.0 * s * ch;
  const E = (a - d) ** 2 + 4.0 * a * d * s * s;
  const dE = 2.0 * a * d * sinT;
  const base = a * (a - d) + 2.0 * a * d * s * s;
  const out = [];
  for (const sign of [-1.0, 1.0]) {
    const M = b * b - c * c + sign * E;
    const g = (a * d * sigma * T * M + base) / E;
    const dg = (a * d * sigma * (sign * dE * T + M * dT) + a * d * sinT - g * dE) / E;
    out.push([g, dg]);
  }
  return out;
}

function changePointRatios(a, b, c, d, theta, branch, gaps, m23, m4) {
  const [g2, g3, g4] = gaps;
  const s = Math.sin(0.5 * theta), ch = Math.cos(0.5 * theta);
  const ad4 = 4.0 * a * d;
  const k = Math.sqrt((a - d) ** 2 + ad4 * s * s);
  const m = Math.abs(a - d);
  const near = (ad4 * s * s) / (k + m);
  const far = (ad4 * ch * ch) / (d + a + k);
  const f1 = b + c + k;
  const [F2, L2] = g2 === 0 ? [ad4 / (k + m), -1.0 / (k + m)] : [near + g2, 1.0 / (near + g2)];
  const [F3, L3] = g3 === 0 ? [ad4 / (k + m), -1.0 / (k + m)] : [near + g3, 1.0 / (near + g3)];
  const [F4, L4] = g4 === 0 ? [ad4 / (d + a + k), -1.0 / (d + a + k)] : [far + g4, -1.0 / (far + g4)];
  const R = Math.sqrt(f1 * F2 * F3 * F4);
  const dk = (a * d * 2.0 * s * ch) / k;
  const dlogR = 0.5 * dk * (1.0 / f1 + L2 + L3 + L4);
  const [num, dnum] = m23 ? (m4 ? [2.0, 0.0] : [2.0 * ch, -s]) : (m4 ? [2.0 * s, ch] : [2.0 * s * ch, Math.cos(theta)]);
  const T = num / R;
  const dT = dnum / R - T * dlogR;
  return ratioSlopes(a, b, c, d, s, ch, T, dT, branch);
}

/** Joints, area term and velocity ratios of the kite a = d, b = c, through B = D. */
function kitePose(a, b, gap4, m4, p, q, theta, branch) {
  const s = Math.sin(0.5 * theta), ch = Math.cos(0.5 * theta);
  const ks = 2.0 * a * s;
  const k = Math.abs(ks);
  const f1 = 2.0 * b + k;
  const f4 = gap4 + (4.0 * a * a * ch * ch) / (2.0 * a + k);
  const F4 = m4 ? (4.0 * a * a) / (2.0 * a + k) : f4;
  const RW = Math.sqrt(f1 * F4);
  const W = m4 ? ch * RW : RW;
  const Bx = a * (1.0 - 2.0 * s * s), By = a * (2.0 * s * ch);
  // C = B + u (ks + i branch W) / 2 with u = s - i ch
  const hx = ks / 2.0, hy = (branch * W) / 2.0;
  const Cx = Bx + (s * hx + ch * hy), Cy = By + (s * hy - ch * hx);
  const ux = (Cx - Bx) / b, uy = (Cy - By) / b;
  const Px = Bx + (p * ux - q * uy), Py = By + (p * uy + q * ux);
  const T = (m4 ? 1.0 : ch) / (a * RW);
  const dlogRW = m4 ? 0.0 : (-a * a * 2.0 * s * ch) / (f1 * f4);
  const dT = (m4 ? 0.0 : -0.5 * s) / (a * RW) - T * dlogRW;
  const rates = [[0.5 - branch * a * a * T, -branch * a * a * dT], [0.5 + branch * a * a * T, branch * a * a * dT]];
  return { Bx, By, Cx, Cy, Px, Py, S: ks * W, rates };
}

const POSITION = ["Bx", "By", "Cx", "Cy", "Px", "Py"];
const VELOCITY = ["omega_coupler", "omega_output", "vBx", "vBy", "vCx", "vCy", "vPx", "vPy"];
const ACCELERATION = ["alpha_coupler", "alpha_output", "aBx", "aBy", "aCx", "aCy", "aPx", "aPy"];
const ANGULAR = new Set(["omega_coupler", "omega_output", "alpha_coupler", "alpha_output"]);

/**
 * A planar revolute four-bar ABCD, A = 0 and D = (d, 0), as `mech.planar.FourBar`.
 * Options: branch (+1 or -1: C left of B->D for input angles just above 0), coupler
 * [p, q] (P = B + (p + i q) (C - B) / b) and rtol (change-point tolerance).
 */
export class FourBar {
  constructor(a, b, c, d, { branch = 1, coupler = [0.0, 0.0], rtol = 1e-12 } = {}) {
    const { scaled, exponent } = fourbarLengths(a, b, c, d);
    const [a_, b_, c_, d_] = scaled;
    if (b_ < 2 ** -1022) {
      throw new LinkageInputError(`Expected \`b\` at least 2**-1022 times the longest link, got ${b} ` +
        `with the longest ${Math.max(a, b, c, d)}`);
    }
    if (branch !== 1 && branch !== -1) throw new LinkageInputError(`Expected \`branch\` +1 or -1, got ${show(branch)}`);
    if (coupler == null || coupler.length !== 2) {
      throw new LinkageInputError(`Expected \`coupler\` to be 2 numbers, got ${show(coupler)}`);
    }
    const p = finiteNumber("coupler[0]", coupler[0]), q = finiteNumber("coupler[1]", coupler[1]);
    const r = finiteNumber("rtol", rtol);
    if (!(r >= 0)) throw new LinkageInputError(`Expected \`rtol\` >= 0, got ${show(r)}`);
    Object.assign(this, { a, b, c, d, branch, coupler: [p, q], exponent });
    this.unit = [a_, b_, c_, d_, ldexp(p, -exponent), ldexp(q, -exponent)];
    this.gaps = assemblyGaps(a_, b_, c_, d_, r);
    const zero = this.gaps.map((g) => g === 0);
    this.m23 = zero[0] || zero[1] ? 1 : 0;
    this.m4 = zero[2] ? 1 : 0;
    this.kite = zero[0] && zero[1];
    this.changePoint = this.m23 + this.m4 > 0;
    const tol = 2.0 * DEAD_POINT_RTOL * (a_ + b_ + c_ + d_);
    const closeGap = c_ > b_ ? this.gaps[0] : this.gaps[1];
    this.mayMeetDeadPoint = (this.gaps[2] !== 0 && this.gaps[2] <= tol) || (closeGap !== 0 && closeGap <= tol);
  }

  /**
   * Poses at the crank angles `theta` (a number or an array). order 0: B, C, P (as x and
   * y arrays), `assembled` (the position exists) and `valid` (every solved field is a
   * number: false also at a dead point when rates are solved, as they are infinite there);
   * 1: also the angular velocities and vB, vC, vP; 2: also the accelerations. omega and
   * alpha: the crank's rate and acceleration (numbers). strict: throw a LinkageInputError
   * naming the first angle where the linkage cannot be assembled, instead of the mask.
   */
  solve(theta, { order = 0, omega = 1.0, alpha = 0.0, strict = false } = {}) {
    const th = finiteArray("theta", theta);
    if (order !== 0 && order !== 1 && order !== 2) throw new LinkageInputError(`Expected \`order\` 0, 1 or 2, got ${show(order)}`);
    const w = finiteNumber("omega", omega), al = finiteNumber("alpha", alpha);
    const out = this._solve(th, order, w, al);
    if (strict) {
      const bad = out.assembled.indexOf(false);
      if (bad >= 0) {
        throw new LinkageInputError(`Cannot assemble FourBar(${this.a}, ${this.b}, ${this.c}, ${this.d}, ` +
          `branch=${this.branch}) at theta = ${th[bad]}: the triangle BCD does not close there`);
      }
    }
    return out;
  }

  _solve(th, order, w, al) {
    const n = th.length;
    const names = POSITION.concat(order >= 1 ? VELOCITY : [], order >= 2 ? ACCELERATION : []);
    const out = { theta: th, valid: new Array(n), assembled: new Array(n) };
    for (const name of names) out[name] = new Float64Array(n);
    const [a, b, c, d, p, q] = this.unit;
    const [g2, g3, g4] = this.gaps;
    const branch = this.branch;
    for (let i = 0; i < n; i++) {
      const t = th[i];
      let Bx, By, Cx, Cy, Px, Py, S, ratios = null;
      if (this.kite) {
        ({ Bx, By, Cx, Cy, Px, Py, S, rates: ratios } = kitePose(a, b, g4, this.m4, p, q, t, branch));
      } else if (this.changePoint) {
        [Bx, By, Cx, Cy, Px, Py, S] = fb.fourbar_position_signed(a, b, c, d, p, q, t, branch, g2, g3, g4, this.m23, this.m4);
      } else {
        [Bx, By, Cx, Cy, Px, Py, S] = fb.fourbar_position(a, b, c, d, p, q, t, branch, g2, g3, g4);
      }
      let valid = S === S;
      let rates = null;
      if (order >= 1) {
        if (this.kite || this.changePoint) {
          const [[r2, dr2], [r3, dr3]] = ratios || changePointRatios(a, b, c, d, t, branch, this.gaps, this.m23, this.m4);
          const w2 = r2 * w, w3 = r3 * w;
          rates = [w2, w3, -w * By, w * Bx, -w3 * Cy, w3 * (Cx - d), -w * By - w2 * (Py - By), w * Bx + w2 * (Px - Bx)];
          if (order >= 2) {
            const w22 = w * w;
            const a2 = r2 * al + dr2 * w22, a3 = r3 * al + dr3 * w22;
            const aBx = -w22 * Bx - al * By, aBy = al * Bx - w22 * By;
            rates.push(a2, a3, aBx, aBy,
              -w3 * w3 * (Cx - d) - a3 * Cy, a3 * (Cx - d) - w3 * w3 * Cy,
              aBx + (-w2 * w2 * (Px - Bx) - a2 * (Py - By)), aBy + (a2 * (Px - Bx) - w2 * w2 * (Py - By)));
          }
        } else {
          rates = fb.fourbar_velocity(b, d, p, q, Bx, By, Cx, Cy, S, branch, w);
          if (order >= 2) {
            rates = rates.concat(fb.fourbar_acceleration(b, d, p, q, Bx, By, Cx, Cy, S, branch, w, al, rates[0], rates[1]));
          }
        }
      }
      if (this.mayMeetDeadPoint) {
        // within DEAD_POINT_RTOL of a dead point: the dead point's pose, rates NaN there
        const tol = DEAD_POINT_RTOL * (a + b + c + d);
        const s = Math.sin(0.5 * t);
        const k = Math.sqrt((d - a) ** 2 + 4.0 * a * d * s * s);
        const nearFar = g4 !== 0 && Math.abs(k - (b + c)) <= tol;
        const nearClose = (c > b ? g2 : g3) !== 0 && Math.abs(Math.abs(b - c) - k) <= tol;
        if (nearFar || nearClose) {
          if (!valid) {
            Bx = a * Math.cos(t);
            By = a * Math.sin(t);
            const sign = nearFar || b >= c ? 1.0 : -1.0;
            Cx = Bx + (sign * b * (d - Bx)) / k;
            Cy = By + (sign * b * -By) / k;
            const ux = (Cx - Bx) / b, uy = (Cy - By) / b;
            Px = Bx + (p * ux - q * uy);
            Py = By + (p * uy + q * ux);
            valid = true;
          }
          if (rates) {
            rates = rates.slice();
            for (let j = 0; j < rates.length; j++) {
              const name = names[6 + j];
              if (!name.startsWith("vB") && !name.startsWith("aB")) rates[j] = NaN;
            }
          }
        }
      }
      out.assembled[i] = valid;
      const scale = this.exponent;
      const values = [Bx, By, Cx, Cy, Px, Py].concat(rates || []);
      for (let j = 0; j < names.length; j++) {
        const name = names[j];
        out[name][i] = ANGULAR.has(name) ? values[j] : ldexp(values[j], scale);
      }
      out.valid[i] = valid;
    }
    // valid: every solved field holds a number (false at a dead point with rates)
    return keepPromise(out);
  }

  /** The coupler curve: P at n crank angles over one turn (two turns for a linkage whose
   *  branch changes sides once per turn), with `valid` false where it cannot assemble. */
  couplerCurve(n = 720) {
    const turns = this.changePoint ? 2 : 1;
    const theta = Array.from({ length: n }, (_, i) => (2 * Math.PI * turns * i) / n);
    const pose = this.solve(theta);
    return { theta: pose.theta, x: pose.Px, y: pose.Py, valid: pose.valid };
  }

  /** Transmission angle in [0, pi/2] at crank angles `theta` (NaN where it cannot assemble). */
  transmissionAngle(theta) {
    return transmissionAngle(this.a, this.b, this.c, this.d, theta);
  }
}

// --- instant centres ---------------------------------------------------------------------

/** |W| below this times |(X, Y)| / d: the coupler pole is at infinity (crank parallel to rocker). */
const INFINITE_RTOL = 1e-12;

/**
 * The coupler's absolute instant centre P24 = AB x DC over the crank angles `theta`, as
 * mech.planar coupler_centrodes: `fixed` (the fixed centrode, in the frame) and `moving`
 * (in the coupler's frame), each {x, y} with NaN at infinity or where the linkage cannot be
 * assembled, and the masks `atInfinity` and `valid`.
 */
export function couplerCentrodes(fourbar, theta) {
  if (!(fourbar instanceof FourBar)) throw new LinkageInputError(`Expected \`fourbar\` to be a FourBar, got ${show(fourbar)}`);
  const pose = fourbar.solve(theta);
  const e = fourbar.exponent;
  // the pole's homogeneous coordinates are cubic in the lengths: on the scaled lengths
  const ds = ldexp(fourbar.d, -e), bs = ldexp(fourbar.b, -e);
  const n = pose.theta.length;
  const out = { theta: pose.theta, valid: pose.valid, atInfinity: new Array(n),
    fixed: { x: new Float64Array(n), y: new Float64Array(n) }, moving: { x: new Float64Array(n), y: new Float64Array(n) } };
  for (let i = 0; i < n; i++) {
    const [X, Y, W, U, V] = ic.fourbar_coupler_pole(ldexp(pose.Bx[i], -e), ldexp(pose.By[i], -e),
      ldexp(pose.Cx[i], -e), ldexp(pose.Cy[i], -e), ds, bs);
    const atInf = pose.valid[i] && Math.abs(W) <= (INFINITE_RTOL * Math.hypot(X, Y)) / ds;
    const finite = pose.valid[i] && !atInf;
    out.atInfinity[i] = atInf;
    out.fixed.x[i] = finite ? ldexp(X / W, e) : NaN;
    out.fixed.y[i] = finite ? ldexp(Y / W, e) : NaN;
    out.moving.x[i] = finite ? ldexp(U / W, e) : NaN;
    out.moving.y[i] = finite ? ldexp(V / W, e) : NaN;
  }
  return out;
}

// --- Grashof classification --------------------------------------------------------------

/** Classify a revolute four-bar by the Grashof conditions, ground d (as mech.planar.grashof). */
export function grashof(a, b, c, d, { rtol = 1e-12 } = {}) {
  const values = [a, b, c, d].map((x, k) => positiveLength(NAMES[k], x));
  const total = values[0] + values[1] + values[2] + values[3];
  for (let k = 0; k < 4; k++) {
    const rest = fsum(values.filter((_, j) => j !== k));
    if (values[k] >= rest) {
      throw new LinkageInputError(`Expected \`${NAMES[k]}\` < ${rest}, the sum of the other three links, got ${values[k]}`);
    }
  }
  const r = finiteNumber("rtol", rtol);
  const margins = gr.grashof_margins(...values);
  const [sab, sac, sad] = margins.map((m) => (Math.abs(m) > r * total ? Math.sign(m) : 0));
  const joints = {
    A: sad >= 0 && sab * sac >= 0,
    B: sab >= 0 && sac * sad >= 0,
    C: sad <= 0 && sab * sac <= 0,
    D: sab <= 0 && sac * sad <= 0,
  };
  const isGrashof = sab * sac * sad >= 0;
  let kind;
  if (!isGrashof) kind = "triple-rocker";
  else if (joints.A && joints.D) kind = "double-crank";
  else if (joints.A) kind = "crank-rocker";
  else if (joints.D) kind = "rocker-crank";
  else kind = "double-rocker";
  const argmin = values.indexOf(Math.min(...values)), argmax = values.indexOf(Math.max(...values));
  const productSign = Math.sign(margins[0]) * Math.sign(margins[1]) * Math.sign(margins[2]);
  return {
    grashof: isGrashof,
    changePoint: sab === 0 || sac === 0 || sad === 0,
    revolving: Object.keys(joints).filter((j) => joints[j]),
    kind,
    shortest: NAMES[argmin],
    longest: NAMES[argmax],
    margin: productSign * Math.min(...margins.map(Math.abs)) + 0,
  };
}

// --- transmission angle ------------------------------------------------------------------

/** Transmission angle gamma in [0, pi/2] at crank angles `theta`; 0 at the dead points, NaN
 *  where the linkage cannot be assembled (as mech.planar.forces transmission_angle). */
export function transmissionAngle(a, b, c, d, theta) {
  const [a_, b_, c_, d_] = fourbarLengths(a, b, c, d).scaled;
  const scalar = typeof theta === "number";
  const th = finiteArray("theta", theta);
  const gaps = assemblyGaps(a_, b_, c_, d_, 1e-12);
  const tol = DEAD_POINT_RTOL * (a_ + b_ + c_ + d_);
  const out = new Float64Array(th.length);
  for (let i = 0; i < th.length; i++) {
    let gamma = ta.fourbar_transmission(a_, b_, c_, d_, th[i])[1];
    if (gamma !== gamma) {
      const s = Math.sin(0.5 * th[i]);
      const k = Math.sqrt((d_ - a_) ** 2 + 4.0 * a_ * d_ * s * s);
      const nearFar = gaps[2] !== 0 && Math.abs(k - (b_ + c_)) <= tol;
      const nearClose = (c_ > b_ ? gaps[0] : gaps[1]) !== 0 && Math.abs(Math.abs(b_ - c_) - k) <= tol;
      if (nearFar || nearClose) gamma = 0.0;
    }
    out[i] = gamma;
  }
  return scalar ? out[0] : out;
}

/** The smallest transmission angle over the motion and the crank angle of it, [gamma, theta]. */
export function minTransmissionAngle(a, b, c, d) {
  const { scaled } = fourbarLengths(a, b, c, d);
  const [a_, b_, c_, d_] = scaled;
  for (let k = 0; k < 4; k++) {
    if (scaled[k] === 0) {
      throw new LinkageInputError(`Expected \`${NAMES[k]}\` at least 2**-1074 times the longest link ` +
        `(${Math.max(a, b, c, d)}) so that the linkage can be solved, got ${[a, b, c, d][k]}`);
    }
  }
  const kind = grashof(a_, b_, c_, d_).kind;
  if (kind === "crank-rocker" || kind === "double-crank") {
    const g0 = ta.fourbar_transmission(a_, b_, c_, d_, 0.0)[1];
    const gpi = ta.fourbar_transmission(a_, b_, c_, d_, Math.PI)[1];
    return gpi < g0 ? [gpi, Math.PI] : [g0, 0.0];
  }
  const locks = [b_ + c_, Math.abs(b_ - c_)].map((k) => ta.fourbar_crank_angle_at_diagonal(a_, d_, k));
  const finite = locks.filter((x) => x === x);
  return [0.0, finite.length ? Math.min(...finite) : NaN];
}

// --- limit positions -----------------------------------------------------------------------

/**
 * Limit positions of a crank-rocker, as mech.planar limit_positions: crank and rocker angles
 * extended and folded, swing, extreme angle and time ratio K (2-9) of this branch.
 */
export function limitPositions(a, b, c, d, { branch = 1 } = {}) {
  const { scaled } = fourbarLengths(a, b, c, d);
  for (let k = 0; k < 4; k++) {
    if (scaled[k] === 0) {
      throw new LinkageInputError(`Expected \`${NAMES[k]}\` at least 2**-1074 times the longest link ` +
        `(${Math.max(a, b, c, d)}) so that the linkage can be solved, got ${[a, b, c, d][k]}`);
    }
  }
  if (branch !== 1 && branch !== -1) throw new LinkageInputError(`Expected \`branch\` +1 or -1, got ${show(branch)}`);
  const kind = grashof(...scaled).kind;
  if (kind !== "crank-rocker") {
    throw new LinkageInputError(`Expected \`a\`, \`b\`, \`c\` and \`d\` of a crank-rocker, got a ${kind}: ` +
      `a=${a}, b=${b}, c=${c}, d=${d}`);
  }
  const [thE, thF, psE, psF, swing, thS] = lp.fourbar_limit_positions(...scaled);
  const extreme = Math.abs(thS);
  return {
    thetaExtended: branch * thE,
    thetaFolded: branch * thF,
    psiExtended: branch * psE,
    psiFolded: branch * psF,
    swing,
    extremeAngle: extreme,
    timeRatio: lp.quick_return_time_ratio(extreme),
  };
}

// --- slider-crank --------------------------------------------------------------------------

const SC_FIELDS = ["x", "phi", "Bx", "By", "Cx", "Cy", "omega_coupler", "v", "vBx", "vBy", "alpha_coupler", "acc", "aBx", "aBy"];
const SC_COUNT = [6, 10, 14];
const SC_LINEAR = new Set(["x", "Bx", "By", "Cx", "Cy", "v", "vBx", "vBy", "acc", "aBx", "aBy"]);
const SC_SOLVED_RATES = ["omega_coupler", "v", "alpha_coupler", "acc"];
const SC_BY_CRANK = new Set(["Bx", "By", "vBx", "vBy", "aBx", "aBy"]);

/**
 * A slider-crank: crank a about A = 0, rod b, slider pin on the line y = e, as
 * `mech.planar.SliderCrank`. branch +1 puts C to the right of B (cos(phi) > 0).
 */
export class SliderCrank {
  constructor(a, b, e = 0.0, { branch = 1 } = {}) {
    this.a = positiveLength("a", a);
    this.b = positiveLength("b", b);
    this.e = finiteNumber("e", e);
    if (branch !== 1 && branch !== -1) throw new LinkageInputError(`Expected \`branch\` +1 or -1, got ${show(branch)}`);
    this.branch = branch;
    // lengths divided by 2**k, 2**k <= the longest < 2**(k + 1) (exact): formulas of order one
    const biggest = Math.max(this.a, this.b, Math.abs(this.e));
    this.exponent = frexpExponent(biggest) - 1;
    this.unit = [this.a, this.b, this.e].map((x) => ldexp(x, -this.exponent));
    const [a_, b_, e_] = this.unit;
    const tol = DEAD_POINT_RTOL * (a_ + b_ + Math.abs(e_));
    this.mayMeetDeadPoint = a_ + Math.abs(e_) >= b_ - 2.0 * tol;
    if (b_ < Math.abs(e_) - a_ - tol) {
      throw new LinkageInputError(`Expected \`b\` >= |e| - a = ${Math.abs(this.e) - this.a} so that the rod ` +
        `reaches the guide, got ${this.b}`);
    }
  }

  /** True if the crank turns fully, b >= a + |e|. */
  get crankTurns() {
    const [a_, b_, e_] = this.unit;
    return b_ >= a_ + Math.abs(e_);
  }

  /**
   * Slider and rod at crank angles `theta`: x, phi, B, C (x and y arrays), `assembled` and
   * `valid` (false also at a dead point when rates are solved); order 1 adds
   * omega_coupler, v, vB; order 2 alpha_coupler, acc, aB. strict: throw a LinkageInputError
   * naming the first angle where the rod cannot reach the guide.
   */
  solve(theta, { order = 0, omega = 1.0, alpha = 0.0, strict = false } = {}) {
    const th = finiteArray("theta", theta);
    if (order !== 0 && order !== 1 && order !== 2) throw new LinkageInputError(`Expected \`order\` 0, 1 or 2, got ${show(order)}`);
    const w = finiteNumber("omega", omega), al = finiteNumber("alpha", alpha);
    const [a_, b_, e_] = this.unit;
    const names = SC_FIELDS.slice(0, SC_COUNT[order]);
    const out = { theta: th, valid: new Array(th.length), assembled: new Array(th.length) };
    for (const name of names) out[name] = new Float64Array(th.length);
    const tol = DEAD_POINT_RTOL * (a_ + b_ + Math.abs(e_));
    for (let i = 0; i < th.length; i++) {
      const t = th[i];
      let values = sc.slider_crank_position(a_, b_, e_, t, this.branch);
      if (order >= 1) values = values.concat(sc.slider_crank_velocity(a_, b_, e_, t, this.branch, w));
      if (order >= 2) values = values.concat(sc.slider_crank_acceleration(a_, b_, e_, t, this.branch, w, al));
      let assembled = values[0] === values[0];
      let dead = false;
      if (this.mayMeetDeadPoint) {
        const s = a_ * Math.sin(t) - e_;
        dead = Math.abs(Math.abs(s) - b_) <= tol;
        if (dead && !assembled) {
          // within DEAD_POINT_RTOL of a dead point: the dead point, C below B
          values[0] = a_ * Math.cos(t);
          values[1] = -Math.sign(s) * (Math.PI / 2);
          values[4] = values[0];
          values[5] = e_;
          assembled = true;
        }
      }
      let valid = assembled;
      for (let j = 0; j < names.length; j++) {
        const name = names[j];
        let v = values[j];
        if (!assembled && !SC_BY_CRANK.has(name)) v = NaN;
        if (dead && SC_SOLVED_RATES.includes(name)) v = NaN;
        v = SC_LINEAR.has(name) ? ldexp(v, this.exponent) : v;
        // with rates: a rate that is not a number (a dead point) makes the pose not valid
        if (order >= 1 && SC_SOLVED_RATES.includes(name) && !Number.isFinite(v)) {
          valid = false;
        }
        out[name][i] = v;
      }
      if (order >= 1 && !valid) for (const name of SC_SOLVED_RATES.slice(0, 2 * order)) out[name][i] = NaN;
      out.assembled[i] = assembled;
      out.valid[i] = valid;
    }
    keepPromise(out);
    if (strict) {
      const bad = out.assembled.indexOf(false);
      if (bad >= 0) {
        throw new LinkageInputError(`Cannot assemble SliderCrank(${this.a}, ${this.b}, ${this.e}, branch=${this.branch}) ` +
          `at theta = ${th[bad]}: the rod cannot reach the guide there (|a sin(theta) - e| > b)`);
      }
    }
    return out;
  }
}
