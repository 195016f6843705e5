// three.mjs - load .glb files in three.js (GLTFLoader, through
// src/viewer/viewer.html) in headless Chromium, from a page served on
// 127.0.0.1, and hold what it built against phyllo-export --csv:
// every InstancedMesh's count and instance matrices (within 1e-5 of
// the structure's size), each object's mesh against its OBJ file's
// vertices, and a screenshot that shows something.  Prints "ok - " or
// "not ok - " lines for tests/run.sh.  Usage, from the repository:
//   node tests/gltf/three.mjs CHROMIUM OUTDIR NAME:GLB:CSV[:OBJECT=OBJ,...[:VIEW]] ...
// (VIEW: the direction to look from, x,y,z in our Z-up frame)
//   node tests/gltf/three.mjs --time CHROMIUM GLB     (load time, JSON)
import fs from 'node:fs';
import path from 'node:path';
import { createRequire } from 'node:module';
import zlib from 'node:zlib';
import { serve } from '../../src/viewer/serve.mjs';

const require = createRequire(path.resolve('src/viewer/package.json'));
const { chromium } = require('playwright-core');

let failed = 0;
function report(ok, what, why) {
  console.log(ok ? `ok - ${what}` : `not ok - ${what}: ${why}`);
  if (!ok) failed++;
}

// The CSV's rows, grouped by object in order.
function readCsv(file) {
  const [head, ...lines] = fs.readFileSync(file, 'utf8').trim().split('\n');
  const keys = head.split(',');
  const rows = lines.map(l => {
    const f = l.split(',');
    const r = {};
    keys.forEach((k, i) => { r[k] = k === 'object' ? f[i] : Number(f[i]); });
    return r;
  });
  const by = new Map();
  for (const r of rows) {
    if (!by.has(r.object)) by.set(r.object, []);
    by.get(r.object).push(r);
  }
  return { rows, by };
}

// glTF is Y up: our (x, y, z) is (x, z, -y) there.
const C = (x, y, z) => [x, z, -y];

// The matrix (column major, as three.js keeps it) glTF should give an
// organ: local X to u, Y to w, Z to u x w = -v, times scale, at pos.
function expected(r) {
  const s = r.scale;
  const u = C(r.ux, r.uy, r.uz), v = C(r.vx, r.vy, r.vz), w = C(r.wx, r.wy, r.wz);
  const t = C(r.x, r.y, r.z);
  return [u[0] * s, u[1] * s, u[2] * s, 0, w[0] * s, w[1] * s, w[2] * s, 0,
    -v[0] * s, -v[1] * s, -v[2] * s, 0, t[0], t[1], t[2], 1];
}

function multiply(a, b) {
  const m = new Array(16).fill(0);
  for (let c = 0; c < 4; c++)
    for (let r = 0; r < 4; r++)
      for (let k = 0; k < 4; k++)
        m[c * 4 + r] += a[k * 4 + r] * b[c * 4 + k];
  return m;
}

function size(rows) {
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  for (const r of rows)
    [r.x, r.y, r.z].forEach((x, i) => { lo[i] = Math.min(lo[i], x); hi[i] = Math.max(hi[i], x); });
  return Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) || 1;
}

// The box of an OBJ file's v lines.
function objBox(file) {
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  for (const line of fs.readFileSync(file, 'utf8').split('\n')) {
    const f = line.trim().split(/\s+/);
    if (f[0] !== 'v') continue;
    for (let i = 0; i < 3; i++) {
      lo[i] = Math.min(lo[i], Number(f[i + 1]));
      hi[i] = Math.max(hi[i], Number(f[i + 1]));
    }
  }
  return { lo, hi };
}

