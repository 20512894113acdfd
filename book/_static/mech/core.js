// The shared rules of the hand-written layer around the generated kernels
// (book/_static/kernels/*.js): exact power-of-two scaling, a correctly rounded sum, and
// input checks whose messages name the argument and the value, as mech/_validate.py does.
// Written by hand; the formulas are only in the kernels. planar.js and spherical.js use it.

/** Input the linkage cannot take (a length that is not positive, a link too long, ...). */
export class LinkageInputError extends Error {
  constructor(message) {
    super(message);
    this.name = "LinkageInputError";
  }
}

/** The inputs within this fraction of a + b + c + d of a dead point are the dead point. */
export const DEAD_POINT_RTOL = 2 ** -46;

// --- exact floating-point helpers ----------------------------------------------------

const _view = new DataView(new ArrayBuffer(8));

/** The exponent e of x = m 2**e with 1/2 <= |m| < 1 (Python's math.frexp(x)[1]); x finite, not 0. */
export function frexpExponent(x) {
  _view.setFloat64(0, x);
  const biased = (_view.getUint16(0) >> 4) & 0x7ff;
  if (biased === 0) return frexpExponent(x * 2 ** 64) - 64; // subnormal
  return biased - 1022;
}

/** x times 2**e, rounded once (Python's math.ldexp). */
export function ldexp(x, e) {
  if (x === 0 || !Number.isFinite(x) || e === 0) return x;
  const ex = frexpExponent(x);
  // m in [1/2, 1), exactly: two steps, as 2**-ex alone may overflow
  const half = Math.trunc(-ex / 2);
  const m = x * 2 ** half * 2 ** (-ex - half);
  const t = ex + e;
  if (t > 1024) return m * Infinity;
  if (t >= -1021) return m * 2 * 2 ** (t - 1); // normal: exact
  if (t >= -1074) return m * 2 ** t; // 2**t is a subnormal power of two: one rounding
  if (t === -1075) return Math.abs(m) > 0.5 ? Math.sign(m) * 2 ** -1074 : m * 0;
  return m * 0;
}

/** The correctly rounded sum of `values` (Python's math.fsum, Shewchuk's partials). */
export function fsum(values) {
  const partials = [];
  for (let x of values) {
    let i = 0;
    for (let y of partials) {
      if (Math.abs(x) < Math.abs(y)) [x, y] = [y, x];
      const hi = x + y;
      const lo = y - (hi - x);
      if (lo !== 0) partials[i++] = lo;
      x = hi;
    }
    partials.length = i;
    partials.push(x);
  }
  let n = partials.length;
  if (n === 0) return 0;
  let hi = partials[--n];
  let lo = 0;
  while (n > 0) {
    const x = hi;
    const y = partials[--n];
    hi = x + y;
    lo = y - (hi - x);
    if (lo !== 0) break;
  }
  if (n > 0 && ((lo < 0 && partials[n - 1] < 0) || (lo > 0 && partials[n - 1] > 0))) {
    const y = lo * 2;
    const x = hi + y;
    if (y === x - hi) hi = x;
  }
  return hi;
}

// --- input checks ---------------------------------------------------------------------

export function show(value) {
  if (typeof value === "string") return JSON.stringify(value);
  if (typeof value === "number" && Object.is(value, -0)) return "-0.0";
  return String(value);
}

export function number(name, value) {
  if (typeof value !== "number") {
    throw new LinkageInputError(`Expected \`${name}\` to be a number, got ${typeof value} ${show(value)}`);
  }
  return value;
}

/** `value` after checking that it is a finite number > 0. */
export function positiveLength(name, value) {
  const x = number(name, value);
  if (!(Number.isFinite(x) && x > 0)) throw new LinkageInputError(`Expected \`${name}\` > 0, got ${show(x)}`);
  return x;
}

export function finiteNumber(name, value) {
  const x = number(name, value);
  if (!Number.isFinite(x)) throw new LinkageInputError(`Expected \`${name}\` finite, got ${show(x)}`);
  return x;
}

export function finiteArray(name, values) {
  const list = typeof values === "number" ? [values] : values;
  if (list == null || typeof list.length !== "number") {
    throw new LinkageInputError(`Expected \`${name}\` to be a number or an array of numbers, got ${show(values)}`);
  }
  const out = new Float64Array(list.length);
  for (let i = 0; i < list.length; i++) out[i] = finiteNumber(`${name}[${i}]`, list[i]);
  return out;
}


/**
 * The package's promise on a solved pose (mech/_pose.py): `valid[i]` is true only where
 * every solved field holds a finite number; a value that is not (an infinite rate at a dead
 * point, a value beyond the float range) becomes NaN, and `assembled` keeps the incoming
 * mask (the position exists). `out` holds per-point numbers (typed arrays) or vectors
 * (arrays of arrays); `theta`, `valid` and `assembled` are not fields.
 */
export function keepPromise(out) {
  const valid = out.valid;
  if (!out.assembled) out.assembled = valid.slice();
  for (const [name, field] of Object.entries(out)) {
    if (name === "theta" || name === "valid" || name === "assembled") continue;
    for (let i = 0; i < field.length; i++) {
      const value = field[i];
      if (typeof value === "number") {
        if (!Number.isFinite(value)) {
          field[i] = NaN;
          valid[i] = false;
        }
      } else {
        for (let k = 0; k < value.length; k++) {
          if (!Number.isFinite(value[k])) {
            value[k] = NaN;
            valid[i] = false;
          }
        }
      }
    }
  }
  return out;
}

// --- 3-D views ----------------------------------------------------------------------------

/** The point of the unit sphere under the user point (x, y) of a 3-D view, on the reader's
 *  side: the inverse of the player's projection with its yaw, pitch and scale K. */
export function unproject([yaw, pitch, K], x, y) {
  let X = x / K, Y = -y / K, w = Math.sqrt(Math.max(0, 1 - X * X - Y * Y));
  const n = Math.hypot(X, Y, w);
  X /= n; Y /= n; w /= n;
  const cy = Math.cos(yaw), sy = Math.sin(yaw), cp = Math.cos(pitch), sp = Math.sin(pitch);
  // the projection: X = x', Y = sp y' + cp z, w = sp z - cp y', with x' = cy p0 + sy p1, y' = -sy p0 + cy p1
  const yv = sp * Y - cp * w, z = cp * Y + sp * w;
  return [cy * X - sy * yv, sy * X + cy * yv, z];
}
