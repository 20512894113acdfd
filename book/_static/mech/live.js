// Live figures: the controls of a player (figures/mech_anim.js) whose linkage the reader may
// change. The player imports this module only on a page that has a live figure; this module
// imports the layer (planar.js or spherical.js, and through it the generated kernels) that
// its linkage needs. figures/live.py writes the description (data.live), the controls and
// the first read-out; here every change recomputes the poses, the coupler curve, the type,
// the limit positions and the smallest transmission angle, and the player draws them.
// Written by hand; the formulas are in the kernels.

import { unproject } from "./core.js";

const deg = (x) => (x * 180 / Math.PI).toFixed(1).replace("-", "\u2212") + "\u00b0";
const DEG = Math.PI / 180;

/** Wire the live figure `div` (data `d`, player hooks `api`). */
export async function attach(div, d, api) {
  const spec = d.live;
  const chains = { linkage: "planarLinkage", sphlinkage: "sphericalLinkage", rssr: "rssr", chain: "openChain",
    circles: "greatCircles", stephenson3: "stephenson3" };
  const kind = { fourbar: planarFourBar, slidercrank: sliderCrank, guidebar: guideBar, sphfourbar: sphericalFourBar,
    hooke: hookeJoint }[spec.type] || (spec.type in chains && "chains");
  if (!kind) return;
  if (kind === "chains") { // linkages built step by step (live_chains.js), the triad (live_triad.js)
    const m = Object.assign({}, await import("./live_chains.js"), spec.type === "stephenson3" ? await import("./live_triad.js") : {});
    return wire(div, d, api, m[chains[spec.type]](div, d, api, spec), m);
  }
  const layer = Object.assign({}, await import(spec.type === "sphfourbar" ? "./spherical.js"
    : spec.type === "hooke" ? "./core.js" : "./planar.js"));
  if (spec.type === "hooke") layer.kernel = await import("../kernels/hooke.js");
  if (spec.type === "slidercrank" || spec.type === "guidebar") layer.kernel = await import("../kernels/slider_crank.js");
  if (spec.type === "guidebar") layer.core = await import("./core.js");
  wire(div, d, api, kind(div, d, api, spec, layer), layer);
}

