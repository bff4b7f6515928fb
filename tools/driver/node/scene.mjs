// SPDX-License-Identifier: MIT
// What the Node drivers share (spec/driver.md DRIVER.EXTERNAL.PATHS, DRIVER.PATH.SKIA,
// DRIVER.PATH.TINY_SKIA): the capabilities query, the scene read from standard input with the
// exact text of its numbers, each path snapped exactly as the kernel snaps it, and the fragment
// list written on standard output. A driver module gives its capabilities and a function that
// draws one snapped path into an 8-bit alpha raster.
//
// Snapping (SNAP.VERTEX.ROUND, SCENE.NUMBER.FLOAT32): the kernel reads each coordinate's decimal
// text directly to the nearest float32 v (ties to even) and snaps it to round-half-to-even of
// v * 256, exactly. JavaScript has neither step: JSON.parse rounds the text to a double (a
// float32 from that double may round twice) and Math.round rounds halves up (Math.round(-0.5) is
// -0, Math.round(2.5) is 3, where the kernel gives 0 and 2). So the numbers of the scene are kept
// as text and both roundings are done here on BigInt integers: the result is the kernel's raw
// 16.8 value, and raw / 256 is given to the library (exact in float32 and in decimal).

// The capabilities query's variable and value (DRIVER.EXTERNAL.CAPABILITIES).
const QUERY_VARIABLE = 'RASTRULES_QUERY';
const QUERY_VALUE = 'capabilities';

// The kernel's range of raw values (SNAP.VERTEX.RANGE): [-2^23, 2^23 - 1].
const RAW_MIN = -(2 ** 23);
const RAW_MAX = 2 ** 23 - 1;

// A failure of the driver: reported on standard error with exit status 1 (never guessed around).
export class DriverFailure extends Error {}

// Returns num / den (BigInt, both > 0) rounded to the nearest integer, ties to even.
function roundHalfEven(num, den) {
  const q = num / den;
  const twice = 2n * (num - q * den);
  if (twice > den || (twice === den && (q & 1n) === 1n))
    return q + 1n;
  return q;
}

// Returns the bit length of a positive BigInt.
function bitLength(n) {
  return n.toString(2).length;
}

// Returns the raw 16.8 value the kernel gives the JSON number `text`: the float32 nearest to the
// decimal value (ties to even; subnormals included), times 256, rounded half to even. Throws a
// DriverFailure for a value outside SNAP.VERTEX.RANGE (which the kernel rejects before a draw).
export function snapRaw(text) {
  const m = /^(-?)(\d+)(?:\.(\d+))?(?:[eE]([+-]?\d+))?$/.exec(text);
  if (m === null)
    throw new DriverFailure(`not a coordinate: ${String(text).slice(0, 40)}`);
  const negative = m[1] === '-';
  const fraction = m[3] ?? '';
  const digits = BigInt(m[2] + fraction);
  const exp10 = Number(m[4] ?? '0') - fraction.length;
  if (!Number.isSafeInteger(exp10) || Math.abs(exp10) > 400)
    return digits === 0n ? 0 : outOfRange(text);
  if (digits === 0n)
    return 0;
  // The value is num / den exactly.
  let num = digits;
  let den = 1n;
  if (exp10 >= 0)
    num *= 10n ** BigInt(exp10);
  else
    den = 10n ** BigInt(-exp10);
  // The float32 nearest: q * 2^e with 2^23 <= q < 2^24 for normal numbers, e >= -149 (the
  // subnormals' exponent, where q may be smaller). Start from the bit lengths, then correct.
  let e = bitLength(num) - bitLength(den) - 24;
  const scaled = (k) => (k >= 0 ? [num, den << BigInt(k)] : [num << BigInt(-k), den]);
  for (;;) {
    const [n, d] = scaled(e);
    if (n >= d << 24n)
      e += 1;
    else if (n < d << 23n && e > -149)
      e -= 1;
    else
      break;
  }
  e = Math.max(e, -149);
  let q = roundHalfEven(...scaled(e)); // may reach 2^24: still q * 2^e exactly
  if (q === 0n)
    return 0;
  if (e > 127 - 23)
    return outOfRange(text); // beyond float32: infinite, refused by the kernel
  // raw = round-half-even(q * 2^e * 256) = round-half-even(q * 2^(e + 8)).
  const shift = e + 8;
  const raw = shift >= 0 ? q << BigInt(shift) : roundHalfEven(q, 1n << BigInt(-shift));
  const value = negative ? -raw : raw;
  if (value < BigInt(RAW_MIN) || value > BigInt(RAW_MAX))
    return outOfRange(text);
  return Number(value) + 0; // + 0: -0 snaps to 0
}

function outOfRange(text) {
  throw new DriverFailure(`coordinate ${String(text).slice(0, 40)} is outside SNAP.VERTEX.RANGE`);
}

// Returns raw / 256 as exact decimal text (at most 8 digits after the point).
export function rawText(raw) {
  const sign = raw < 0 ? '-' : '';
  const a = Math.abs(raw);
  const whole = Math.floor(a / 256);
  const frac = (a % 256) * 390625; // (a % 256) / 256 = frac / 10^8
  if (frac === 0)
    return sign + String(whole);
  return sign + String(whole) + '.' + String(frac).padStart(8, '0').replace(/0+$/, '');
}

// Parses the scene text with every number kept as its text: each number token outside a string
// becomes {"#": "TEXT"} before JSON.parse (a string is matched first, so digits inside strings
// are left alone).
function parseExact(text) {
  const wrapped = text.replace(
    /"(?:[^"\\]|\\.)*"|-?\d+(?:\.\d+)?(?:[eE][+-]?\d+)?/g,
    (t) => (t[0] === '"' ? t : `{"#":"${t}"}`));
  return JSON.parse(wrapped);
}

