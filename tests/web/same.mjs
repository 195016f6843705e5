// same.mjs - is what the WebAssembly build wrote what the native program
// wrote?  Byte for byte, or else equal but for the last printed digit
// of some numbers: emscripten's C library (musl) computes sin, cos,
// atan2 and the like to within an ulp of glibc's, but not always to the
// same bits, and a difference in the last bit now and then shows in
// the 9th significant digit we print, or as a rounding residue (1e-18
// for 0).  Text is compared as text with its numbers picked out; a .glb
// as its JSON (text) and its binary chunk, the float accessors' data as
// floats, every other byte exactly.

// One unit of the last of 9 significant digits of x (numfmt.c's %.9g).
const DIGITS = 9;

function lastDigit(x) {
  const a = Math.abs(x);
  return a === 0 ? 0 : 10 ** (Math.floor(Math.log10(a)) - DIGITS + 1);
}

// How far apart two printed numbers are, in units of the last digit of
// the larger; 0 where they differ by less than 1e-11 of the largest
// number on their line (a position's line, an SVG element): what
// rounding leaves of a sum that cancels (3.46944695e-18 for 0 beside
// coordinates of order one, a spread of angles of order 137).  A
// line's numbers are of one computation, the error the two maths
// libraries' last bits leave is relative to its magnitudes.
const RESIDUE = 1e-11;

function closeNumbers(a, b, scale) {
  if (a === b || Math.abs(a - b) <= RESIDUE * scale)
    return 0;
  const unit = Math.max(lastDigit(a), lastDigit(b));
  return unit > 0 ? Math.abs(a - b) / unit : Infinity;
}

const NUMBER = /[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?/g;

// Split text into its numbers and what lies between them.
function tokens(text) {
  const words = [], numbers = [];
  let last = 0;
  for (const m of text.matchAll(NUMBER)) {
    words.push(text.slice(last, m.index));
    numbers.push(m[0]);
    last = m.index + m[0].length;
  }
  words.push(text.slice(last));
  return { words, numbers };
}

// A --blender script's structures: each "(FRAME, NAME, COUNT, [...]," then
// its data, lines of base64 alone: little-endian float32, every
// position (x, y, z), then every rotation (Euler XYZ, radians), then
// every scale (templates/blender.tmpl).
const STRUCTURE = /^\s*\(\d+, "[^"\n]*", (\d+), \[$/;
const DATA = /^\s*"([A-Za-z0-9+/]+={0,2})"\)?,?$/;

// The structures' data, decoded, and the text with those lines
// emptied (to be compared as text).
function blenderData(text) {
  const structures = [], rest = [];
  let cur = null;
  for (const line of text.split('\n')) {
    let m;
    if ((m = STRUCTURE.exec(line)) !== null) {
      structures.push(cur = { count: Number(m[1]), data: [] });
    } else if (cur !== null && (m = DATA.exec(line)) !== null) {
      cur.data.push(m[1]);
      rest.push('""');
      continue;
    } else if (cur !== null && cur.data.length > 0) {
      cur = null;
    }
    rest.push(line);
  }
  return {
    rest: rest.join('\n'),
    structures: structures.map(({ count, data }) => {
      const bytes = Uint8Array.from(data.map(atob).join(''), c => c.charCodeAt(0));
      return { count, floats: new Float32Array(bytes.buffer, 0, bytes.length >> 2) };
    }),
  };
}

// Two float32 values: within 2 ulps of a float, or both below 1e-7
// times the data's scale (residues of rounding, written as floats).
function closeFloats(x, y, scale) {
  if (x === y || Math.abs(x - y) <= 1e-7 * Math.max(1, scale))
    return 0;
  return Math.abs(x - y) / (Math.max(Math.abs(x), Math.abs(y)) * 2 ** -23);
}