/** The controls, handles and read-out of the figure object `fig` of the player `api`. */
function wire(div, d, api, fig, layer) {
  const box = div.querySelector(".mech-live");
  const msg = box.querySelector(".mech-live-msg");
  const stats = { times: [], updates: 0, parts: [] };
  div.mechLive = stats;
  let good = Object.assign({}, fig.state);

  function fields() {
    box.querySelectorAll("input[data-k]").forEach((input) => {
      const v = fig.shown()[input.dataset.k];
      if (v !== undefined && document.activeElement !== input) input.value = +v.toPrecision(6);
    });
    const button = box.querySelector(".mech-branch");
    if (button) button.textContent = "branch " + (fig.state.branch > 0 ? "+1" : "\u22121");
  }
  // One change: recompute with the kernels, draw, or say why not and keep the last good state.
  function update(change) {
    const t0 = performance.now();
    Object.assign(fig.state, change);
    let text = "";
    try {
      fig.compute();
      const t1 = performance.now();
      good = Object.assign({}, fig.state);
      text = fig.message(api.frame());
      api.redraw();
      const t2 = performance.now();
      stats.parts.push([t1 - t0, t2 - t1]);
      const out = fig.readout();
      box.querySelector(".mech-live-type").textContent = out.kind;
      box.querySelector(".mech-live-limits").textContent = out.limits;
      box.querySelector(".mech-live-gamma").textContent = out.transmission;
    } catch (err) {
      if (!(err instanceof layer.LinkageInputError)) throw err;
      fig.state = Object.assign(fig.state, good);
      text = "Cannot take this change: " + err.message + ". The last linkage that assembles is kept.";
    }
    msg.textContent = text;
    fields();
    stats.updates += 1;
    stats.times.push(performance.now() - t0);
    if (stats.times.length > 2000) stats.times.shift();
  }
  stats.update = update;
  stats.data = d;
  stats.api = api;
  // Several values at once, in the units of the fields (the browser test resets with it).
  stats.set = (values) => update(Object.assign({}, ...Object.entries(values).map(([k, v]) =>
    (k in fig.shown() ? fig.fromField(k, v) : { [k]: v }))));

  box.querySelectorAll("input[data-k]").forEach((input) => {
    input.addEventListener("input", () => {
      const v = parseFloat(input.value);
      if (!Number.isFinite(v)) {
        msg.textContent = `Expected a number for ${input.dataset.k}, got "${input.value}"`;
        return;
      }
      box.querySelectorAll(`input[data-k="${input.dataset.k}"]`).forEach((o) => { if (o !== input) o.value = v; });
      update(fig.fromField(input.dataset.k, v));
    });
  });
  const button = box.querySelector(".mech-branch");
  if (button) button.addEventListener("click", () => update({ branch: -fig.state.branch }));
  // A pose the player passes without a change still gets its message (it may not assemble).
  const svg = api.svg;
  const handles = document.createElementNS("http://www.w3.org/2000/svg", "g");
  handles.setAttribute("class", "mf-handles");
  svg.appendChild(handles);
  const dots = fig.handles.map((h) => {
    const c = document.createElementNS("http://www.w3.org/2000/svg", "circle");
    c.setAttribute("class", "mf-handle");
    c.setAttribute("data-handle", h);
    c.setAttribute("r", fig.handleSize);
    handles.appendChild(c);
    return c;
  });
  let last = -1;
  api.after = (f) => {
    if (svg.lastChild !== handles) svg.appendChild(handles); // above the drawing
    fig.handles.forEach((h, k) => {
      const q = fig.where(h, f);
      dots[k].style.display = q ? "" : "none";
      if (q) { dots[k].setAttribute("cx", q[0]); dots[k].setAttribute("cy", q[1]); }
    });
    if (f !== last) { last = f; if (!msg.textContent.startsWith("Cannot take")) msg.textContent = fig.message(f); }
  };
  // While a handle is held, a label keeps the place it took last time around its point:
  // measuring text boxes forces a layout, too slow for every move.
  const place = api.place, spots = {};
  api.place = (t, q, off, placed, key) => {
    const s = spots[key];
    if (api.quick && s) {
      t.setAttribute("x", q[0] + s[0]); t.setAttribute("y", q[1] + s[1]); t.setAttribute("text-anchor", s[2]);
      return;
    }
    place(t, q, off, placed);
    spots[key] = [+t.getAttribute("x") - q[0], +t.getAttribute("y") - q[1], t.getAttribute("text-anchor")];
  };
  let held = null;
  dots.forEach((dot, k) => {
    dot.addEventListener("pointerdown", (e) => {
      held = fig.handles[k];
      api.quick = true;
      e.stopPropagation(); // not a turn of a 3-D view
      e.preventDefault();
      try { svg.setPointerCapture(e.pointerId); } catch (err) { /* a synthetic event has no pointer to capture */ }
    });
  });
  // the moves of a held handle, wherever the pointer is (captured by the svg)
  svg.addEventListener("pointermove", (e) => {
    if (!held) return;
    e.stopPropagation();
    const p = new DOMPoint(e.clientX, e.clientY).matrixTransform(svg.getScreenCTM().inverse());
    const change = fig.fromDrag(held, p.x, p.y, api.frame());
    if (change) update(change);
  }, true);
  // the drag ends: labels placed afresh around their points
  ["pointerup", "pointercancel"].forEach((t) => window.addEventListener(t, () => {
    if (held) { held = null; api.quick = false; api.redraw(); }
  }));
  api.after(api.frame());
}

// --- planar four-bar ---------------------------------------------------------------------

function planarFrame(spec, d) {
  // local (A = 0, D = (d, 0)) -> the player's grid (x, -y over the grid step)
  const toGrid = (x, y) => {
    const c = Math.cos(state.angle), s = Math.sin(state.angle);
    return [(state.ox + c * x - s * y) / d.grid, -(state.oy + s * x + c * y) / d.grid];
  };
  const toWorld = (gx, gy) => [gx * d.grid, -gy * d.grid];
  const state = { ox: spec.origin[0], oy: spec.origin[1], angle: spec.angle };
  return { state, toGrid, toWorld };
}