// The pixels of an 8-bit, non-interlaced RGB or RGBA PNG (what
// Chromium's screenshots are), as { width, height, channels, data }.
function decodePng(buf) {
  let pos = 8, width, height, type, idat = [];
  while (pos < buf.length) {
    const len = buf.readUInt32BE(pos), kind = buf.toString('latin1', pos + 4, pos + 8);
    const body = buf.subarray(pos + 8, pos + 8 + len);
    if (kind === 'IHDR') {
      width = body.readUInt32BE(0); height = body.readUInt32BE(4);
      if (body[8] !== 8 || body[12] !== 0) throw new Error('not an 8-bit plain PNG');
      type = body[9];
    } else if (kind === 'IDAT') idat.push(body);
    pos += 12 + len;
  }
  const ch = type === 6 ? 4 : type === 2 ? 3 : 0;
  if (!ch) throw new Error(`PNG colour type ${type}`);
  const raw = zlib.inflateSync(Buffer.concat(idat)), stride = width * ch;
  const out = Buffer.alloc(height * stride);
  for (let y = 0; y < height; y++) {
    const f = raw[y * (stride + 1)], line = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    for (let x = 0; x < stride; x++) {
      const a = x >= ch ? out[y * stride + x - ch] : 0;
      const b = y > 0 ? out[(y - 1) * stride + x] : 0;
      const c = x >= ch && y > 0 ? out[(y - 1) * stride + x - ch] : 0;
      const p = a + b - c, pa = Math.abs(p - a), pb = Math.abs(p - b), pc = Math.abs(p - c);
      const pred = [0, a, b, (a + b) >> 1, pa <= pb && pa <= pc ? a : pb <= pc ? b : c][f];
      out[y * stride + x] = (line[x] + pred) & 255;
    }
  }
  return { width, height, channels: ch, data: out };
}

async function launch() {
  // A fresh profile (playwright's own temporary one) and no network
  // but the page's own server.
  return chromium.launch({
    executablePath: process.argv[process.argv[2] === '--time' ? 3 : 2],
    args: ['--no-sandbox', '--disable-gpu', '--enable-unsafe-swiftshader',
      '--disable-background-networking', '--disable-component-update',
      '--disable-sync', '--no-first-run'],
  });
}

async function open(browser, base, glb, view, width = 640, height = 480) {
  const page = await browser.newPage({ viewport: { width, height } });
  const errors = [];
  page.on('pageerror', e => errors.push(e.message));
  page.on('console', m => { if (m.type() === 'error') errors.push(m.text()); });
  // As README names it: a path from where the server was started.
  await page.goto(`${base}/src/viewer/viewer.html?glb=${glb}${view ? '&view=' + view : ''}`);
  const facts = await page.evaluate(() => window.viewer.ready);
  return { page, facts, errors };
}

// What three.js made of the file: each InstancedMesh, its names up to
// the root, its count, world and instance matrices, and its box.
function readBack() {
  const out = [];
  window.viewer.scene.updateMatrixWorld(true);
  window.viewer.scene.traverse(o => {
    if (!o.isInstancedMesh) return;
    const names = [];
    for (let p = o; p; p = p.parent) names.push(p.name);
    o.geometry.computeBoundingBox();
    const b = o.geometry.boundingBox;
    out.push({ names, count: o.count, world: o.matrixWorld.elements.slice(),
      m: Array.from(o.instanceMatrix.array), vertices: o.geometry.attributes.position.count,
      lo: [b.min.x, b.min.y, b.min.z], hi: [b.max.x, b.max.y, b.max.z] });
  });
  return out;
}

