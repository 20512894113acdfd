// The live function-generation figure of the synthesis chapter: y = log10 x on 1 <= x <= 10
// mapped linearly onto the input and output rotations, three precision points that the
// reader moves (drag them on the error plot or type them), and the four-bar through them
// with its structural error over the whole range, as mech.planar.synthesis.precision_pairs
// designs and checks it. Written by hand; Freudenstein's rows and the lengths come from the
// generated kernels of derivations/planar/function_generation.md, the motion from
// planar.js's FourBar.
//
// `render(state)` returns the figure's HTML (no DOM; the build runs it under Node) and
// `mount(root)` makes it live. A state is {x: [x1, x2, x3], theta0, psi0 (degrees),
// thetaRange, psiRange (degrees, signed), d, at (the x at which the linkage is drawn)}.

import * as fg from "../kernels/function_generation.js";
import { FourBar } from "./planar.js";

const DEG = Math.PI / 180;
const X0 = 1.0, X1 = 10.0;
const target = (x) => Math.log10(x);
const wrap = (a) => Math.atan2(Math.sin(a), Math.cos(a));

/** Input and output rotations of the precision points (the linear map of FunctionMap). */
function rotations(state, x) {
  const yspan = target(X1) - target(X0);
  return [state.thetaRange * DEG * (x - X0) / (X1 - X0), state.psiRange * DEG * (target(x) - target(X0)) / yspan];
}

function solve3(M, b) {
  const A = M.map((row, i) => row.concat([b[i]]));
  for (let k = 0; k < 3; k++) {
    let p = k;
    for (let i = k + 1; i < 3; i++) if (Math.abs(A[i][k]) > Math.abs(A[p][k])) p = i;
    if (A[p][k] === 0) return null;
    [A[k], A[p]] = [A[p], A[k]];
    for (let i = k + 1; i < 3; i++) {
      const f = A[i][k] / A[k][k];
      for (let j = k; j < 4; j++) A[i][j] -= f * A[k][j];
    }
  }
  const x = [0, 0, 0];
  for (let i = 2; i >= 0; i--) {
    let s = A[i][3];
    for (let j = i + 1; j < 3; j++) s -= A[i][j] * x[j];
    x[i] = s / A[i][i];
  }
  return x.every(Number.isFinite) ? x : null;
}

/**
 * The four-bar through the three precision points, simulated over the range: {lengths,
 * theta0, psi0, branch, linkage, xs, error (radians of output, NaN where it cannot be
 * assembled), covers, monotone, pairError} or {error message}.
 */
export function design(state) {
  const xs = state.x.slice().sort((u, v) => u - v);
  if (!xs.every((x) => x >= X0 && x <= X1) || xs[0] === xs[1] || xs[1] === xs[2]) {
    return { problem: `Expected three distinct precision points in [${X0}, ${X1}], got ${state.x.join(", ")}` };
  }
  let t0 = state.theta0 * DEG, p0 = state.psi0 * DEG;
  const pairs = xs.map((x) => rotations(state, x));
  const rows = pairs.map(([X, Y]) => fg.fg_row(t0 + X, p0 + Y));
  const k = solve3(rows.map((r) => r.slice(0, 3)), rows.map((r) => r[3]));
  if (k === null) return { problem: "The three precision points give a singular system: no four-bar through them" };
  const [a, c, bsq] = fg.fg_lengths(k[0], k[1], k[2], state.d);
  if (!(bsq > 0) || !Number.isFinite(a) || !Number.isFinite(c)) {
    return { problem: "No real four-bar passes through these points (the coupler's squared length is not positive)" };
  }
  // a negative length is that link turned by pi (mech's _from_signed)
  if (a < 0) t0 += Math.PI;
  if (c < 0) p0 += Math.PI;
  const lengths = [Math.abs(a), Math.sqrt(bsq), Math.abs(c), state.d];
  const [xf, yf] = pairs[0];
  const B = [lengths[0] / state.d * Math.cos(t0 + xf), lengths[0] / state.d * Math.sin(t0 + xf)];
  const C = [1 + lengths[2] / state.d * Math.cos(p0 + yf), lengths[2] / state.d * Math.sin(p0 + yf)];
  const cross = (1 - B[0]) * (C[1] - B[1]) - (0 - B[1]) * (C[0] - B[0]);
  const branch = cross >= 0 ? 1 : -1;
  let linkage;
  try {
    linkage = new FourBar(...lengths, { branch });
  } catch (err) {
    return { problem: err.message };
  }
  const output = (x) => {
    const [X] = rotations(state, x);
    const pose = linkage.solve([t0 + X]);
    if (!pose.valid[0]) return { psi: NaN, pose: null };
    return { psi: Math.atan2(pose.Cy[0], pose.Cx[0] - state.d), pose };
  };
  const samples = 241;
  const grid = [], error = [];
  let covers = true, monotone = true, last = null;
  // the drawing's bounds: the ground and every position of B and C over the range
  const box = [Math.min(0, state.d), 0, Math.max(0, state.d), 0];
  for (let i = 0; i < samples; i++) {
    const x = X0 + (X1 - X0) * i / (samples - 1);
    const { psi, pose } = output(x);
    if (pose) {
      for (const [u, v] of [[pose.Bx[0], pose.By[0]], [pose.Cx[0], pose.Cy[0]]]) {
        box[0] = Math.min(box[0], u); box[1] = Math.min(box[1], v);
        box[2] = Math.max(box[2], u); box[3] = Math.max(box[3], v);
      }
    }
    const [, Y] = rotations(state, x);
    const e = wrap(psi - p0 - Y);
    grid.push(x);
    error.push(e);
    if (!Number.isFinite(psi)) covers = false;
    else if (last !== null && Math.sign(wrap(psi - last)) * Math.sign(state.psiRange) < 0) monotone = false;
    if (Number.isFinite(psi)) last = psi;
  }
  const pairError = Math.max(...xs.map((x, i) => Math.abs(wrap(output(x).psi - p0 - pairs[i][1]))));
  return { lengths, theta0: t0, psi0: p0, branch, linkage, xs, grid, error, covers, monotone, pairError, output, box };
}