// Floats a and b: within 2 ulps, or residues; angle: equal modulo a
// turn (an Euler angle of pi and one of -pi are the same rotation, and
// which one atan2() gives follows the sign of a residue).
function compareFloats(a, b, r, angle = () => false) {
  if (a.length !== b.length) {
    r.worst = Infinity;
    r.first ||= `${a.length} floats against ${b.length}`;
    return;
  }
  let scale = 0;
  for (const x of a)
    if (Number.isFinite(x))
      scale = Math.max(scale, Math.abs(x));
  for (let i = 0; i < a.length; i++) {
    if (Object.is(a[i], b[i]))
      continue;
    let y = b[i];
    if (angle(i) && Math.abs(a[i] - y) > Math.PI)
      y += a[i] > y ? 2 * Math.PI : -2 * Math.PI;
    const e = closeFloats(a[i], Math.fround(y), scale);
    r.worst = Math.max(r.worst, e);
    r.count++;
    r.first ||= `float ${a[i]} against ${b[i]}`;
  }
}

// The structures' data of two --blender scripts.
function compareBlender(a, b, r) {
  if (a.length !== b.length) {
    r.worst = Infinity;
    r.first ||= `${a.length} structures against ${b.length}`;
    return;
  }
  a.forEach((s, k) => {
    const n = s.count;
    if (s.floats.length !== 7 * n || b[k].count !== n) {
      r.worst = Infinity;
      r.first ||= `structure ${k}: ${s.floats.length} floats for ${n} organs`;
      return;
    }
    compareFloats(s.floats, b[k].floats, r, i => i >= 3 * n && i < 6 * n);
  });
}

// --info's output-bytes: line estimates the bytes each format would
// take, from the lengths of the numbers it would print: a residue
// printed as 3.46944695e-18 on one side and 0 on the other moves it.
// Its numbers are held to 2% (it prints them to 3 digits).
const ESTIMATES = /^output-bytes:.*$/m;

function compareEstimates(want, got, r) {
  const a = (want.match(ESTIMATES) || [''])[0], b = (got.match(ESTIMATES) || [''])[0];
  const ta = tokens(a), tb = tokens(b);
  if (ta.words.join('|') !== tb.words.join('|') ||
      ta.numbers.length !== tb.numbers.length) {
    r.worst = Infinity;
    r.first ||= `${a} against ${b}`;
    return;
  }
  ta.numbers.forEach((n, i) => {
    const x = Number(n), y = Number(tb.numbers[i]);
    if (x === y)
      return;
    r.count++;
    r.first ||= `${a} against ${b}`;
    if (Math.abs(x - y) > 0.02 * Math.max(x, y))
      r.worst = Infinity;
  });
}

/*
 * Compare two texts: { identical, close, worst (in units of the last
 * digit or of a float's ulp), count (numbers that differ), first (the
 * first difference) }.
 */
export function compareText(want, got) {
  if (want === got)
    return { identical: true, close: true, worst: 0, count: 0, first: '' };
  const r = { identical: false, close: false, worst: 0, count: 0, first: '' };
  const fail = where => ({ ...r, worst: Infinity, first: where });
  const da = blenderData(want), db = blenderData(got);
  compareBlender(da.structures, db.structures, r);
  compareEstimates(want, got, r);
  const a = tokens(da.rest.replace(ESTIMATES, ''));
  const b = tokens(db.rest.replace(ESTIMATES, ''));
  if (a.numbers.length !== b.numbers.length)
    return fail(`${a.numbers.length} numbers against ${b.numbers.length}`);
  // Each number's line's largest magnitude: number i follows words[i].
  const line = [], most = [0];
  a.numbers.forEach((n, i) => {
    if (a.words[i].includes('\n'))
      most.push(0);
    line.push(most.length - 1);
    if (Number.isFinite(Number(n)))
      most[most.length - 1] = Math.max(most[most.length - 1], Math.abs(Number(n)));
  });
  for (let i = 0; i < a.words.length; i++) {
    if (a.words[i] !== b.words[i])
      return fail(`text ${JSON.stringify(a.words[i].slice(0, 60))} against ${JSON.stringify(b.words[i].slice(0, 60))}`);
    if (i === a.numbers.length || a.numbers[i] === b.numbers[i])
      continue;
    const e = closeNumbers(Number(a.numbers[i]), Number(b.numbers[i]), most[line[i]]);
    r.count++;
    r.first ||= `${a.numbers[i]} against ${b.numbers[i]}`;
    r.worst = Math.max(r.worst, e);
  }
  r.close = r.worst <= 2;
  return r;
}