function numberText(v, where) {
  if (v === null || typeof v !== 'object' || typeof v['#'] !== 'string')
    throw new DriverFailure(`${where}: expected a number`);
  return v['#'];
}

function integer(v, where) {
  const n = Number(numberText(v, where));
  if (!Number.isSafeInteger(n))
    throw new DriverFailure(`${where}: expected an integer`);
  return n;
}

// A scene as the drivers draw it: {width, height, paths: [{fillRule, antialiased, contours}]},
// each contour a list of commands {op: 'M' | 'L' | 'Q' | 'C', pts: [[x, y], ...]} in raw 16.8.
// Throws a DriverFailure for what the drivers do not draw (they declare paths only, one sample).
export function readScene(text) {
  let scene;
  try {
    scene = parseExact(text);
  } catch (err) {
    throw new DriverFailure(`the scene is not JSON: ${err.message}`);
  }
  const target = scene?.target;
  const width = integer(target?.width, 'target.width');
  const height = integer(target?.height, 'target.height');
  if (scene.samples !== undefined && integer(scene.samples, 'samples') !== 1)
    throw new DriverFailure('samples: this driver draws one sample at the pixel centre');
  if (scene.sample_positions !== undefined)
    throw new DriverFailure('sample_positions: this driver draws one sample at the pixel centre');
  const prims = scene.primitives;
  if (!Array.isArray(prims))
    throw new DriverFailure('primitives: expected an array');
  const paths = prims.map((p, i) => {
    const at = `primitives[${i}]`;
    if (p?.type !== 'path' || !Array.isArray(p.contours))
      throw new DriverFailure(`${at}: this driver draws paths only`);
    if (p.fill_rule !== 'nonzero' && p.fill_rule !== 'evenodd')
      throw new DriverFailure(`${at}.fill_rule: expected "nonzero" or "evenodd"`);
    if (p.coverage !== 'samples' && p.coverage !== 'area')
      throw new DriverFailure(`${at}.coverage: expected "samples" or "area"`);
    const counts = { M: 1, L: 1, Q: 2, C: 3 };
    const contours = p.contours.map((c, ci) => c.map((cmd, k) => {
      const where = `${at}.contours[${ci}][${k}]`;
      const n = counts[cmd?.[0]];
      if (n === undefined || cmd.length !== 1 + 2 * n || (cmd[0] === 'M') !== (k === 0))
        throw new DriverFailure(`${where}: expected ["M", x, y] first, then "L", "Q" or "C"`);
      const pts = [];
      for (let j = 0; j < n; ++j) {
        pts.push([snapRaw(numberText(cmd[1 + 2 * j], where)),
                  snapRaw(numberText(cmd[2 + 2 * j], where))]);
      }
      return { op: cmd[0], pts };
    }));
    return { fillRule: p.fill_rule, antialiased: p.coverage === 'area', contours };
  });
  return { width, height, paths };
}

// Returns the whole of standard input as text.
async function readStdin() {
  const chunks = [];
  for await (const chunk of process.stdin)
    chunks.push(chunk);
  return Buffer.concat(chunks).toString('utf8');
}

// Writes text to standard output and resolves once it is handed to the pipe.
function write(text) {
  return new Promise((resolve, reject) => {
    process.stdout.write(text, (err) => (err ? reject(err) : resolve()));
  });
}

// Runs a driver: answers the capabilities query with `capabilities`, or reads the scene and, for
// each path, calls `await draw(path, width, height)` for an alpha raster (width * height bytes,
// rows from the top) and writes the fragments (DRIVER.EXTERNAL.PATHS): {"prim", "x", "y"} for
// every pixel with nonzero alpha of an aliased path, with "alpha" for an antialiased one.
export async function run(capabilities, draw) {
  try {
    if (process.env[QUERY_VARIABLE] === QUERY_VALUE) {
      await write(JSON.stringify({ capabilities }) + '\n');
      return;
    }
    const scene = readScene(await readStdin());
    await write('{"fragments": [');
    let first = true;
    for (let prim = 0; prim < scene.paths.length; ++prim) {
      const path = scene.paths[prim];
      const alpha = await draw(path, scene.width, scene.height);
      let out = '';
      for (let y = 0; y < scene.height; ++y) {
        for (let x = 0; x < scene.width; ++x) {
          const a = alpha[y * scene.width + x];
          if (a === 0)
            continue;
          out += `${first ? '' : ',\n'}{"prim": ${prim}, "x": ${x}, "y": ${y}` +
                 (path.antialiased ? `, "alpha": ${a}}` : '}');
          first = false;
          if (out.length >= 65536) {
            await write(out);
            out = '';
          }
        }
      }
      if (out.length > 0)
        await write(out);
    }
    await write(']}\n');
  } catch (err) {
    const what = err instanceof DriverFailure ? err.message : (err?.stack ?? String(err));
    process.stderr.write(`${what}\n`);
    process.exitCode = 1;
  }
}

// The capabilities reply of a 2D library (DRIVER.EXTERNAL.PATHS): paths only, one sample, no
// pipeline, both coverage kinds, both fill rules, both curves, float coordinates; what differs
// between libraries is the largest target and how they decide aliased and antialiased pixels.
export function pathLibraryCapabilities({ maxTargetSide, aliased, antialiased }) {
  return {
    primitives: ['path'],
    sample_counts: [1],
    pipeline: false,
    values: false,
    max_target_side: maxTargetSide,
    paths: {
      samples: true,
      area: true,
      fill_rules: ['nonzero', 'evenodd'],
      curves: ['quadratic', 'cubic'],
      grid: 'float',
      aliased_method: aliased,
      antialiased_method: antialiased,
    },
  };
}
