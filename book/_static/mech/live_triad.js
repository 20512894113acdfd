// The live Stephenson-3 spherical six-bar (figures/live_chains.py, `stephenson3`): its
// guided link CGH hangs from the crank ABE by BC and EG and from the ground pivot D by DH,
// a triad that no dyad solves. As mech.spherical.SphericalStephenson3 does, the page moves
// the link from the assembled pose in input steps of at most 0.05 rad, correcting its
// rotation with Newton's method on the three arc conditions (a 3 x 3 solve per step), and
// keeps the assembly: where the determinant of the conditions would change sign (a dead
// point) every later input is left unassembled, never moved to the other assembly.
// Written by hand: a thin solver of the loop closure (no kernel has the triad's closure).

import { LinkageInputError } from "./core.js";
import { fieldHelpers, fieldState, grid3, where3 } from "./live_chains.js";

const DEG = Math.PI / 180;
const STEP = 0.05;
const CLOSE = 1e-15;
const deg = (x) => (x * 180 / Math.PI).toFixed(1).replace("-", "\u2212") + "\u00b0";
const dot = (u, v) => u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
const cross = (u, v) => [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
const apply = (Q, v) => [0, 1, 2].map((i) => Q[i][0] * v[0] + Q[i][1] * v[1] + Q[i][2] * v[2]);
const matmul = (R, Q) => [0, 1, 2].map((i) => [0, 1, 2].map((j) => R[i][0] * Q[0][j] + R[i][1] * Q[1][j] + R[i][2] * Q[2][j]));
const det = (J) => dot(J[0], cross(J[1], J[2]));

/** The rotation exp([w]x) (Rodrigues). */
function expmap(w) {
  const t = Math.hypot(...w);
  if (t === 0) return [[1, 0, 0], [0, 1, 0], [0, 0, 1]];
  const [x, y, z] = w.map((v) => v / t), c = Math.cos(t), s = Math.sin(t), k = 1 - c;
  return [[c + x * x * k, x * y * k - z * s, x * z * k + y * s],
    [y * x * k + z * s, c + y * y * k, y * z * k - x * s],
    [z * x * k - y * s, z * y * k + x * s, c + z * z * k]];
}

/** x with J x = b (Cramer's rule; J is 3 x 3 and not singular along an assembly). */
function solve3(J, b) {
  const D = det(J), cols = [0, 1, 2];
  return cols.map((k) => det(J.map((row, i) => row.map((v, j) => (j === k ? b[i] : v)))) / D);
}

export function stephenson3(div, d, api, spec) {
  const angular = () => true;
  const state = fieldState(spec, angular);
  const theta = Float64Array.from(spec.theta);
  const fig = { state, handleSize: 26, handles: [] };
  fieldHelpers(fig, spec, angular);
  const grid = grid3(d), idx = (name) => d.names.indexOf(name);
  const p = spec.points, A = p.A, D = p.D;
  // the crank's points at input theta: B and E of the given pose turned about A by theta - theta0
  const turned = (q, c, s) => { const k = dot(A, q) * (1 - c), n = cross(A, q); return [0, 1, 2].map((i) => q[i] * c + n[i] * s + A[i] * k); };
  const crank = (t) => { const c = Math.cos(t - spec.theta0), s = Math.sin(t - spec.theta0); return [turned(p.B, c, s), turned(p.E, c, s)]; };
  let cosines = null, sign = 0, frames = null, run = null;
  const residual = (Q, B, E) => [dot(B, apply(Q, p.C)) - cosines[0], dot(E, apply(Q, p.G)) - cosines[1], dot(D, apply(Q, p.H)) - cosines[2]];
  const jacobian = (Q, B, E) => [cross(apply(Q, p.C), B), cross(apply(Q, p.G), E), cross(apply(Q, p.H), D)];
  function correct(Q, t) {
    const [B, E] = crank(t);
    for (let k = 0; k < 16; k++) {
      const r = residual(Q, B, E);
      if (Math.max(...r.map(Math.abs)) <= CLOSE) break;
      const w = solve3(jacobian(Q, B, E), r.map((v) => -v)), step = Math.hypot(...w);
      if (!(step <= 0.3)) return null;
      Q = matmul(expmap(w), Q);
      if (step < 1e-15) break;
    }
    if (!(Math.max(...residual(Q, B, E).map(Math.abs)) <= 1e-12)) return null;
    return Math.sign(det(jacobian(Q, B, E))) === sign ? Q : null;
  }
  /** The rotations of CGH at the inputs `targets`, marched in order from (Q0, t0). */
  function march(Q, t, targets) {
    return targets.map((target) => {
      while (Q && t !== target) {
        let h = Math.max(-STEP, Math.min(STEP, target - t)), next = null;
        const least = Math.min(1e-7, Math.abs(target - t)); // the last step may be a rounding's worth
        while (!next && Math.abs(h) >= least) { next = correct(Q, t + h); if (!next) h /= 2; }
        if (next) { Q = next; t = Math.abs(target - t - h) < 1e-15 ? target : t + h; } else Q = null;
      }
      return Q;
    });
  }
  fig.compute = () => {
    cosines = ["BC", "EG", "DH"].map((k) => {
      const v = state[k];
      if (!(v > 0 && v < Math.PI)) throw new LinkageInputError(`Expected \`${k}\` an arc between 0 and 180 degrees, got ${v / DEG}`);
      return Math.cos(v);
    });
    // the given pose, corrected onto the new arcs at its own input
    const I = [[1, 0, 0], [0, 1, 0], [0, 0, 1]], [B0, E0] = crank(spec.theta0);
    sign = Math.sign(det(jacobian(I, B0, E0)));
    const Q0 = correct(I, spec.theta0);
    if (!Q0) throw new LinkageInputError(`Expected arcs BC, EG, DH near the assembled pose's, got ${["BC", "EG", "DH"].map((k) => (state[k] / DEG).toFixed(2)).join(", ")} degrees (the guided link does not reach them there)`);
    const order = Array.from(theta.keys()).sort((i, j) => theta[i] - theta[j]);
    const up = order.filter((i) => theta[i] >= spec.theta0), down = order.filter((i) => theta[i] < spec.theta0).reverse();
    frames = new Array(theta.length);
    march(Q0, spec.theta0, up.map((i) => theta[i])).forEach((Q, k) => { frames[up[k]] = Q; });
    march(Q0, spec.theta0, down.map((i) => theta[i])).forEach((Q, k) => { frames[down[k]] = Q; });
    const turn = Array.from({ length: spec.curve }, (_, i) => spec.theta0 + (2 * Math.PI * i) / spec.curve);
    run = march(Q0, spec.theta0, turn);
    const put = (name, list, at) => { if (idx(name) >= 0 && d.P[idx(name)].length !== 3) d.P[idx(name)] = list.flatMap(at); };
    const crankAt = (t, k) => crank(t)[k];
    put("B", frames, (Q, f) => grid(crankAt(theta[f], 0)));
    put("E", frames, (Q, f) => grid(crankAt(theta[f], 1)));
    ["C", "G", "H", "P"].forEach((name) => { if (p[name]) put(name, frames, (Q) => grid(Q && apply(Q, p[name]))); });
    d.curves = d.trace.map((i) => (p[d.names[i]] ? run.map((Q) => (Q ? grid(apply(Q, p[d.names[i]])) : null)) : null));
  };
  fig.message = (f) => (!frames || frames[f] ? "" : `At \u03b8 = ${deg(theta[f])} this Stephenson-3 cannot be reached on ` +
    "its assembly: the guided link meets a dead point before it.");
  fig.readout = () => ({ kind: "Stephenson-3: the guided link CGH hangs from the crank by BC and EG and from D by DH",
    limits: `assembled at ${frames.filter((Q) => Q).length} of ${theta.length} frames`,
    transmission: "arcs " + ["BC", "EG", "DH"].map((k) => `${k} ${deg(state[k])}`).join(", ") });
  fig.where = where3(d, api);
  fig.fromDrag = () => null;
  return fig;
}