function planarFourBar(div, d, api, spec, L) {
  const frame = planarFrame(spec, d);
  const [nA, nB, nC, nD] = spec.names.map((n) => d.names.indexOf(n));
  const couplers = Object.entries(spec.couplers).map(([name, pq]) => ({ i: d.names.indexOf(name), p: pq[0], q: pq[1] }));
  const state = Object.assign(frame.state, { a: spec.a, b: spec.b, c: spec.c, d: spec.d, branch: spec.branch,
    p: couplers.length ? couplers[0].p : 0, q: couplers.length ? couplers[0].q : 0 });
  const theta = Float64Array.from(spec.theta);
  const curveTheta = Float64Array.from({ length: spec.curve }, (_, i) => (2 * Math.PI * i) / spec.curve);
  const fig = { state, handleSize: 1.1 * d.unit };
  let pose = null, first = true, solved = {};
  fig.handles = [nA, nD, nB, nC].concat(couplers.map((c) => c.i)).filter((i) => i >= 0).map((i) => d.names[i]);
  fig.shown = () => ({ a: state.a, b: state.b, c: state.c, d: state.d, p: state.p, q: state.q });
  fig.fromField = (k, v) => ({ [k]: v });

  function local(x, y) { // world -> local frame of A, D
    const c = Math.cos(state.angle), s = Math.sin(state.angle), u = x - state.ox, v = y - state.oy;
    return [c * u + s * v, -s * u + c * v];
  }
  // the other coupler points keep their place on the coupler when the first one moves
  function extra(Bx, By, Cx, Cy, p, q) {
    const ux = (Cx - Bx) / state.b, uy = (Cy - By) / state.b;
    return [Bx + p * ux - q * uy, By + p * uy + q * ux];
  }
  function fill(P, out, bx) {
    const n = out.Bx.length;
    const B = new Array(2 * n), C = new Array(2 * n), X = couplers.map(() => new Array(2 * n));
    for (let f = 0; f < n; f++) {
      const ok = out.assembled[f];
      const b = frame.toGrid(out.Bx[f], out.By[f]);
      B[2 * f] = b[0]; B[2 * f + 1] = b[1];
      const c = ok ? frame.toGrid(out.Cx[f], out.Cy[f]) : [null, null];
      C[2 * f] = c[0]; C[2 * f + 1] = c[1];
      couplers.forEach((k, j) => {
        const w = ok ? frame.toGrid(...extra(out.Bx[f], out.By[f], out.Cx[f], out.Cy[f], k.p, k.q)) : [null, null];
        X[j][2 * f] = w[0]; X[j][2 * f + 1] = w[1];
      });
    }
    if (nB >= 0) P[nB] = B;
    if (nC >= 0) P[nC] = C;
    couplers.forEach((k, j) => { P[k.i] = X[j]; });
    if (nA >= 0) P[nA] = frame.toGrid(0, 0);
    if (nD >= 0) P[nD] = frame.toGrid(state.d, 0);
    return bx;
  }
  fig.compute = () => {
    if (couplers.length) { couplers[0].p = state.p; couplers[0].q = state.q; }
    // the joints depend on the lengths and the branch only: a moved coupler point reuses them
    const key = [state.a, state.b, state.c, state.d, state.branch].join();
    if (key !== solved.key) {
      const linkage = new L.FourBar(state.a, state.b, state.c, state.d, { branch: state.branch });
      solved = { key, pose: linkage.solve(theta), run: linkage.solve(curveTheta),
        ghost: d.ghost ? new L.FourBar(state.a, state.b, state.c, state.d, { branch: -state.branch }).solve(theta) : null };
    }
    pose = solved.pose;
    fill(d.P, pose);
    if (d.ghost) fill(d.ghost, solved.ghost);
    // the path of each traced point over a whole turn of the crank, finer than the frames
    const run = solved.run;
    d.curves = d.trace.map((i) => {
      const pts = new Array(curveTheta.length);
      const k = couplers.findIndex((c) => c.i === i);
      for (let f = 0; f < curveTheta.length; f++) {
        if (!run.assembled[f]) { pts[f] = null; continue; }
        const [x, y] = i === nB ? [run.Bx[f], run.By[f]] : i === nC ? [run.Cx[f], run.Cy[f]]
          : k >= 0 ? extra(run.Bx[f], run.By[f], run.Cx[f], run.Cy[f], couplers[k].p, couplers[k].q) : [NaN, NaN];
        pts[f] = x === x ? frame.toGrid(x, y) : null;
      }
      if (pts[0] && pts[pts.length - 1]) pts.push(pts[0]);
      return pts;
    });
    if (first) { d.marks = []; div.querySelectorAll(".mech-mark").forEach((b) => { b.disabled = true; }); first = false; }
  };
  fig.message = (f) => {
    if (!pose || pose.assembled[f]) return "";
    return `At \u03b8 = ${deg(theta[f])} this four-bar cannot be assembled: the triangle BCD does not close ` +
      `(the crank does not reach this angle).`;
  };
  fig.readout = () => {
    const { a, b, c, d: g } = state;
    const kind = L.grashof(a, b, c, g).kind;
    let limits = "limit positions: none of a crank-rocker";
    if (kind === "crank-rocker") {
      const lim = L.limitPositions(a, b, c, g, { branch: state.branch });
      limits = `limit positions \u03b8 = ${deg(lim.thetaExtended)}, ${deg(lim.thetaFolded)} ` +
        `(swing ${deg(lim.swing)}, K = ${lim.timeRatio.toFixed(3)})`;
    }
    const [gamma, at] = L.minTransmissionAngle(a, b, c, g);
    return { kind, limits, transmission: `smallest transmission angle ${deg(gamma)} at \u03b8 = ${deg(at)}` };
  };
  fig.where = (name, f) => {
    const i = d.names.indexOf(name), arr = d.P[i];
    const j = arr.length === 2 ? 0 : 2 * f;
    return arr[j] === null || arr[j] === undefined ? null : [arr[j], arr[j + 1]];
  };
  fig.fromDrag = (name, gx, gy, f) => {
    const [x, y] = frame.toWorld(gx, gy);
    const i = d.names.indexOf(name);
    const th = theta[f];
    if (i === nA || i === nD) {
      const Dw = [state.ox + state.d * Math.cos(state.angle), state.oy + state.d * Math.sin(state.angle)];
      const [Ax, Ay] = i === nA ? [x, y] : [state.ox, state.oy];
      const [Dx, Dy] = i === nA ? Dw : [x, y];
      const len = Math.hypot(Dx - Ax, Dy - Ay);
      if (!(len > 0)) return null;
      return { ox: Ax, oy: Ay, d: len, angle: Math.atan2(Dy - Ay, Dx - Ax) };
    }
    const [lx, ly] = local(x, y);
    if (i === nB) return { a: Math.hypot(lx, ly) || state.a };
    // before any change the drawing is the build's: solve the pose it shows
    pose = pose || new L.FourBar(state.a, state.b, state.c, state.d, { branch: state.branch }).solve(theta);
    if (!pose.assembled[f]) return null;
    const Bx = pose.Bx[f], By = pose.By[f];
    if (i === nC) {
      // C dragged: new coupler and rocker lengths; the branch is the side of B->D it is on
      const cross = (state.d - Bx) * (ly - By) - (0 - By) * (lx - Bx);
      return { b: Math.hypot(lx - Bx, ly - By), c: Math.hypot(lx - state.d, ly), branch: cross >= 0 ? 1 : -1 };
    }
    if (couplers.length && i === couplers[0].i) {
      // (P - B) / (C - B) * b = p + i q
      const ux = pose.Cx[f] - Bx, uy = pose.Cy[f] - By, wx = lx - Bx, wy = ly - By, n2 = ux * ux + uy * uy;
      return { p: ((wx * ux + wy * uy) / n2) * state.b, q: ((wy * ux - wx * uy) / n2) * state.b };
    }
    return null;
  };
  return fig;
}

