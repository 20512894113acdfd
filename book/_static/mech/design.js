// The live rigid-body guidance figure of the synthesis chapter: the reader sets two to five
// poses (drag a pose's dot to move it, its square to turn it, or type its numbers) and the
// page shows the poles, the circle-point and centre-point curves (four poses) or the
// Burmester points (five), and every four-bar made of two of the dyads, moved through the
// poses, with its defects. Written by hand; the design equations are the generated kernels'
// (through guidance.js and burmester.js) and the analysis is planar.js's FourBar.
//
// `render(state)` returns the figure's HTML as a string (no DOM): the build runs it under
// Node to write the initial state into the page, and `mount(root)` redraws with it in the
// browser. A state is {poses: [[theta_deg, x, y], ...] (five), n: 2..5, pick (the design
// drawn), t (its motion, 0..1), pivots (two moving pivots for two or three poses), choose
// (two places, 0..1, on the four-pose curve)}.

import { FourBar, grashof } from "./planar.js";
import { dyadForCirclePoint, pole } from "./guidance.js";
import { burmester, circlePointCurve } from "./burmester.js";

const DEG = Math.PI / 180;
const TURN = 2 * Math.PI;

// --- the designs ------------------------------------------------------------------------

const wrap = (a) => Math.atan2(Math.sin(a), Math.cos(a));
const rot = (t, [x, y]) => [Math.cos(t) * x - Math.sin(t) * y, Math.sin(t) * x + Math.cos(t) * y];

/**
 * The four-bar with `crank` driven and `rocker` as output (mech.planar.synthesis
 * guidance_fourbars), or null when the lengths make no four-bar. Its defects: `branch` (C
 * changes side of the line B->D between poses), `order` (the input cannot meet the poses
 * in order turning one way by less than a turn), `circuit` (it can, but the linkage cannot
 * be assembled all along that turn: the poses lie on different circuits).
 */
export function candidate(th, ds, crank, rocker) {
  const A = crank.centrePoint, D = rocker.centrePoint;
  const zB = crank.circlePoint, zC = rocker.circlePoint;
  const lengths = [crank.length, Math.hypot(zC[0] - zB[0], zC[1] - zB[1]), rocker.length, Math.hypot(D[0] - A[0], D[1] - A[1])];
  if (!lengths.every((x) => Number.isFinite(x) && x > 0)) return null;
  const unit = Math.max(...lengths);
  const angle = Math.atan2(D[1] - A[1], D[0] - A[0]);
  const scaled = lengths.map((x) => x / unit);
  const place = (z, k) => {
    const w = rot(th[k], z);
    return rot(-angle, [(w[0] + ds[k][0] - A[0]) / unit, (w[1] + ds[k][1] - A[1]) / unit]);
  };
  const B = th.map((_, k) => place(zB, k)), C = th.map((_, k) => place(zC, k));
  const thetaIn = B.map(([x, y]) => Math.atan2(y, x));
  const dx = scaled[3];
  const side = B.map((b, k) => Math.sign((dx - b[0]) * (C[k][1] - b[1]) - -b[1] * (C[k][0] - b[0])));
  const branch = side[0] !== 0 ? side[0] : 1;
  const hinge = Math.atan2(zC[1] - zB[1], zC[0] - zB[0]);
  const body = rot(-hinge, [-zB[0], -zB[1]]);
  let model;
  try {
    // FourBar refuses one link at least as long as the other three together
    model = new FourBar(...scaled, { branch, coupler: [body[0] / unit, body[1] / unit] });
  } catch (err) {
    return null;
  }
  // the input's path each way from the first pose to the last: its ends and the angles
  // k pi inside it, where the diagonal BD is extreme (mech._driving.input_travel)
  const paths = [1, -1].map((sense) => {
    let travel = 0;
    for (let k = 1; k < th.length; k++) travel += ((sense * (thetaIn[k] - thetaIn[k - 1])) % TURN + TURN) % TURN;
    if (travel >= TURN) return null;
    const start = thetaIn[0];
    const [lo, hi] = sense > 0 ? [start, start + travel] : [start - travel, start];
    const critical = [lo, hi];
    for (let m = Math.ceil(lo / Math.PI); m <= Math.floor(hi / Math.PI); m++) critical.push(m * Math.PI);
    return { sense, travel, critical };
  });
  // one solve for the poses and both paths
  const angles = thetaIn.concat(...paths.map((p) => (p ? p.critical : [])));
  const pose = model.solve(angles);
  let poseError = 0;
  for (let k = 0; k < th.length; k++) {
    const P = rot(angle, [pose.Px[k], pose.Py[k]]);
    const turned = Math.atan2(pose.Cy[k] - pose.By[k], pose.Cx[k] - pose.Bx[k]) + angle - hinge;
    poseError = Math.max(poseError, Math.hypot(P[0] - (ds[k][0] - A[0]) / unit, P[1] - (ds[k][1] - A[1]) / unit),
      Math.abs(wrap(turned - th[k])));
  }
  if (!pose.valid.slice(0, th.length).every(Boolean)) poseError = Infinity;
  let direction = 0, travelled = 0, offset = th.length;
  const orderable = paths.some((p) => p !== null);
  for (const p of paths) {
    if (p === null) continue;
    const ok = pose.valid.slice(offset, offset + p.critical.length).every(Boolean);
    offset += p.critical.length;
    if (ok && direction === 0) {
      direction = p.sense;
      travelled = p.travel;
    }
  }
  const defects = {
    branch: !side.every((s) => s === side[0]),
    order: !orderable,
    circuit: orderable && direction === 0,
  };
  const kind = grashof(...lengths).kind;
  return {
    lengths, kind, defects, poseError, direction, travel: travelled, thetaIn, angle, unit, A, model,
    passes: !defects.branch && !defects.order && !defects.circuit && poseError <= 1e-9,
  };
}