async function check(browser, base, outdir, spec) {
  const [name, glb, csvFile, objs, view] = spec.split(':');
  const what = `three.js ${name}`;
  const { rows, by } = readCsv(csvFile);
  const tol = 1e-5 * size(rows);
  const { page, facts, errors } = await open(browser, base, glb, view);
  const meshes = await page.evaluate(readBack);

  report(errors.length === 0, `${what}: GLTFLoader loads ${glb}, no error in the page`, errors.join('; '));
  // Each object's organs once per primitive: a mesh of two materials
  // is a group of two InstancedMeshes.
  const seen = new Map();
  let worst = 0, bad = '';
  for (const mesh of meshes) {
    const object = mesh.names.find(n => by.has(n));
    const want = by.get(object);
    if (!want) { bad = `an InstancedMesh of no object (${mesh.names})`; continue; }
    if (!seen.has(object)) seen.set(object, []);
    seen.get(object).push(mesh.count);
    if (mesh.count !== want.length) { bad = `${object}: ${mesh.count} instances, CSV ${want.length}`; continue; }
    want.forEach((r, i) => {
      const got = multiply(mesh.world, mesh.m.slice(16 * i, 16 * i + 16));
      const e = expected(r);
      for (let k = 0; k < 16; k++) worst = Math.max(worst, Math.abs(got[k] - e[k]));
    });
  }
  const counts = [...by.keys()].map(o => `${o} ${by.get(o).length}`).join(', ');
  report(!bad && [...by.keys()].every(o => seen.has(o)) && seen.size === by.size,
    `${what}: an InstancedMesh per organ object, counts as --csv (${counts})`,
    bad || `objects ${[...seen.keys()]} against ${[...by.keys()]}`);
  report(!bad && worst <= tol, `${what}: every instance matrix is the CSV's frame and scale at its position (worst ${worst.toExponential(2)}, allowed ${tol.toExponential(2)})`,
    bad || `worst ${worst}`);
  if (objs) {
    let off = '';
    for (const pair of objs.split(',')) {
      const [object, file] = pair.split('=');
      const box = objBox(file);
      for (const mesh of meshes.filter(m => m.names.includes(object)))
        for (let i = 0; i < 3; i++)
          if (Math.abs(mesh.lo[i] - box.lo[i]) > 1e-6 || Math.abs(mesh.hi[i] - box.hi[i]) > 1e-6)
            off += ` ${object} axis ${i}: ${mesh.lo[i]}..${mesh.hi[i]} vs ${box.lo[i]}..${box.hi[i]};`;
    }
    report(!off, `${what}: each mesh spans its OBJ file's box, axes as written`, off);
  }
  const png = path.join(outdir, `${name}-three.png`);
  await page.evaluate(() => { document.getElementById('status').hidden = true; });
  await page.screenshot({ path: png });
  const img = decodePng(fs.readFileSync(png));
  const bg = [0xc6, 0xd3, 0xdc];	// the page's background
  const colours = new Set();
  let drawn = 0;
  for (let p = 0; p < img.width * img.height; p++) {
    const o = p * img.channels, px = [img.data[o], img.data[o + 1], img.data[o + 2]];
    if (Math.abs(px[0] - bg[0]) + Math.abs(px[1] - bg[1]) + Math.abs(px[2] - bg[2]) > 24) drawn++;
    colours.add((px[0] >> 4) << 8 | (px[1] >> 4) << 4 | px[2] >> 4);
  }
  const share = drawn / (img.width * img.height);
  report(share > 0.03 && share < 0.97 && colours.size > 8,
    `${what}: the screenshot ${png} shows the structure (${(100 * share).toFixed(1)}% of pixels drawn, ${colours.size} colours)`,
    `${(100 * share).toFixed(2)}% drawn, ${colours.size} colours`);
  console.error(`${name}: ${JSON.stringify(facts)}`);
  await page.close();
}

const server = await serve('.');
const base = `http://127.0.0.1:${server.address().port}`;
const browser = await launch();
try {
  if (process.argv[2] === '--time') {
    const { page, facts, errors } = await open(browser, base, process.argv[4], null, 1280, 720);
    console.log(JSON.stringify({ ...facts, errors }));
    await page.close();
  } else {
    const outdir = process.argv[3];
    for (const spec of process.argv.slice(4))
      await check(browser, base, outdir, spec).catch(e => report(false, `three.js ${spec.split(':')[0]}`, e.message));
  }
} finally {
  await browser.close();
  server.close();
}
process.exit(failed ? 1 : 0);