// --- drawing --------------------------------------------------------------------------------

const f = (v) => (Number.isFinite(v) ? +v.toFixed(3) : 0);
const esc = (s) => String(s).replace(/&/g, "&amp;").replace(/</g, "&lt;").replace(/>/g, "&gt;");

// the error plot: x from 1 to 10 across 0..300, error (in units of y) over -E..E down 0..160
const PLOT = { w: 300, h: 160 };

function errorScale(sol, state) {
  const perY = Math.abs(state.psiRange * DEG);
  const finite = sol.error.filter(Number.isFinite).map((e) => Math.abs(e / perY));
  return Math.max(1e-6, ...finite) * 1.15;
}

/** Markup of the two SVG panels: the linkage at x = state.at, and the structural error. */
export function renderFigure(state, sol) {
  if (sol.problem) return { linkage: "", plot: "" };
  const d = state.d;
  const pose = sol.output(state.at).pose;
  const L = [];
  const pt = (x, y) => `${f(x)},${f(-y)}`;
  for (const x of sol.xs) {
    const p = sol.output(x).pose;
    if (p) L.push(`<polyline class="mech-fg-ghost" points="${[[0, 0], [p.Bx[0], p.By[0]], [p.Cx[0], p.Cy[0]], [d, 0]].map(([u, v]) => pt(u, v)).join(" ")}" fill="none"/>`);
  }
  if (pose) {
    L.push(`<polyline class="mech-design-linkage" points="${[[0, 0], [pose.Bx[0], pose.By[0]], [pose.Cx[0], pose.Cy[0]], [d, 0]].map(([u, v]) => pt(u, v)).join(" ")}" fill="none"/>`);
  }
  L.push(`<line class="mech-dyad" x1="0" y1="0" x2="${f(d)}" y2="0"/>`);
  const perY = Math.abs(state.psiRange * DEG);
  const E = errorScale(sol, state);
  const px = (x) => (PLOT.w * (x - X0)) / (X1 - X0);
  const py = (e) => PLOT.h / 2 - (PLOT.h / 2) * (e / perY) / E;
  const P = [`<line class="mech-fg-axis" x1="0" y1="${PLOT.h / 2}" x2="${PLOT.w}" y2="${PLOT.h / 2}"/>`];
  let path = "", pen = false;
  sol.grid.forEach((x, i) => {
    const e = sol.error[i];
    if (!Number.isFinite(e)) { pen = false; return; }
    path += `${pen ? "L" : "M"}${f(px(x))} ${f(py(e))}`;
    pen = true;
  });
  P.push(`<path class="mech-error-curve" d="${path}"/>`);
  state.x.forEach((x, i) => P.push(`<circle class="mech-handle" data-handle="x" data-index="${i}" cx="${f(px(x))}" cy="${PLOT.h / 2}" r="5"><title>precision point x${i + 1} = ${x.toFixed(3)}</title></circle>`));
  P.push(`<line class="mech-fg-at" x1="${f(px(state.at))}" y1="0" x2="${f(px(state.at))}" y2="${PLOT.h}"/>`);
  P.push(`<text x="2" y="12" font-size="10">+${E.toPrecision(2)}</text><text x="2" y="${PLOT.h - 3}" font-size="10">-${E.toPrecision(2)}</text>`);
  return { linkage: L.join(""), plot: P.join("") };
}

/** The view box (SVG units, y down) around the linkage's motion, with a margin. */
function linkageBox(state, sol) {
  const [x0, y0, x1, y1] = sol.problem ? [0, 0, state.d, 0] : sol.box;
  const pad = 0.08 * Math.max(x1 - x0, y1 - y0, state.d);
  return [x0 - pad, -y1 - pad, x1 - x0 + 2 * pad, y1 - y0 + 2 * pad].map(f).join(" ");
}