/** The ground-frame joints A, B, C, D and the coupler origin P at input angle `theta`. */
export function placedJoints(design, theta) {
  const pose = design.model.solve([theta]);
  if (!pose.valid[0]) return null;
  const to = (x, y) => {
    const w = rot(design.angle, [x * design.unit, y * design.unit]);
    return [design.A[0] + w[0], design.A[1] + w[1]];
  };
  return { A: design.A, B: to(pose.Bx[0], pose.By[0]), C: to(pose.Cx[0], pose.Cy[0]), D: to(design.model.d, 0),
    P: to(pose.Px[0], pose.Py[0]) };
}

function checkedState(state) {
  const n = state.n;
  const poses = state.poses.slice(0, n);
  return { n, th: poses.map((p) => p[0] * DEG), ds: poses.map((p) => [p[1], p[2]]) };
}

/** Everything the figure shows for `state`: poles, dyads, curves, designs, or an error. */
export function solveState(state) {
  const { n, th, ds } = checkedState(state);
  const out = { n, th, ds, poles: [], dyads: [], curve: null, designs: [], error: null };
  try {
    for (let j = 0; j < n; j++) {
      for (let k = j + 1; k < n; k++) {
        if (Math.abs(wrap(th[k] - th[j])) > 0) out.poles.push({ name: `P${j + 1}${k + 1}`, at: pole(th[j], ds[j], th[k], ds[k]) });
      }
    }
    if (n <= 3) {
      out.dyads = state.pivots.map((Z) => {
        const z = rot(-th[0], [Z[0] - ds[0][0], Z[1] - ds[0][1]]);
        const dy = dyadForCirclePoint(th, ds, z);
        return { circlePoint: dy.circlePoint, centrePoint: dy.centrePoint, movingPivot: dy.circlePoint1, length: dy.length };
      });
    } else if (n === 4) {
      const curve = circlePointCurve(th, ds, { samples: 180 });
      out.curve = curve;
      const points = [];
      curve.valid.forEach((pair, i) => pair.forEach((ok, k) => {
        if (ok) points.push({ circlePoint: curve.circlePoint[i][k], centrePoint: curve.centrePoint[i][k],
          movingPivot: curve.movingPivot[i][k], length: curve.length[i][k] });
      }));
      out.curvePoints = points;
      if (points.length >= 2) {
        const at = (s) => points[Math.min(points.length - 1, Math.max(0, Math.round(s * (points.length - 1))))];
        out.dyads = [at(state.choose[0]), at(state.choose[1])];
      }
    } else {
      const found = burmester(th, ds);
      out.burmester = found;
      out.dyads = found.dyads;
    }
    out.dyads.forEach((crank, i) => out.dyads.forEach((rocker, j) => {
      if (i === j) return;
      const design = candidate(th, ds, crank, rocker);
      if (design) out.designs.push({ input: i + 1, output: j + 1, ...design });
    }));
  } catch (err) {
    out.error = err.message;
  }
  return out;
}

