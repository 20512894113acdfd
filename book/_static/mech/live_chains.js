// Live figures of linkages built step by step (figures/live_chains.py writes their
// descriptions): any planar Linkage of ground, crank, point, RRR, RRP and RPR steps (the
// six-bars, the shapers, Jansen's leg), any spherical linkage of a crank, points and RRR
// dyads (the spherical six-bars), the RSSR and the open chain of example 2-25. Each returns
// the figure object that live.js wires to the player. Written by hand: a thin solver of the
// loop closure, group after group; every formula is a generated kernel.

import * as assur from "../kernels/assur_groups.js";
import * as sph from "../kernels/spherical_linkage.js";
import * as rssrK from "../kernels/rssr.js";
import * as abc from "../kernels/one_equation.js";
import * as chainK from "../kernels/open_chains.js";
import * as calc from "../kernels/spherical_calculus.js";
import { LinkageInputError, unproject } from "./core.js";

export { LinkageInputError };

const DEG = Math.PI / 180;
const deg = (x) => (x * 180 / Math.PI).toFixed(1).replace("-", "\u2212") + "\u00b0";
const fold = (mu) => Math.min(mu, Math.PI - mu);
const dot3 = (u, v) => u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
const cross3 = (u, v) => [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
const angle3 = (u, v) => Math.atan2(Math.hypot(...cross3(u, v)), dot3(u, v));
const tangent = (at, to) => { const k = dot3(at, to); return [to[0] - k * at[0], to[1] - k * at[1], to[2] - k * at[2]]; };

function positive(label, v) {
  if (!(Number.isFinite(v) && v > 0)) throw new LinkageInputError(`Expected \`${label}\` a positive length, got ${v}`);
  return v;
}

function turnWords(count, n) {
  return [count === n ? "the crank turns fully" : "the crank does not turn fully", `assembles at ${count} of ${n} crank angles`];
}

/** The fields of a description as state values (lengths; arcs and angles in radians). */
export function fieldState(spec, angular) {
  const state = { branch: spec.branch };
  spec.fields.forEach(([k, , v]) => { state[k] = angular(k) ? v * DEG : v; });
  return state;
}

export function fieldHelpers(fig, spec, angular) {
  fig.shown = () => Object.fromEntries(spec.fields.map(([k]) => [k, angular(k) ? fig.state[k] / DEG : fig.state[k]]));
  fig.fromField = (k, v) => ({ [k]: angular(k) ? v * DEG : v });
}

function disableMarks(div, d) {
  d.marks = [];
  div.querySelectorAll(".mech-mark").forEach((b) => { b.disabled = true; });
}

/** How many poses of the curve assemble, and the smallest transmission angle over them:
 *  `angle(group, pose)` is the angle at a group's joint, folded into [0, pi/2]. */
function overCurve(ok, groups, angle) {
  let count = 0, least = Infinity;
  for (let f = 0; f < ok.length; f++) {
    if (!ok[f]) continue;
    count += 1;
    groups.forEach((s) => { least = Math.min(least, fold(angle(s, f))); });
  }
  return [count, least];
}

const labelOf = (spec, key) => (spec.fields.find((f) => f[0] === key) || [key, key])[1];

// --- planar linkage ---------------------------------------------------------------------------

/** Solve the planar steps at the crank angles `theta`: points[name] = [x[], y[]], ok[]. */
export function solvePlanar(spec, state, theta) {
  const n = theta.length, P = {}, O = {}, D = {}, ok = new Uint8Array(n).fill(1);
  const arr = () => [new Float64Array(n), new Float64Array(n)];
  const put = (name) => (P[name] = P[name] || arr());
  const flip = state.branch;
  for (const s of spec.steps) {
    if (s.k === "ground") {
      const p = put(s.name), [x, y] = state["g_" + s.name] || s.at;
      p[0].fill(x); p[1].fill(y);
      continue;
    }
    if (s.k === "crank") {
      const r = positive(labelOf(spec, s.len), state[s.len]), A = P[s.pivot], B = put(s.tip);
      const dir = arr();
      for (let f = 0; f < n; f++) {
        const c = Math.cos(theta[f]), sn = Math.sin(theta[f]);
        [B[0][f], B[1][f]] = assur.rigid_body_position(A[0][f], A[1][f], c, sn, r, 0);
        dir[0][f] = c; dir[1][f] = sn;
      }
      O[s.link] = s.pivot; D[s.link] = dir;
      continue;
    }
    if (s.k === "point") {
      const o = P[O[s.link]], dir = D[s.link], Q = put(s.name), [lx, ly] = state["p_" + s.name] || s.at;
      for (let f = 0; f < n; f++) [Q[0][f], Q[1][f]] = assur.rigid_body_position(o[0][f], o[1][f], dir[0][f], dir[1][f], lx, ly);
      continue;
    }
    if (s.k === "rrr") {
      const r1 = positive(labelOf(spec, s.lens[0]), state[s.lens[0]]), r2 = positive(labelOf(spec, s.lens[1]), state[s.lens[1]]);
      const P1 = P[s.pins[0]], P2 = P[s.pins[1]], J = put(s.joint), d1 = arr(), d2 = arr();
      const M = (state["b_" + s.joint] || s.branch) * flip;
      for (let f = 0; f < n; f++) {
        const gx = P2[0][f] - P1[0][f], gy = P2[1][f] - P1[1][f];
        const heron = assur.rrr_position(gx, gy, r1, r2, 1)[2];
        const fine = heron >= 0;
        const [ux, uy] = assur.rrr_position_root(gx, gy, r1, r2, fine ? M * Math.sqrt(heron) : NaN);
        if (!fine) ok[f] = 0;
        J[0][f] = P1[0][f] + ux; J[1][f] = P1[1][f] + uy;
        d1[0][f] = ux / r1; d1[1][f] = uy / r1;
        d2[0][f] = (J[0][f] - P2[0][f]) / r2; d2[1][f] = (J[1][f] - P2[1][f]) / r2;
      }
      O[s.links[0]] = s.pins[0]; D[s.links[0]] = d1; O[s.links[1]] = s.pins[1]; D[s.links[1]] = d2;
      continue;
    }
    if (s.k === "rrp") {
      const r1 = positive(labelOf(spec, s.len), state[s.len]), P1 = P[s.pin], J = put(s.joint), d1 = arr(), e = arr();
      const M = s.branch * flip, g = s.guide;
      for (let f = 0; f < n; f++) {
        // the guide: through a point fixed in its link, at an angle to the link
        let qx = g.through[0], qy = g.through[1], ex = Math.cos(g.angle), ey = Math.sin(g.angle);
        if (g.link !== "ground") {
          const o = P[O[g.link]], dir = D[g.link];
          [qx, qy] = assur.rigid_body_position(o[0][f], o[1][f], dir[0][f], dir[1][f], qx, qy);
          [ex, ey] = [dir[0][f] * ex - dir[1][f] * ey, dir[1][f] * ex + dir[0][f] * ey];
        }
        const gx = qx - P1[0][f], gy = qy - P1[1][f], disc = assur.rrp_position(gx, gy, ex, ey, r1, 1)[3];
        if (!(disc >= 0)) ok[f] = 0;
        const [, ux, uy] = assur.rrp_position_root(gx, gy, ex, ey, disc >= 0 ? M * Math.sqrt(disc) : NaN);
        J[0][f] = P1[0][f] + ux; J[1][f] = P1[1][f] + uy;
        d1[0][f] = ux / r1; d1[1][f] = uy / r1; e[0][f] = ex; e[1][f] = ey;
      }
      O[s.links[0]] = s.pin; D[s.links[0]] = d1; O[s.links[1]] = s.joint; D[s.links[1]] = e;
      continue;
    }
    if (s.k === "rpr") {
      const P1 = P[s.pins[0]], P2 = P[s.pins[1]], w = arr(), M = s.branch * flip;
      for (let f = 0; f < n; f++) {
        const gx = P2[0][f] - P1[0][f], gy = P2[1][f] - P1[1][f], disc = assur.rpr_position(gx, gy, s.offset, 1)[3];
        if (!(disc >= 0)) ok[f] = 0;
        [w[0][f], w[1][f]] = assur.rpr_position_root(gx, gy, s.offset, disc >= 0 ? M * Math.sqrt(disc) : NaN);
      }
      O[s.links[0]] = s.pins[0]; D[s.links[0]] = w; O[s.links[1]] = s.pins[1]; D[s.links[1]] = w;
    }
  }
  return { P, O, D, ok };
}

export function planarLinkage(div, d, api, spec) {
  const state = fieldState(spec, () => false);
  const theta = Float64Array.from(spec.theta);
  const curveTheta = Float64Array.from({ length: spec.curve }, (_, i) => (2 * Math.PI * i) / spec.curve);
  const fig = { state, handleSize: 1.1 * d.unit };
  fieldHelpers(fig, spec, () => false);
  const g = (x, y) => [x / d.grid, -y / d.grid];
  const idx = (name) => d.names.indexOf(name);
  // a block's helper point "_X" sets its direction: as far from X as the build put it
  const helpers = d.names.filter((nm) => nm[0] === "_" && idx(nm.slice(1)) >= 0).map((nm) => {
    const a = d.P[idx(nm)], b = d.P[idx(nm.slice(1))];
    return { i: idx(nm), of: idx(nm.slice(1)), reach: Math.hypot(a[0] - b[0], a[1] - b[1]) * d.grid };
  });
  const blockLink = {};
  spec.steps.forEach((s) => {
    if (s.k === "rrp") blockLink[s.joint] = s.links[1];
    if (s.k === "rpr") blockLink[s.pins[1]] = s.links[1];
  });
  const grounds = spec.steps.filter((s) => s.k === "ground").map((s) => s.name);
  const crank = spec.steps.find((s) => s.k === "crank");
  const joints = spec.steps.filter((s) => s.k === "rrr");
  const points = spec.steps.filter((s) => s.k === "point");
  fig.handles = grounds.concat([crank.tip], joints.map((s) => s.joint), points.map((s) => s.name)).filter((nm) => idx(nm) >= 0);
  let sol = null, run = null, first = true;
  fig.compute = () => {
    sol = solvePlanar(spec, state, theta);
    run = solvePlanar(spec, state, curveTheta);
    const n = theta.length;
    Object.entries(sol.P).forEach(([name, [X, Y]]) => {
      const i = idx(name);
      if (i < 0) return;
      if (grounds.includes(name)) { d.P[i] = g(X[0], Y[0]); return; }
      const out = new Array(2 * n);
      for (let f = 0; f < n; f++) [out[2 * f], out[2 * f + 1]] = sol.ok[f] ? g(X[f], Y[f]) : [null, null];
      d.P[i] = out;
    });
    helpers.forEach((h) => {
      const [X, Y] = sol.P[d.names[h.of]], dir = sol.D[blockLink[d.names[h.of]]];
      if (!dir) return;
      const out = new Array(2 * n);
      for (let f = 0; f < n; f++) {
        [out[2 * f], out[2 * f + 1]] = sol.ok[f] ? g(X[f] + h.reach * dir[0][f], Y[f] + h.reach * dir[1][f]) : [null, null];
      }
      d.P[h.i] = out;
    });
    d.curves = d.trace.map((i) => {
      const [X, Y] = run.P[d.names[i]];
      return Array.from(curveTheta, (_, f) => (run.ok[f] ? g(X[f], Y[f]) : null));
    });
    if (first) { disableMarks(div, d); first = false; }
  };
  fig.message = (f) => (!sol || sol.ok[f] ? "" : `At \u03b8 = ${deg(theta[f])} this linkage cannot be assembled: ` +
    "a group's two links do not reach each other (the crank does not reach this angle).");
  fig.readout = () => {
    const [count, least] = overCurve(run.ok, joints, (s, f) => {
      const J = run.P[s.joint], A = run.P[s.pins[0]], B = run.P[s.pins[1]];
      const ux = A[0][f] - J[0][f], uy = A[1][f] - J[1][f], vx = B[0][f] - J[0][f], vy = B[1][f] - J[1][f];
      return Math.atan2(Math.abs(ux * vy - uy * vx), ux * vx + uy * vy);
    });
    const [kind, limits] = turnWords(count, curveTheta.length);
    const transmission = joints.length && Number.isFinite(least)
      ? `smallest transmission angle ${deg(least)} (joints ${joints.map((s) => s.joint).join(", ")}; over ${spec.curve} poses)`
      : "no RRR group: no transmission angle";
    return { kind, limits, transmission };
  };
  fig.where = (name, f) => {
    const arr = d.P[idx(name)], j = arr.length === 2 ? 0 : 2 * f;
    return arr[j] === null || arr[j] === undefined ? null : [arr[j], arr[j + 1]];
  };
  fig.fromDrag = (name, gx, gy, f) => {
    const x = gx * d.grid, y = -gy * d.grid;
    if (grounds.includes(name)) return { ["g_" + name]: [x, y] };
    const one = solvePlanar(spec, state, [theta[f]]);
    if (!one.ok[0]) return null;
    const at = (nm) => [one.P[nm][0][0], one.P[nm][1][0]];
    if (name === crank.tip) {
      const A = at(crank.pivot);
      return { [crank.len]: Math.hypot(x - A[0], y - A[1]) || state[crank.len] };
    }
    const s = joints.find((j) => j.joint === name);
    if (s) {
      // new lengths to the two pins; the group's mode is the side of pins[0] -> pins[1] it is on
      const A = at(s.pins[0]), B = at(s.pins[1]);
      const side = (B[0] - A[0]) * (y - A[1]) - (B[1] - A[1]) * (x - A[0]) >= 0 ? 1 : -1;
      return { [s.lens[0]]: Math.hypot(x - A[0], y - A[1]), [s.lens[1]]: Math.hypot(x - B[0], y - B[1]),
        ["b_" + s.joint]: side * state.branch };
    }
    const p = points.find((q) => q.name === name);
    if (p) {
      const o = at(one.O[p.link]), c = one.D[p.link][0][0], sn = one.D[p.link][1][0];
      const u = x - o[0], v = y - o[1];
      return { ["p_" + name]: [c * u + sn * v, -sn * u + c * v] };
    }
    return null;
  };
  return fig;
}

// --- spherical linkage ------------------------------------------------------------------------

export function solveSpherical(spec, state, theta) {
  const n = theta.length, P = {}, F = {}, ok = new Uint8Array(n).fill(1);
  const list = () => new Array(n);
  for (const s of spec.steps) {
    if (s.k === "ground") { P[s.name] = new Array(n).fill(s.at); continue; }
    if (s.k === "crank") {
      const a = positive(labelOf(spec, s.arc), state[s.arc]), tip = (P[s.tip] = list());
      for (let f = 0; f < n; f++) tip[f] = sph.spherical_link_point(...P[s.pivot][f], ...P[s.ref][f], a, theta[f]);
      F[s.link] = [s.pivot, s.tip];
      continue;
    }
    if (s.k === "point") {
      const [o, x] = F[s.link], Q = (P[s.name] = list());
      for (let f = 0; f < n; f++) Q[f] = sph.spherical_link_point(...P[o][f], ...P[x][f], s.r, s.g);
      continue;
    }
    const b1 = positive(labelOf(spec, s.arcs[0]), state[s.arcs[0]]), b2 = positive(labelOf(spec, s.arcs[1]), state[s.arcs[1]]);
    const J = (P[s.joint] = list()), sigma = (state["b_" + s.joint] || s.branch) * state.branch;
    for (let f = 0; f < n; f++) {
      const P1 = P[s.pins[0]][f], P2 = P[s.pins[1]][f];
      const rho = sph.spherical_dyad_radicand(...P1, ...P2, b1, b2);
      if (!(rho >= 0)) ok[f] = 0;
      J[f] = sph.spherical_dyad_position(...P1, ...P2, b1, b2, sigma, rho >= 0 ? rho : NaN);
    }
    F[s.links[0]] = [s.pins[0], s.joint];
    F[s.links[1]] = [s.pins[1], s.joint];
  }
  return { P, F, ok };
}

export function grid3(d) {
  const s = d.step, c = d.c0;
  return (p) => (p && p[0] === p[0] ? [(p[0] - c[0]) / s, (p[1] - c[1]) / s, (p[2] - c[2]) / s] : [null, null, null]);
}

export function where3(d, api) {
  return (name, f) => {
    const arr = d.P[d.names.indexOf(name)], j = arr.length === 3 ? 0 : 3 * f;
    if (arr[j] === null) return null;
    const q = api.project([arr[j] * d.step, arr[j + 1] * d.step, arr[j + 2] * d.step]);
    return q[2] < 0 && d.sphere ? null : q;
  };
}

export function sphericalLinkage(div, d, api, spec) {
  const angular = () => true;
  const state = fieldState(spec, angular);
  const theta = Float64Array.from(spec.theta);
  const curveTheta = Float64Array.from({ length: spec.curve }, (_, i) => (2 * Math.PI * i) / spec.curve);
  const fig = { state, handleSize: 26 };
  fieldHelpers(fig, spec, angular);
  const grid = grid3(d), idx = (name) => d.names.indexOf(name);
  const crank = spec.steps.find((s) => s.k === "crank"), joints = spec.steps.filter((s) => s.k === "rrr");
  fig.handles = [crank.tip].concat(joints.map((s) => s.joint)).filter((nm) => idx(nm) >= 0);
  let sol = null, run = null;
  fig.compute = () => {
    sol = solveSpherical(spec, state, theta);
    run = solveSpherical(spec, state, curveTheta);
    Object.entries(sol.P).forEach(([name, pts]) => {
      const i = idx(name);
      if (i < 0 || d.P[i].length === 3) return; // a ground point stays where it is
      d.P[i] = pts.flatMap((p, f) => (sol.ok[f] ? grid(p) : [null, null, null]));
    });
    d.curves = d.trace.map((i) => run.P[d.names[i]].map((p, f) => (run.ok[f] ? grid(p) : null)));
  };
  fig.message = (f) => (!sol || sol.ok[f] ? "" : `At \u03b8 = ${deg(theta[f])} this spherical linkage cannot be ` +
    "assembled: a dyad's two arcs do not meet (the input does not reach this angle).");
  fig.readout = () => {
    const [count, least] = overCurve(run.ok, joints, (s, f) => {
      const J = run.P[s.joint][f];
      return angle3(tangent(J, run.P[s.pins[0]][f]), tangent(J, run.P[s.pins[1]][f]));
    });
    const [kind, limits] = turnWords(count, curveTheta.length);
    return { kind, limits,
      transmission: `smallest transmission angle ${deg(least)} (joints ${joints.map((s) => s.joint).join(", ")}; over ${spec.curve} poses)` };
  };
  fig.where = where3(d, api);
  fig.fromDrag = (name, x, y, f) => {
    const w = unproject(api.view(), x, y);
    const one = solveSpherical(spec, state, [theta[f]]);
    if (name === crank.tip) return { [crank.arc]: angle3(one.P[crank.pivot][0], w) };
    const s = joints.find((j) => j.joint === name);
    if (!s || !one.ok[0]) return null;
    const A = one.P[s.pins[0]][0], B = one.P[s.pins[1]][0];
    const side = dot3(A, cross3(B, w)) >= 0 ? 1 : -1;
    return { [s.arcs[0]]: angle3(A, w), [s.arcs[1]]: angle3(B, w), ["b_" + s.joint]: side * state.branch };
  };
  return fig;
}

// --- RSSR ----------------------------------------------------------------------------------------

const RSSR_KEYS = ["l1", "l2", "l3", "s0", "s3", "h0", "lam"];

export function solveRSSR(v, sigma, phi) {
  const dims = RSSR_KEYS.map((k) => v[k]);
  const [A, B, C] = rssrK.rssr_abc(...dims, phi);
  const [, rho, r2] = rssrK.rssr_reach(...dims, phi);
  const disc = r2 >= 0 ? rssrK.rssr_discriminant(v.l1, v.l3, rho, Math.sqrt(Math.max(r2, 0))) : abc.abc_discriminant(A, B, C);
  const dead = Math.abs(disc) <= 2 ** -46 * (A * A + B * B + C * C);
  const good = disc >= 0 || dead;
  if (!good) return null;
  const phi03 = abc.abc_solve(A, B, C, Math.sqrt(Math.max(disc, 0)), sigma);
  const p = rssrK.rssr_points(v.l1, v.l3, v.s0, v.s3, v.h0, v.lam, phi, phi03);
  return [[p[0], p[1], p[2]], [p[3], p[4], p[5]]];
}

export function rssr(div, d, api, spec) {
  const angular = (k) => k === "lam";
  const state = fieldState(spec, angular);
  Object.assign(state, spec.dims, { branch: spec.branch });
  const theta = Float64Array.from(spec.theta);
  const curveTheta = Float64Array.from({ length: spec.curve }, (_, i) => (2 * Math.PI * i) / spec.curve);
  const fig = { state, handleSize: 26, handles: [] };
  fieldHelpers(fig, spec, angular);
  const grid = grid3(d), idx = (name) => d.names.indexOf(name);
  let run = null, ok = null, first = true;
  fig.compute = () => {
    ["l1", "l2", "l3", "h0"].forEach((k) => positive(labelOf(spec, k), state[k]));
    ["s0", "s3", "lam"].forEach((k) => {
      if (!Number.isFinite(state[k])) throw new LinkageInputError(`Expected \`${labelOf(spec, k)}\` a finite number, got ${state[k]}`);
    });
    const out = { B: [], C: [], "C'": [] };
    ok = theta.map(() => 1);
    theta.forEach((t, f) => {
      const a = solveRSSR(state, state.branch, t), b = solveRSSR(state, -state.branch, t);
      if (!a) ok[f] = 0;
      out.B.push(...grid(a && a[0])); out.C.push(...grid(a && a[1])); out["C'"].push(...grid(b && b[1]));
    });
    Object.entries(out).forEach(([name, arr]) => { if (idx(name) >= 0) d.P[idx(name)] = arr; });
    const lam = state.lam, A = [0, 0, state.s0], D = [state.h0, state.s3 * Math.sin(lam), state.s3 * Math.cos(lam)];
    const z3 = [0, Math.sin(lam), Math.cos(lam)];
    const put = (name, p) => { if (idx(name) >= 0) d.P[idx(name)] = grid(p); };
    put("A", A); put("D", D); put("OK", [state.h0, 0, 0]);
    run = Array.from(curveTheta, (t) => solveRSSR(state, state.branch, t));
    const runOther = Array.from(curveTheta, (t) => solveRSSR(state, -state.branch, t));
    d.curves = d.trace.map((i) => (d.names[i] === "C'" ? runOther : run).map((p) => (p ? grid(p[1]) : null)));
    // the two axes and the common perpendicular, as the build draws them
    const seg = (a, b) => [...grid(a), ...grid(b)];
    const axes = [seg([A[0], A[1], A[2] - 1.5], [A[0], A[1], A[2] + 1.5]),
      seg(D.map((v, k) => v - 1.5 * z3[k]), D.map((v, k) => v + 1.5 * z3[k])), seg([0, 0, 0], [state.h0, 0, 0])];
    if (first) { d.still = d.still.slice(0, 3); first = false; }
    axes.forEach((p, k) => { d.still[k] = { p, c: d.still[k].c }; });
  };
  fig.message = (f) => (!ok || ok[f] ? "" : `At \u03c6\u2080\u2081 = ${deg(theta[f])} this RSSR cannot be assembled: ` +
    "the coupler does not reach the rocker's circle.");
  fig.readout = () => {
    let count = 0, least = Infinity;
    const z3 = [0, Math.sin(state.lam), Math.cos(state.lam)];
    const D = [state.h0, state.s3 * Math.sin(state.lam), state.s3 * Math.cos(state.lam)];
    run.forEach((p) => {
      if (!p) return;
      count += 1;
      const [B, C] = p, bc = [C[0] - B[0], C[1] - B[1], C[2] - B[2]], along = cross3(z3, [C[0] - D[0], C[1] - D[1], C[2] - D[2]]);
      const mu = Math.atan2(Math.hypot(...cross3(bc, along)), Math.abs(dot3(bc, along)));
      least = Math.min(least, Math.PI / 2 - mu);
    });
    const [kind, limits] = turnWords(count, curveTheta.length);
    return { kind, limits, transmission: `smallest transmission angle ${deg(least)} at C` };
  };
  fig.where = () => null;
  fig.fromDrag = () => null;
  return fig;
}

// --- open chain of example 2-25 -------------------------------------------------------------

export function openChain(div, d, api, spec) {
  const state = fieldState(spec, () => false);
  const fig = { state, handleSize: 0, handles: [] };
  fieldHelpers(fig, spec, () => false);
  const grid = grid3(d), idx = (name) => d.names.indexOf(name);
  let reach = [0, 0];
  fig.compute = () => {
    const s0 = positive("S0", state.s0), p = positive("p", state.p), shift = state.shift;
    if (!Number.isFinite(shift)) throw new LinkageInputError(`Expected \`shift of S2\` a finite number, got ${shift}`);
    const out = { O3: [], P: [], J: [] };
    let lo = Infinity, hi = -Infinity;
    spec.q.forEach(([q1, q2, q3, q4]) => {
      const r = chainK.example_2_25_pose(q1, q2, q3 + shift, q4, s0, p);
      const P = [r[0], r[1], r[2]], O = [r[0] - p * r[6], r[1] - p * r[7], r[2] - p * r[8]];
      out.P.push(...grid(P)); out.O3.push(...grid(O));
      out.J.push(...grid([O[0] + 0.05 * r[3], O[1] + 0.05 * r[4], O[2] + 0.05 * r[5]]));
      const a = chainK.example_2_25_reach(q2, q3 + shift, s0, p);
      lo = Math.min(lo, a); hi = Math.max(hi, a);
    });
    Object.entries(out).forEach(([name, arr]) => { if (idx(name) >= 0) d.P[idx(name)] = arr; });
    if (idx("B") >= 0) d.P[idx("B")] = grid([0, 0, s0]);
    d.curves = null;
    reach = [lo, hi];
  };
  fig.message = () => "";
  fig.readout = () => ({ kind: "open chain RRPR: no loop to close, every pose exists",
    limits: `reach |AP| from ${reach[0].toFixed(4)} to ${reach[1].toFixed(4)}`,
    transmission: "the gripper turns with \u03c6\u2083\u2084" });
  fig.where = () => null;
  fig.fromDrag = () => null;
  return fig;
}

// --- two great circles through a spherical triangle ------------------------------------------

const norm3 = (v) => { const k = Math.hypot(...v); return [v[0] / k, v[1] / k, v[2] / k]; };
// the pole of the directed great circle a -> b, formed as (a - b) x b (accurate for close points)
const pole = (a, b) => norm3(cross3([a[0] - b[0], a[1] - b[1], a[2] - b[2]], b));

export function greatCircles(div, d, api, spec) {
  const angular = () => true;
  const state = fieldState(spec, angular);
  const fig = { state, handleSize: 26, handles: ["A", "B", "C"] };
  fieldHelpers(fig, spec, angular);
  const grid = grid3(d), idx = (name) => d.names.indexOf(name);
  let pts = null, n1 = null, n2 = null;
  const ring = (n) => {
    const h = Math.abs(n[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0], e1 = norm3(cross3(n, h)), e2 = cross3(n, e1), out = [];
    for (let k = 0; k <= 96; k++) {
      const t = (2 * Math.PI * k) / 96, c = Math.cos(t), s = Math.sin(t);
      out.push(...grid([c * e1[0] + s * e2[0], c * e1[1] + s * e2[1], c * e1[2] + s * e2[2]]));
    }
    return out;
  };
  fig.compute = () => {
    pts = {};
    "ABC".split("").forEach((k) => {
      const lon = state[k + "lon"], lat = state[k + "lat"];
      if (!(Number.isFinite(lon) && Number.isFinite(lat) && Math.abs(lat) <= Math.PI / 2)) {
        throw new LinkageInputError(`Expected \`${k}\` a finite longitude and a latitude in [-90, 90] degrees, got ${lon / DEG}, ${lat / DEG}`);
      }
      pts[k] = calc.sph_to_xyz(lon, lat);
    });
    n1 = pole(pts.A, pts.B);
    n2 = pole(pts.B, pts.C);
    const x = cross3(n1, n2);
    if (!(Math.hypot(...x) > 0) || !(n1[0] === n1[0]) || !(n2[0] === n2[0])) {
      throw new LinkageInputError("Expected A, B and C with distinct great circles AB and BC, got one circle");
    }
    const X = norm3(x);
    const put = (name, p) => { if (idx(name) >= 0) d.P[idx(name)] = grid(p); };
    put("A", pts.A); put("B", pts.B); put("C", pts.C); put("X", X); put("\u2212X", X.map((v) => -v));
    put("N1", n1); put("N2", n2);
    d.still[0] = { p: ring(n1), c: d.still[0].c };
    d.still[1] = { p: ring(n2), c: d.still[1].c };
    d.still[3] = { p: [...grid([0, 0, 0]), ...grid(n1)], c: d.still[3].c };
    d.still[4] = { p: [...grid([0, 0, 0]), ...grid(n2)], c: d.still[4].c };
  };
  fig.message = () => "";
  fig.readout = () => ({ kind: "the great circles AB and BC meet at X and \u2212X",
    limits: `angle between the circles at X ${deg(angle3(n1, n2))}`,
    transmission: "arcs " + [["A", "B"], ["B", "C"], ["C", "A"]].map(([p, q]) => `${p}${q} ${deg(angle3(pts[p], pts[q]))}`).join(", ") });
  fig.where = where3(d, api);
  fig.fromDrag = (name, x, y) => {
    const w = unproject(api.view(), x, y);
    return { [name + "lon"]: Math.atan2(w[1], w[0]), [name + "lat"]: Math.atan2(w[2], Math.hypot(w[0], w[1])) };
  };
  return fig;
}