export function renderReport(state, sol) {
  if (sol.problem) return `<p class="mech-design-error">${esc(sol.problem)}</p>`;
  const perY = Math.abs(state.psiRange * DEG);
  const worst = Math.max(...sol.error.map((e) => (Number.isFinite(e) ? Math.abs(e) : 0))) / perY;
  const [a, b, c, d] = sol.lengths;
  const notes = [];
  if (!sol.covers) notes.push("<strong>it cannot be assembled over the whole range</strong> (the curve breaks off)");
  if (!sol.monotone) notes.push("<strong>its output turns back</strong> inside the range");
  return `<p>Lengths a, b, c, d = ${a.toFixed(3)}, ${b.toFixed(3)}, ${c.toFixed(3)}, ${d.toFixed(3)}; start angles ` +
    `${(wrap(sol.theta0) / DEG).toFixed(2)}° and ${(wrap(sol.psi0) / DEG).toFixed(2)}°; assembly branch ${sol.branch > 0 ? "+1" : "-1"}. ` +
    `Largest structural error over 1 ≤ x ≤ 10: ${worst.toPrecision(3)} in y; at the precision points ` +
    `${sol.pairError.toExponential(1)} rad. ${notes.length ? `The linkage ${notes.join(" and ")}.` : "One branch covers the range."}</p>`;
}

function inputs(state) {
  const field = (name, label, value, step) => `<label>${label} <input type="number" step="${step}" data-field="${name}" value="${+value.toFixed(6)}"></label>`;
  return state.x.map((x, i) => field(`x${i}`, `x${i + 1}`, x, "any")).join(" ") + " " +
    field("theta0", "input start (deg)", state.theta0, "1") + " " + field("psi0", "output start (deg)", state.psi0, "1") + " " +
    `<label>Output turns <select data-field="sense"><option value="-1"${state.psiRange < 0 ? " selected" : ""}>clockwise</option>` +
    `<option value="1"${state.psiRange > 0 ? " selected" : ""}>counter-clockwise</option></select></label> ` +
    `<label>Draw at x <input type="range" min="1" max="10" step="0.01" value="${state.at}" data-field="at"></label>`;
}

export function render(state) {
  const sol = design(state);
  const parts = renderFigure(state, sol);
  return `<div class="mech-design-controls" data-part="inputs">${inputs(state)}</div>` +
    `<div style="display:flex;flex-wrap:wrap;gap:1em"><svg class="mech-fg-linkage" viewBox="${linkageBox(state, sol)}" style="flex:1 1 18em" ` +
    `role="img" aria-label="The four-bar at the chosen x, and at the precision points (thin)">${parts.linkage}</svg>` +
    `<svg class="mech-fg-plot" viewBox="0 0 ${PLOT.w} ${PLOT.h}" style="flex:1 1 18em" role="img" ` +
    `aria-label="Structural error in y against x from 1 to 10; the dots are the precision points">${parts.plot}</svg></div>` +
    `<div data-part="report">${renderReport(state, sol)}</div>`;
}

export function mount(root) {
  const state = JSON.parse(root.dataset.state);
  // drawn again from the state: the build's drawing may come from an older script (the
  // notebook cache keys on the page's code, not on this file)
  root.innerHTML = render(state);
  const link = root.querySelector("svg.mech-fg-linkage"), plot = root.querySelector("svg.mech-fg-plot");
  const redraw = () => {
    const sol = design(state);
    const parts = renderFigure(state, sol);
    link.innerHTML = parts.linkage;
    link.setAttribute("viewBox", linkageBox(state, sol));
    plot.innerHTML = parts.plot;
    root.querySelector("[data-part=report]").innerHTML = renderReport(state, sol);
    root.dataset.lengths = sol.problem ? "" : JSON.stringify(sol.lengths);
  };
  root.addEventListener("input", (event) => {
    const name = event.target.dataset.field;
    const v = Number(event.target.value);
    if (!name || !Number.isFinite(v)) return;
    if (name.startsWith("x")) state.x[+name.slice(1)] = v;
    else if (name === "sense") state.psiRange = v * Math.abs(state.psiRange);
    else state[name] = v;
    redraw();
  });
  let drag = null;
  plot.addEventListener("pointerdown", (event) => {
    if (event.target.dataset.handle !== "x") return;
    drag = +event.target.dataset.index;
    plot.setPointerCapture(event.pointerId);
    event.preventDefault();
  });
  plot.addEventListener("pointermove", (event) => {
    if (drag === null) return;
    const p = new DOMPoint(event.clientX, event.clientY).matrixTransform(plot.getScreenCTM().inverse());
    state.x[drag] = Math.min(X1, Math.max(X0, X0 + (X1 - X0) * p.x / PLOT.w));
    const field = root.querySelector(`[data-field=x${drag}]`);
    if (field) field.value = +state.x[drag].toFixed(6);
    redraw();
  });
  const end = () => { drag = null; };
  plot.addEventListener("pointerup", end);
  plot.addEventListener("pointercancel", end);
  redraw();
}

if (typeof document !== "undefined") {
  for (const root of document.querySelectorAll(".mech-live-design.mech-live-fg[data-state]")) mount(root);
}
