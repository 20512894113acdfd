// Rigid-body guidance through two or three poses, for the book's live design pages: the
// displacement pole and the crank (dyad) of a chosen circle point or centre point, as
// mech.planar.synthesis does. Written by hand around the generated kernels of
// derivations/planar/displacement.md. A pose is [theta, [x, y]]: the body point z is at
// exp(i theta) z + d; points are [x, y].

import * as dp from "../kernels/displacement.js";
import { LinkageInputError, finiteNumber, show } from "./core.js";

export { LinkageInputError };

function roundHalfEven(x) {
  const r = Math.round(x);
  return Math.abs(x % 1) === 0.5 && r % 2 !== 0 ? r - 1 : r;
}

/** theta_i - theta_1 less its nearest whole number of turns. */
function wrappedTurn(t1, ti) {
  const turn = ti - t1;
  return turn - 2 * Math.PI * roundHalfEven(turn / (2 * Math.PI));
}

function point(name, value) {
  if (value == null || value.length !== 2) throw new LinkageInputError(`Expected \`${name}\` to be a point [x, y], got ${show(value)}`);
  return [finiteNumber(`${name}[0]`, value[0]), finiteNumber(`${name}[1]`, value[1])];
}

function poses(theta, d, counts) {
  if (theta == null || d == null || theta.length !== d.length || !counts.includes(theta.length)) {
    throw new LinkageInputError(`Expected ${counts.join(" or ")} poses (angles and translations of one length), ` +
      `got ${show(theta && theta.length)} angles and ${show(d && d.length)} translations`);
  }
  return [theta.map((t, k) => finiteNumber(`theta[${k}]`, t)), d.map((p, k) => point(`d[${k}]`, p))];
}

/** The pole of the displacement from pose 1 to pose i (mech.planar.synthesis.pole). */
export function pole(theta1, d1, thetaI, dI) {
  const t1 = finiteNumber("theta_1", theta1), ti = finiteNumber("theta_i", thetaI);
  const p1 = point("d_1", d1), pi = point("d_i", dI);
  const turn = wrappedTurn(t1, ti);
  if (turn === 0) {
    throw new LinkageInputError("Expected `theta_1` and `theta_i` of poses that turn relative to each other " +
      `(a pure translation has its pole at infinity), got theta_1=${t1}, theta_i=${ti}`);
  }
  let [qx, qy] = dp.displacement_pole(0.0, p1[0], p1[1], turn, pi[0], pi[1]);
  // beyond the float range the pole is infinite along the bisector; 0 * inf is the midpoint's
  if (qx !== qx) qx = p1[0] / 2 + pi[0] / 2;
  if (qy !== qy) qy = p1[1] / 2 + pi[1] / 2;
  return [qx, qy];
}

const rotate = (t, [x, y]) => [Math.cos(t) * x - Math.sin(t) * y, Math.sin(t) * x + Math.cos(t) * y];

/** Circumcentre of three points, on the differences scaled by their spread (no overflow). */
function circumcentre(w) {
  const rel = w.map(([x, y]) => [x - w[0][0], y - w[0][1]]);
  let scale = Math.max(...rel.map(([x, y]) => Math.hypot(x, y)));
  if (!(scale > 0)) scale = 1.0;
  const [cx, cy] = dp.circumcentre(0.0, 0.0, rel[1][0] / scale, rel[1][1] / scale, rel[2][0] / scale, rel[2][1] / scale);
  return [w[0][0] + scale * cx, w[0][1] + scale * cy];
}

function bisectorPoint(w, along) {
  const dx = w[1][0] - w[0][0], dy = w[1][1] - w[0][1];
  return [0.5 * (w[0][0] + w[1][0]) - along * dy, 0.5 * (w[0][1] + w[1][1]) + along * dx];
}

function checkedDyad(z, A, Z1, name, value) {
  const length = Math.hypot(Z1[0] - A[0], Z1[1] - A[1]);
  if (!Number.isFinite(length) || length === 0) {
    throw new LinkageInputError(`Expected \`${name}\` whose positions fix a crank of finite, non-zero length ` +
      `(not a pole, not on a line through three positions), got ${JSON.stringify(value)}`);
  }
  return { circlePoint: z, centrePoint: A, circlePoint1: Z1, length };
}

/** The crank through two or three poses with a chosen circle point (moving pivot, body frame). */
export function dyadForCirclePoint(theta, d, circlePoint, { along = 0.0 } = {}) {
  const [th, ds] = poses(theta, d, [2, 3]);
  const z = point("circle_point", circlePoint);
  const a = finiteNumber("along", along);
  const w = th.map((t, k) => {
    const r = rotate(t, z);
    return [r[0] + ds[k][0], r[1] + ds[k][1]];
  });
  const A = th.length === 3 ? circumcentre(w) : bisectorPoint(w, a);
  return checkedDyad(z, A, w[0], "circle_point", z);
}

/** The crank through two or three poses with a chosen centre point (fixed pivot, ground frame). */
export function dyadForCentrePoint(theta, d, centrePoint, { along = 0.0 } = {}) {
  const [th, ds] = poses(theta, d, [2, 3]);
  const A = point("centre_point", centrePoint);
  const a = finiteNumber("along", along);
  const seen = th.map((t, k) => rotate(-t, [A[0] - ds[k][0], A[1] - ds[k][1]]));
  const z = th.length === 3 ? circumcentre(seen) : bisectorPoint(seen, a);
  const r = rotate(th[0], z);
  return checkedDyad(z, A, [r[0] + ds[0][0], r[1] + ds[0][1]], "centre_point", A);
}
