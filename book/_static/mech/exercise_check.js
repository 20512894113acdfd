// The answer check of the exercise pages: the rules of `python -m mech.exercises check`
// (mech/exercises/_grade.py: parse_answer, judge) in the page. The answers themselves were
// computed when the book was built (book/_ext/exercise_check.py writes one JSON file per
// page, seeds 0 to 99, with the unit table); here are only the reading of a number with its
// unit, the conversion to the quantity's unit, and the comparison with the tolerance.

const NUMBER = /^\s*([-+\u2212]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$/;
const CASE_KEPT = new Set(["N", "kN", "m", "mm", "cm"]);

/** A unit spelling as the table writes it, or null (mech.exercises._grade._unit_key). */
function unitKey(units, text) {
  const t = text.trim().replace(/\s+/g, " ");
  if (Object.prototype.hasOwnProperty.call(units, t)) return t;
  for (const k of Object.keys(units)) {
    if (!CASE_KEPT.has(k) && k.toLowerCase() === t.toLowerCase()) return k;
  }
  return null;
}

const pyRepr = (s) => (s.includes("'") && !s.includes('"') ? `"${s}"` : `'${s.replace(/'/g, "\\'")}'`);

/**
 * `text` (a number with an optional unit) as a value in `unit`, the quantity's own unit:
 * {value} or {why} (mech.exercises._grade.parse_answer and convert).
 */
export function parseAnswer(rules, text, unit) {
  const m = NUMBER.exec(text);
  const bad = { why: `Expected \`text\` to be a number with an optional unit, got ${pyRepr(text)}` };
  if (!m) return bad;
  if (m[2] !== "" && "0123456789.,+-\u2212".includes(m[2][0])) return bad;
  const value = Number(m[1].replace("\u2212", "-"));
  // "1e400" reads as Infinity: refused, as check refuses it
  if (!Number.isFinite(value)) return { why: `Expected \`text\` to be a finite number, got ${pyRepr(text)}` };
  const spelt = unitKey(rules.units, m[2]);
  if (spelt === null) {
    return { why: "Expected `text` in a known unit (deg, rad, mm, m, N, N m, N mm, m/s, m/s^2, rad/s, rpm ...), " +
      `got ${pyRepr(text)}` };
  }
  const [kind, factor] = rules.units[spelt];
  const want = rules.kinds[unit] || "number";
  if (!m[2]) return { value };
  if (kind !== want) {
    const names = rules.shown[want] || "no unit";
    const article = "aeiou".includes(want[0]) ? "an" : "a";
    return { why: `Expected ${article} ${want} (${names || "no unit"}), got ${pyRepr(text)} (a ${kind})` };
  }
  const base = (rules.units[unit] || [want, 1.0])[1];
  return { value: (value * factor) / base };
}

/** Grade one answer (mech.exercises._grade.judge): {status, right, why, tolerance, given}. */
export function judge(rules, quantity, value, text) {
  const tol = rules.rtol * Math.abs(value) + rules.atol;
  if (text == null || !String(text).trim()) return { status: "missing", right: false, why: "no answer given", tolerance: tol };
  const got = parseAnswer(rules, String(text), quantity.unit);
  if (got.why) return { status: "malformed", right: false, why: got.why, tolerance: tol };
  const err = got.value - value;
  const fmt = (x) => Number(x.toPrecision(4)).toString();
  if (Math.abs(err) <= tol) {
    return { status: "right", right: true, given: got.value, why: `off by ${fmt(Math.abs(err))} <= tolerance ${fmt(tol)}`, tolerance: tol };
  }
  const sense = err > 0 ? "too high" : "too low";
  return { status: "wrong", right: false, given: got.value, why: `${sense} by ${fmt(Math.abs(err))} > tolerance ${fmt(tol)}`, tolerance: tol };
}

/** The statement of a variant: the template with its givens filled in (str.format). */
export function statement(template, givens) {
  return template.replace(/\{\{|\}\}|\{([A-Za-z_][A-Za-z0-9_]*)\}/g, (all, name) => {
    if (all === "{{") return "{";
    if (all === "}}") return "}";
    return Object.prototype.hasOwnProperty.call(givens, name) ? givens[name] : all;
  });
}

const esc = (s) => String(s).replace(/&/g, "&amp;").replace(/</g, "&lt;").replace(/>/g, "&gt;").replace(/"/g, "&quot;");

/** Make the form in `root` live; its table is fetched on first use. */
export function mount(root) {
  let data = null;
  const load = async () => {
    if (!data) {
      const response = await fetch(root.dataset.table);
      if (!response.ok) throw new Error(`the answer table ${root.dataset.table} could not be read (${response.status})`);
      data = await response.json();
    }
    return data;
  };
  const q = (sel) => root.querySelector(sel);
  const current = () => ({ number: q("[data-control=exercise]").value, seed: Number(q("[data-control=seed]").value) });
  const showExercise = async (keepAnswers) => {
    const d = await load();
    const { number, seed } = current();
    const table = d.exercises[number];
    const body = q("[data-part=answers]");
    if (!keepAnswers || body.dataset.number !== number) {
      body.innerHTML = table.quantities.map((qt) => `<tr><td><label for="ans-${esc(number)}-${esc(qt.key)}"><code>${esc(qt.key)}</code>` +
        `</label></td><td>${esc(qt.name)}</td><td><input type="text" id="ans-${esc(number)}-${esc(qt.key)}" data-key="${esc(qt.key)}" ` +
        `size="12"> ${esc(qt.unit)}</td><td class="verdict" data-key="${esc(qt.key)}"></td></tr>`).join("");
      body.dataset.number = number;
    }
    const valid = Number.isInteger(seed) && seed >= d.seeds[0] && seed <= d.seeds[1];
    const row = valid ? table.seeds[seed - d.seeds[0]] : null;
    // a row is [givens in the order of table.givens, answers in the order of table.quantities]
    const variant = row && {
      givens: Object.fromEntries(table.givens.map((name, i) => [name, row[0][i]])),
      answers: Object.fromEntries(table.quantities.map((qt, i) => [qt.key, row[1][i]]).filter(([, v]) => v !== null)),
    };
    q("[data-part=givens]").textContent = !valid
      ? `Seeds ${d.seeds[0]} to ${d.seeds[1]} are checked here; for another, use python -m mech.exercises check.`
      : variant === null ? "This seed gives no valid variant."
        : `Variant ${seed}: ${statement(table.statement, variant.givens)}`;
    return { d, table, variant };
  };
  /** Check every field; returns the verdicts by key (also written into the page). */
  const check = async () => {
    const { d, table, variant } = await showExercise(true);
    const out = {};
    for (const qt of table.quantities) {
      const cell = root.querySelector(`td.verdict[data-key="${CSS.escape(qt.key)}"]`);
      const text = root.querySelector(`input[data-key="${CSS.escape(qt.key)}"]`).value;
      if (!variant || !(qt.key in variant.answers)) {
        cell.textContent = "";
        continue;
      }
      const v = judge(d, qt, variant.answers[qt.key], text);
      out[qt.key] = v.status;
      cell.dataset.status = v.status;
      cell.textContent = `${v.status}: ${v.why}`;
    }
    const counts = Object.values(out).reduce((c, s) => ({ ...c, [s]: (c[s] || 0) + 1 }), {});
    q("[data-part=summary]").textContent = Object.entries(counts).map(([s, n]) => `${n} ${s}`).join(", ");
    root.dataset.verdicts = JSON.stringify(out);
    return out;
  };
  const report = (err) => { q("[data-part=summary]").textContent = `The check could not run: ${err.message}`; };
  q("[data-control=check]").addEventListener("click", () => check().catch(report));
  q("[data-control=exercise]").addEventListener("change", () => showExercise(false).catch(report));
  q("[data-control=seed]").addEventListener("change", () => showExercise(true).catch(report));
  root.addEventListener("focusin", () => showExercise(true).catch(report), { once: true });
  root.mechCheck = check;
}

if (typeof document !== "undefined") {
  for (const root of document.querySelectorAll(".mech-exercise-check[data-table]")) mount(root);
}