// --- slider-crank ---------------------------------------------------------------------------

function sliderCrank(div, d, api, spec, L) {
  const [nA, nB, nC] = spec.names.map((n) => d.names.indexOf(n));
  const state = { a: spec.a, b: spec.b, e: spec.e, branch: spec.branch };
  const theta = Float64Array.from(spec.theta);
  const curveTheta = Float64Array.from({ length: spec.curve }, (_, i) => (2 * Math.PI * i) / spec.curve);
  const g = (x, y) => [x / d.grid, -y / d.grid];
  const fig = { state, handleSize: 1.1 * d.unit, handles: [nB, nC].filter((i) => i >= 0).map((i) => d.names[i]) };
  let pose = null, first = true, crank = null;
  fig.shown = () => ({ a: state.a, b: state.b, e: state.e });
  fig.fromField = (k, v) => ({ [k]: v });
  fig.compute = () => {
    crank = new L.SliderCrank(state.a, state.b, state.e, { branch: state.branch });
    pose = crank.solve(theta);
    const n = theta.length, B = new Array(2 * n), C = new Array(2 * n);
    let lo = Infinity, hi = -Infinity;
    for (let f = 0; f < n; f++) {
      [B[2 * f], B[2 * f + 1]] = g(pose.Bx[f], pose.By[f]);
      const ok = pose.assembled[f];
      [C[2 * f], C[2 * f + 1]] = ok ? g(pose.Cx[f], pose.Cy[f]) : [null, null];
      if (ok) { lo = Math.min(lo, pose.Cx[f]); hi = Math.max(hi, pose.Cx[f]); }
    }
    d.P[nB] = B;
    if (nC >= 0) d.P[nC] = C;
    if (nA >= 0) d.P[nA] = g(0, 0);
    const run = crank.solve(curveTheta);
    d.curves = d.trace.map((i) => Array.from(curveTheta, (_, f) =>
      (i === nB ? g(run.Bx[f], run.By[f]) : run.assembled[f] ? g(run.Cx[f], run.Cy[f]) : null)));
    if (lo <= hi) {
      const pad = 0.15 * (hi - lo) + state.a * 0.3;
      d.lines = [[g(lo - pad, state.e), g(hi + pad, state.e)]];
    }
    if (first) { d.marks = []; div.querySelectorAll(".mech-mark").forEach((b) => { b.disabled = true; }); first = false; }
  };
  fig.message = (f) => (!pose || pose.assembled[f] ? "" : `At \u03b8 = ${deg(theta[f])} the rod cannot reach the guide ` +
    `(|a sin \u03b8 \u2212 e| > b): this slider-crank does not assemble there.`);
  fig.readout = () => {
    const [a, b, e] = crank.unit; // lengths over a power of two: the kernels' own scale
    if (!crank.crankTurns) {
      return { kind: "rocker-slider (the crank rocks)", limits: "limit positions: the crank's own",
        transmission: "smallest transmission angle 0.0\u00b0" };
    }
    const lim = L.kernel.slider_crank_limits(a, b, e, state.branch);
    const scale = state.a / a;
    return { kind: "crank-slider (the crank turns fully)",
      limits: `limit positions \u03b8 = ${deg(lim[0])}, ${deg(lim[1])} (stroke ${(lim[4] * scale).toFixed(2)}, ` +
        `K = ${((Math.PI + lim[5]) / (Math.PI - lim[5])).toFixed(3)})`,
      transmission: `smallest transmission angle ${deg(L.kernel.slider_crank_min_transmission(a, b, e))}` };
  };
  fig.where = (name, f) => {
    const arr = d.P[d.names.indexOf(name)], j = arr.length === 2 ? 0 : 2 * f;
    return arr[j] === null ? null : [arr[j], arr[j + 1]];
  };
  fig.fromDrag = (name, gx, gy, f) => {
    const x = gx * d.grid, y = -gy * d.grid, i = d.names.indexOf(name);
    if (i === nB) return { a: Math.hypot(x, y) || state.a };
    pose = pose || new L.SliderCrank(state.a, state.b, state.e, { branch: state.branch }).solve(theta);
    const Bx = pose.Bx[f], By = pose.By[f];
    return { e: y, b: Math.hypot(x - Bx, y - By), branch: x >= Bx ? 1 : -1 };
  };
  return fig;
}