// A .glb's JSON text and binary chunk.
function glbChunks(bytes) {
  const v = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const out = {};
  for (let pos = 12; pos + 8 <= bytes.length;) {
    const len = v.getUint32(pos, true), type = v.getUint32(pos + 4, true);
    const body = bytes.subarray(pos + 8, pos + 8 + len);
    if (type === 0x4e4f534a)
      out.json = new TextDecoder().decode(body);
    else if (type === 0x004e4942)
      out.bin = body;
    pos += 8 + len;
  }
  return out;
}

function compareGlb(want, got) {
  if (want.length !== got.length)
    return { identical: false, close: false, worst: Infinity, count: 0,
      first: `${want.length} bytes against ${got.length}` };
  const a = glbChunks(want), b = glbChunks(got);
  if (a.json === undefined || b.json === undefined)
    return { identical: false, close: false, worst: Infinity, count: 0, first: 'no JSON chunk' };
  const r = compareText(a.json, b.json);
  if (!r.close)
    return r;
  // Which bytes of the binary chunk are floats: the float accessors'.
  const gltf = JSON.parse(a.json);
  const isFloat = new Uint8Array(a.bin ? a.bin.length : 0);
  const sizes = { SCALAR: 1, VEC2: 2, VEC3: 3, VEC4: 4, MAT4: 16 };
  for (const acc of gltf.accessors || []) {
    if (acc.componentType !== 5126 || acc.bufferView === undefined)
      continue;
    const view = gltf.bufferViews[acc.bufferView];
    const n = sizes[acc.type], stride = view.byteStride || 4 * n;
    const start = (view.byteOffset || 0) + (acc.byteOffset || 0);
    for (let i = 0; i < acc.count; i++)
      isFloat.fill(1, start + i * stride, start + i * stride + 4 * n);
  }
  const fa = a.bin ? new DataView(a.bin.buffer, a.bin.byteOffset, a.bin.length) : null;
  const fb = b.bin ? new DataView(b.bin.buffer, b.bin.byteOffset, b.bin.length) : null;
  let worst = r.worst, count = r.count, first = r.first;
  for (let i = 0; a.bin && i < a.bin.length; i++) {
    if (a.bin[i] === b.bin[i])
      continue;
    if (!isFloat[i])
      return { identical: false, close: false, worst: Infinity, count,
        first: `byte ${i} of the binary chunk, not a float` };
    // The float holding byte i.
    const at = i - (i % 4);
    const x = fa.getFloat32(at, true), y = fb.getFloat32(at, true);
    const e = closeFloats(x, y, 1);
    worst = Math.max(worst, e);
    count++;
    if (!first)
      first = `float ${x} against ${y}`;
    i = at + 3;
  }
  return { identical: false, close: worst <= 2, worst, count, first };
}

/*
 * Compare two outputs (Uint8Array): a .glb (by its magic) or text.
 */
export function compare(want, got) {
  if (want.length === got.length && want.every((x, i) => x === got[i]))
    return { identical: true, close: true, worst: 0, count: 0, first: '' };
  const magic = b => b.length >= 4 && b[0] === 0x67 && b[1] === 0x6c &&
    b[2] === 0x54 && b[3] === 0x46;
  if (magic(want) && magic(got))
    return compareGlb(want, got);
  const dec = new TextDecoder('utf-8', { fatal: false });
  return compareText(dec.decode(want), dec.decode(got));
}