// --- drawing ------------------------------------------------------------------------------

const f = (v) => (Number.isFinite(v) ? +v.toFixed(3) : 0);
const esc = (s) => String(s).replace(/&/g, "&amp;").replace(/</g, "&lt;").replace(/>/g, "&gt;").replace(/"/g, "&quot;");
const pt = ([x, y]) => `${f(x)},${f(-y)}`;

/** The view box [x, y, w, h] (SVG units, y down) around the five poses of `state`. */
export function viewBox(state) {
  const xs = state.poses.map((p) => p[1]), ys = state.poses.map((p) => -p[2]);
  const size = Math.max(Math.max(...xs) - Math.min(...xs), Math.max(...ys) - Math.min(...ys), 1e-9);
  const pad = 1.2 * size;
  return [Math.min(...xs) - pad, Math.min(...ys) - pad, Math.max(...xs) - Math.min(...xs) + 2 * pad,
    Math.max(...ys) - Math.min(...ys) + 2 * pad];
}

function bodyShape(theta, d, L) {
  const pts = [[0, 0], [L, 0], [0.25 * L, 0.3 * L]].map((z) => {
    const w = rot(theta, z);
    return [w[0] + d[0], w[1] + d[1]];
  });
  return pts.map(pt).join(" ");
}

function dots(points, r, cls) {
  if (!points.length) return "";
  const d = points.map(([x, y]) => `M${f(x)} ${f(-y)}h0`).join("");
  return `<path class="${cls}" d="${d}" stroke-width="${f(2 * r)}" stroke-linecap="round" fill="none"/>`;
}

/** The SVG's inner markup for `state` and its solution. */
export function renderFigure(state, sol) {
  const box = viewBox(state);
  const L = 0.06 * Math.max(box[2], box[3]);
  const r = 0.008 * Math.max(box[2], box[3]);
  const parts = [];
  if (sol.curve) {
    const moving = [], centre = [];
    sol.curvePoints.forEach((p) => { moving.push(p.movingPivot); centre.push(p.centrePoint); });
    parts.push(dots(centre, 0.35 * r, "mech-centre-curve"), dots(moving, 0.35 * r, "mech-circle-curve"));
  }
  const pick = sol.designs[Math.min(state.pick, sol.designs.length - 1)];
  if (pick) {
    // a design that cannot make the move is drawn in the first pose only
    const theta = pick.direction !== 0 ? pick.thetaIn[0] + pick.direction * state.t * pick.travel : pick.thetaIn[0];
    const j = placedJoints(pick, theta);
    if (j) {
      parts.push(`<polyline class="mech-design-linkage" points="${[j.A, j.B, j.C, j.D].map(pt).join(" ")}" fill="none"/>`);
      parts.push(`<polygon class="mech-design-coupler" points="${[j.B, j.C, j.P].map(pt).join(" ")}"/>`);
    }
  }
  sol.ds.forEach((d, k) => {
    parts.push(`<polygon class="mech-pose" points="${bodyShape(sol.th[k], d, L)}"/>`);
    const tip = rot(sol.th[k], [L, 0]);
    parts.push(`<circle class="mech-handle" data-handle="move" data-pose="${k}" cx="${f(d[0])}" cy="${f(-d[1])}" r="${f(r)}"/>`);
    parts.push(`<rect class="mech-handle" data-handle="turn" data-pose="${k}" x="${f(d[0] + tip[0] - r)}" ` +
      `y="${f(-(d[1] + tip[1]) - r)}" width="${f(2 * r)}" height="${f(2 * r)}"/>`);
    parts.push(`<text x="${f(d[0] - 2.5 * r)}" y="${f(-d[1] - 1.5 * r)}" font-size="${f(3 * r)}" text-anchor="end">${k + 1}</text>`);
  });
  for (const p of sol.poles) {
    parts.push(`<circle class="mech-pole" cx="${f(p.at[0])}" cy="${f(-p.at[1])}" r="${f(0.7 * r)}"><title>${p.name}</title></circle>`);
  }
  sol.dyads.forEach((dy, i) => {
    parts.push(`<line class="mech-dyad" x1="${f(dy.centrePoint[0])}" y1="${f(-dy.centrePoint[1])}" ` +
      `x2="${f(dy.movingPivot[0])}" y2="${f(-dy.movingPivot[1])}"/>`);
    parts.push(`<circle class="mech-centre-point" cx="${f(dy.centrePoint[0])}" cy="${f(-dy.centrePoint[1])}" r="${f(r)}"/>`);
    const pivot = sol.n <= 3 ? ` class="mech-handle mech-circle-point" data-handle="pivot" data-pivot="${i}"`
      : ' class="mech-circle-point"';
    parts.push(`<circle${pivot} cx="${f(dy.movingPivot[0])}" cy="${f(-dy.movingPivot[1])}" r="${f(r)}"/>`);
    parts.push(`<text x="${f(dy.centrePoint[0] + 1.5 * r)}" y="${f(-dy.centrePoint[1] + 3.5 * r)}" font-size="${f(3 * r)}">A${i + 1}</text>`);
  });
  return parts.join("");
}

const yesNo = (bad) => (bad ? "<strong>yes</strong>" : "no");

/** The report under the figure: the dyads, every four-bar with its defects, and notes. */
export function renderReport(state, sol) {
  if (sol.error) return `<p class="mech-design-error">No design for these poses: ${esc(sol.error)}</p>`;
  const lines = [];
  const what = sol.n === 5
    ? `${sol.dyads.length} real Burmester dyads (${sol.burmester.nComplex} complex, ${sol.burmester.nInfinite} at infinity)`
    : sol.n === 4 ? `two dyads chosen on the curves (${sol.curvePoints.length} traced points)`
      : "two dyads through the moving pivots you place";
  lines.push(`<p>${sol.n} poses; ${sol.poles.length} poles; ${what}.</p>`);
  if (sol.dyads.length) {
    lines.push("<table class=\"mech-dyads\"><thead><tr><th>dyad</th><th>centre point A</th><th>moving pivot at pose 1</th>" +
      "<th>crank length</th></tr></thead><tbody>");
    sol.dyads.forEach((dy, i) => lines.push(`<tr><td>${i + 1}</td><td>(${dy.centrePoint.map((v) => v.toFixed(3)).join(", ")})</td>` +
      `<td>(${dy.movingPivot.map((v) => v.toFixed(3)).join(", ")})</td><td>${dy.length.toFixed(3)}</td></tr>`));
    lines.push("</tbody></table>");
  }
  if (sol.designs.length) {
    lines.push("<table class=\"mech-designs\"><thead><tr><th>four-bar (input, output)</th><th>a, b, c, d</th><th>type</th>" +
      "<th>branch defect</th><th>order defect</th><th>circuit defect</th><th>usable</th></tr></thead><tbody>");
    sol.designs.forEach((dz) => lines.push(`<tr data-usable="${dz.passes}"><td>${dz.input}, ${dz.output}</td>` +
      `<td>${dz.lengths.map((v) => v.toFixed(2)).join(", ")}</td><td>${dz.kind}</td><td>${yesNo(dz.defects.branch)}</td>` +
      `<td>${yesNo(dz.defects.order)}</td><td>${yesNo(dz.defects.circuit)}</td><td>${dz.passes ? "yes" : "no"}</td></tr>`));
    lines.push("</tbody></table>");
  } else {
    lines.push("<p>No pair of these dyads makes a four-bar.</p>");
  }
  return lines.join("");
}

function renderPoseTable(state) {
  const rows = state.poses.map((p, k) => `<tr${k < state.n ? "" : " hidden"}><td>${k + 1}</td>` +
    ["x", "y", "angle (deg)"].map((name, j) => `<td><input type="number" step="any" data-pose="${k}" data-field="${j === 2 ? 0 : j + 1}" ` +
      `aria-label="pose ${k + 1} ${name}" value="${+p[j === 2 ? 0 : j + 1].toFixed(6)}"></td>`).join("") + "</tr>");
  return "<table class=\"mech-pose-table\"><thead><tr><th>pose</th><th>x</th><th>y</th><th>angle (deg)</th></tr></thead>" +
    `<tbody>${rows.join("")}</tbody></table>`;
}

/** The whole figure as HTML (the build writes it; `mount` redraws its parts). */
export function render(state) {
  const sol = solveState(state);
  const box = viewBox(state).map(f).join(" ");
  const options = sol.designs.map((dz, i) => `<option value="${i}"${i === state.pick ? " selected" : ""}>` +
    `${dz.input} drives, ${dz.output} follows</option>`).join("");
  return `<div class="mech-design-controls"><label>Poses <select data-control="n">` +
    [2, 3, 4, 5].map((n) => `<option${n === state.n ? " selected" : ""}>${n}</option>`).join("") + "</select></label> " +
    `<label>Four-bar <select data-control="pick">${options}</select></label> ` +
    `<label>Motion <input type="range" min="0" max="1" step="0.005" value="${state.t}" data-control="t"></label>` +
    '<button type="button" data-control="play">Play</button>' +
    `<span data-part="choose"${state.n === 4 ? "" : " hidden"}> <label>Dyad 1 on the curve <input type="range" min="0" max="1" step="0.002" ` +
    `value="${state.choose[0]}" data-control="choose0"></label> <label>Dyad 2 <input type="range" min="0" max="1" ` +
    `step="0.002" value="${state.choose[1]}" data-control="choose1"></label></span></div>` +
    `<svg class="mech-design-svg" viewBox="${box}" role="img" aria-label="The poses, poles, dyads and the chosen four-bar">` +
    `${renderFigure(state, sol)}</svg>` +
    `<div data-part="poses">${renderPoseTable(state)}</div><div data-part="report">${renderReport(state, sol)}</div>`;
}

// --- in the browser ------------------------------------------------------------------------

/** Make the figure in `root` live; its initial state is in root.dataset.state. */
export function mount(root) {
  const state = JSON.parse(root.dataset.state);
  // drawn again from the state: the build's drawing may come from an older script (the
  // notebook cache keys on the page's code, not on this file)
  root.innerHTML = render(state);
  const svg = () => root.querySelector("svg");
  let sol = null;
  // `same`: only the motion or the chosen design changed, the solution stands
  const redraw = (all, same = false) => {
    if (!same || sol === null) sol = solveState(state);
    svg().innerHTML = renderFigure(state, sol);
    root.querySelector("[data-part=report]").innerHTML = renderReport(state, sol);
    if (all) {
      root.querySelector("[data-part=poses]").innerHTML = renderPoseTable(state);
      root.querySelector("[data-part=choose]").hidden = state.n !== 4;
      const pick = root.querySelector("[data-control=pick]");
      pick.innerHTML = sol.designs.map((dz, i) => `<option value="${i}">${dz.input} drives, ${dz.output} follows</option>`).join("");
      state.pick = Math.min(state.pick, Math.max(0, sol.designs.length - 1));
      pick.value = String(state.pick);
    }
    // for readers' tools and the browser test: the dyads found, in numbers
    root.dataset.dyads = JSON.stringify(sol.dyads.map((dy) => [dy.circlePoint, dy.centrePoint]));
    root.dataset.error = sol.error || "";
  };
  root.addEventListener("input", (event) => {
    const el = event.target;
    if (el.dataset.pose !== undefined) {
      const v = Number(el.value);
      if (Number.isFinite(v)) state.poses[+el.dataset.pose][+el.dataset.field] = v;
      redraw(false);
      // the designs and their menu change with the poses
      const pick = root.querySelector("[data-control=pick]");
      pick.innerHTML = sol.designs.map((dz, i) => `<option value="${i}">${dz.input} drives, ${dz.output} follows</option>`).join("");
      pick.value = String(Math.min(state.pick, Math.max(0, sol.designs.length - 1)));
      return;
    }
    const c = el.dataset.control;
    if (c === "n") {
      state.n = Number(el.value);
      state.pick = 0;
      redraw(true);
    } else if (c === "pick") {
      state.pick = Number(el.value);
      redraw(false, true);
    } else if (c === "t") {
      state.t = Number(el.value);
      redraw(false, true);
    } else if (c === "choose0" || c === "choose1") {
      state.choose[c === "choose0" ? 0 : 1] = Number(el.value);
      redraw(true);
    }
  });
  let playing = null;
  root.querySelector("[data-control=play]").addEventListener("click", (event) => {
    if (playing !== null) {
      cancelAnimationFrame(playing);
      playing = null;
      event.target.textContent = "Play";
      return;
    }
    event.target.textContent = "Pause";
    let last = null;
    const step = (now) => {
      // from the first pose to the last in three seconds, then again
      if (last !== null) state.t = (state.t + (now - last) / 3000) % 1;
      last = now;
      root.querySelector("[data-control=t]").value = String(state.t);
      redraw(false, true);
      playing = requestAnimationFrame(step);
    };
    playing = requestAnimationFrame(step);
  });
  let drag = null;
  const world = (event) => {
    const m = svg().getScreenCTM().inverse();
    const p = new DOMPoint(event.clientX, event.clientY).matrixTransform(m);
    return [p.x, -p.y];
  };
  svg().addEventListener("pointerdown", (event) => {
    const h = event.target.dataset && event.target.dataset.handle;
    if (!h) return;
    drag = { handle: h, pose: +event.target.dataset.pose, pivot: +event.target.dataset.pivot };
    try {
      svg().setPointerCapture(event.pointerId);
    } catch (err) {
      // a pointer the browser does not track (a synthetic event): the drag works uncaptured
    }
    event.preventDefault();
  });
  svg().addEventListener("pointermove", (event) => {
    if (!drag) return;
    const [x, y] = world(event);
    if (drag.handle === "move") {
      state.poses[drag.pose][1] = x;
      state.poses[drag.pose][2] = y;
    } else if (drag.handle === "turn") {
      const p = state.poses[drag.pose];
      p[0] = Math.atan2(y - p[2], x - p[1]) / DEG;
    } else if (drag.handle === "pivot") {
      state.pivots[drag.pivot] = [x, y];
    }
    redraw(false);
  });
  const end = () => {
    if (drag) {
      drag = null;
      redraw(true);
    }
  };
  svg().addEventListener("pointerup", end);
  svg().addEventListener("pointercancel", end);
  redraw(true);
}

if (typeof document !== "undefined") {
  for (const root of document.querySelectorAll(".mech-live-design:not(.mech-live-fg)[data-state]")) mount(root);
}