// --- oscillating or rotating guide-bar -------------------------------------------------------

function guideBar(div, d, api, spec, L) {
  const [nA, nB, nD, nE] = spec.names.map((n) => d.names.indexOf(n));
  const state = { a: spec.a, d: spec.d, branch: 1 };
  const theta = Float64Array.from(spec.theta);
  const g = (x, y) => [x / d.grid, -y / d.grid];
  const fig = { state, handleSize: 1.1 * d.unit, handles: [nB, nD].filter((i) => i >= 0).map((i) => d.names[i]) };
  let first = true;
  fig.shown = () => ({ a: state.a, d: state.d });
  fig.fromField = (k, v) => ({ [k]: v });
  fig.compute = () => {
    const a = L.core.positiveLength("a", state.a), dd = L.core.positiveLength("d", state.d);
    // as mech.planar.GuideBar: an oscillating guide only
    if (!(a < dd)) throw new L.LinkageInputError(`Expected \`a\` < \`d\` = ${dd} for an oscillating guide, got ${a}`);
    const reach = spec.reach * (a + dd), n = theta.length, B = new Array(2 * n), E = new Array(2 * n);
    for (let f = 0; f < n; f++) {
      const [psi, , Bx, By] = L.kernel.guide_bar_position(a, dd, theta[f]);
      [B[2 * f], B[2 * f + 1]] = g(Bx, By);
      [E[2 * f], E[2 * f + 1]] = g(dd + reach * Math.cos(psi), reach * Math.sin(psi));
    }
    d.P[nB] = B;
    if (nE >= 0) d.P[nE] = E;
    if (nA >= 0) d.P[nA] = g(0, 0);
    if (nD >= 0) d.P[nD] = g(dd, 0);
    // a helper point on the guide sets the block's direction: the guide's end E serves
    if (first) { d.marks = []; div.querySelectorAll(".mech-mark").forEach((b) => { b.disabled = true; }); first = false; }
  };
  fig.message = () => "";
  fig.readout = () => {
    const { a, d: dd } = state;
    const [swing] = L.kernel.guide_bar_swing(a, dd);
    return { kind: "oscillating guide-bar (the guide swings)",
      limits: `limit positions: swing ${deg(swing)}, K = ${((Math.PI + swing) / (Math.PI - swing)).toFixed(3)}`,
      transmission: "transmission angle 90.0\u00b0 throughout (the block pushes at right angles to the guide)" };
  };
  fig.where = (name, f) => {
    const arr = d.P[d.names.indexOf(name)], j = arr.length === 2 ? 0 : 2 * f;
    return arr[j] === null ? null : [arr[j], arr[j + 1]];
  };
  fig.fromDrag = (name, gx, gy) => {
    const x = gx * d.grid, y = -gy * d.grid, i = d.names.indexOf(name);
    if (i === nB) return { a: Math.hypot(x, y) || state.a };
    if (i === nD) return { d: Math.hypot(x, y) || state.d };
    return null;
  };
  return fig;
}

// --- Hooke's joint ------------------------------------------------------------------------

function hookeJoint(div, d, api, spec, L) {
  const state = { alpha: spec.alpha, branch: 1 };
  const t1 = Float64Array.from(spec.theta);
  const idx = Object.fromEntries(d.names.map((n, i) => [n, i]));
  const c0 = d.c0, s = d.step;
  const grid = (p) => [(p[0] - c0[0]) / s, (p[1] - c0[1]) / s, (p[2] - c0[2]) / s];
  const fig = { state, handleSize: 0, handles: [] };
  let lead = 0;
  fig.shown = () => ({ alpha: state.alpha / DEG });
  fig.fromField = (k, v) => ({ alpha: v * DEG });
  fig.compute = () => {
    const alpha = L.finiteNumber("alpha", state.alpha);
    // as mech.spatial.hooke_output: a shaft angle in [0, pi/2)
    if (!(alpha >= 0 && alpha < Math.PI / 2)) {
      throw new L.LinkageInputError(`Expected \`alpha\` in [0, pi/2) (0 to 90 degrees), got ${alpha}`);
    }
    const ca = Math.cos(alpha), sa = Math.sin(alpha), r = spec.arm, z = [0, sa, ca];
    const put = (name, fn) => { if (name in idx) d.P[idx[name]] = fn; };
    const moving = { e3: [], "-e3": [], a3: [], b3: [] };
    lead = 0;
    for (let f = 0; f < t1.length; f++) {
      const t3 = L.kernel.hooke_output_angle(t1[f], alpha);
      lead = Math.max(lead, Math.abs(t3 - t1[f]));
      const e3 = [Math.cos(t3), ca * Math.sin(t3), -sa * Math.sin(t3)];
      const k3 = z.map((v) => r * v);
      moving.e3.push(...grid(e3));
      moving["-e3"].push(...grid(e3.map((v) => -v)));
      moving.a3.push(...grid(k3.map((v, k) => v + e3[k])));
      moving.b3.push(...grid(k3.map((v, k) => v - e3[k])));
    }
    Object.entries(moving).forEach(([name, arr]) => put(name, arr));
    put("out", grid(z.map((v) => spec.shaft * v)));
    put("k3", grid(z.map((v) => r * v)));
  };
  fig.message = () => "";
  fig.readout = () => {
    const lo = L.kernel.hooke_ratio_terms(Math.PI / 2, state.alpha)[0], hi = L.kernel.hooke_ratio_terms(0.0, state.alpha)[0];
    return { kind: `Hooke's joint, shafts at ${deg(state.alpha)}`,
      limits: `speed ratio \u03c9\u2083/\u03c9\u2081 from ${lo.toFixed(3)} to ${hi.toFixed(3)}`,
      transmission: `the output leads or lags by up to ${deg(lead)}` };
  };
  fig.where = () => null;
  fig.fromDrag = () => null;
  return fig;
}

// --- spherical four-bar -----------------------------------------------------------------------

const dot = (u, v) => u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
const cross = (u, v) => [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
const angleOf = (u, v) => Math.atan2(Math.hypot(...cross(u, v)), dot(u, v));
const tangent = (at, to) => { const k = dot(at, to); return [to[0] - k * at[0], to[1] - k * at[1], to[2] - k * at[2]]; };

/** The input angles of SphericalFourBar.couplerCurve(n): n over the full turn, or spread
 *  over the assembly intervals with a NaN between intervals. */
function curveAngles(rng, n) {
  if (rng.fullTurn) return Array.from({ length: n }, (_, i) => -Math.PI + (2 * Math.PI * i) / (n - 1));
  const theta = [];
  const total = rng.intervals.reduce((acc, [lo, hi]) => acc + (hi - lo), 0) || 1.0;
  rng.intervals.forEach(([lo, hi], k) => {
    const count = Math.max(2, Math.round((n * (hi - lo)) / total));
    const inset = 1e-10 * (hi - lo);
    if (k > 0) theta.push(NaN);
    for (let j = 0; j < count; j++) theta.push(lo + inset + ((hi - inset - (lo + inset)) * j) / (count - 1));
  });
  return theta;
}

function sphericalFourBar(div, d, api, spec, S) {
  const [nA, nB, nC, nD, nP] = spec.names.map((n) => d.names.indexOf(n));
  const state = { a: spec.a, b: spec.b, c: spec.c, d: spec.d, branch: spec.branch, r: spec.coupler[0], g: spec.coupler[1] };
  const theta = Float64Array.from(spec.theta);
  const s = d.step;
  const grid = (p) => (p[0] === p[0] ? [p[0] / s, p[1] / s, p[2] / s] : [null, null, null]);
  const fig = { state, handleSize: 26, handles: [nB, nC, nD, nP].filter((i) => i >= 0).map((i) => d.names[i]) };
  let pose = null, linkage = null, curve = null, first = true, hadGround = false, grids = 0;
  if (spec.drawCurve && nP >= 0 && d.trace.indexOf(nP) < 0) d.trace = d.trace.concat([nP]);
  fig.shown = () => ({ a: state.a / DEG, b: state.b / DEG, c: state.c / DEG, d: state.d / DEG, r: state.r / DEG, g: state.g / DEG });
  fig.fromField = (k, v) => ({ [k]: v * DEG });
  const A = () => grid3(d.P[nA]);
  function grid3(arr) { return [arr[0] * s, arr[1] * s, arr[2] * s]; }
  fig.compute = () => {
    S.classify(state.a, state.b, state.c, state.d); // throws when it assembles nowhere
    linkage = new S.SphericalFourBar(state.a, state.b, state.c, state.d,
      { branch: state.branch, coupler: [state.r, state.g], frame: spec.frame });
    pose = linkage.solve(theta);
    const flat = (list) => list.flatMap(grid);
    if (nB >= 0) d.P[nB] = flat(pose.B);
    if (nC >= 0) d.P[nC] = flat(pose.C);
    if (nP >= 0) d.P[nP] = flat(pose.P);
    if (nD >= 0) d.P[nD] = grid(frameD());
    // the coupler curve over the assembly range, sampled as couplerCurve samples it; one
    // solve gives the curve and the poses of the smallest transmission angle
    const angles = curveAngles(linkage.assemblyRange(), spec.curve);
    const run = linkage.solve(angles.filter((t) => t === t));
    let j = 0;
    const P = angles.map((t) => (t === t ? run.P[j++] : null));
    curve = run;
    d.curves = d.trace.map((i) => (i === nP ? P.map((p) => (p && p[0] === p[0] ? grid(p) : null)) : null));
    if (first) {
      // still curves of the first linkage (its coupler curves, their twins) are stale now
      hadGround = d.still.some((c) => c.c === "mf-fixed");
      d.still = d.still.filter((c) => c.c === "mf-grid");
      grids = d.still.length;
      first = false;
    }
    if (hadGround) {
      // the ground arc A D, as a still curve in grid units
      const a0 = A(), D = frameD(), w = angleOf(a0, D), p = [];
      for (let k = 0; k <= 24; k++) {
        const t = k / 24, fa = Math.sin((1 - t) * w) / Math.sin(w), fb = Math.sin(t * w) / Math.sin(w);
        p.push(...grid([fa * a0[0] + fb * D[0], fa * a0[1] + fb * D[1], fa * a0[2] + fb * D[2]]));
      }
      d.still.length = grids;
      d.still.push({ p, c: "mf-fixed" });
    }
  };
  function frameD() {
    const local = [Math.sin(state.d), 0, Math.cos(state.d)], R = spec.frame;
    return R ? [0, 1, 2].map((k) => R[k][0] * local[0] + R[k][1] * local[1] + R[k][2] * local[2]) : local;
  }
  fig.message = (f) => (!pose || pose.valid[f] ? "" : `At \u03b8 = ${deg(theta[f])} this spherical four-bar cannot be ` +
    "assembled: the arcs BC and CD do not meet (the input does not reach this angle).");
  fig.readout = () => {
    const kind = S.classify(state.a, state.b, state.c, state.d).kind;
    const rng = linkage.assemblyRange();
    const limits = rng.fullTurn ? "the input turns fully"
      : "input between " + rng.intervals.map(([lo, hi]) => `${deg(lo)} and ${deg(hi)}`).join(", ");
    // the smallest angle at C between the arcs to B and D over the curve's poses
    const run = curve, D = frameD();
    let least = Infinity;
    for (let i = 0; i < run.theta.length; i++) {
      if (!run.valid[i]) continue;
      const mu = angleOf(tangent(run.C[i], run.B[i]), tangent(run.C[i], D));
      least = Math.min(least, mu, Math.PI - mu);
    }
    return { kind, limits, transmission: `smallest transmission angle ${deg(least)} (over ${spec.curve} poses)` };
  };
  fig.where = (name, f) => {
    const arr = d.P[d.names.indexOf(name)], j = arr.length === 3 ? 0 : 3 * f;
    if (arr[j] === null) return null;
    const q = api.project([arr[j] * s, arr[j + 1] * s, arr[j + 2] * s]);
    return q[2] < 0 ? null : q; // only handles on the near side of the sphere
  };
  fig.fromDrag = (name, x, y, f) => {
    const w = unproject(api.view(), x, y), i = d.names.indexOf(name);
    const a0 = A();
    if (i === nD) return { d: angleOf(a0, w) };
    if (i === nB) return { a: angleOf(a0, w) };
    pose = pose || new S.SphericalFourBar(state.a, state.b, state.c, state.d,
      { branch: state.branch, coupler: [state.r, state.g], frame: spec.frame }).solve(theta);
    if (!pose.valid[f]) return null;
    const B = pose.B[f], C = pose.C[f];
    if (i === nC) {
      const D = frameD();
      const det = dot(B, cross(D, w));
      return { b: angleOf(B, w), c: angleOf(w, D), branch: det >= 0 ? 1 : -1 };
    }
    if (i === nP) {
      const t = tangent(B, C), u = tangent(B, w);
      return { r: angleOf(B, w), g: Math.atan2(dot(B, cross(t, u)), dot(t, u)) };
    }
    return null;
  };
  return fig;
}
