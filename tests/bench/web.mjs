// web.mjs - the WebAssembly build's speed, side by side with the native
// program in one run (make bench): the module in Node.js against the
// native program on the same scenes (best of 3 each, the files both
// write), and the page in Chromium, a setting changed to the picture.
//   node tests/bench/web.mjs PHYLLO WEB OUT [CHROMIUM]
import fs from 'node:fs';
import path from 'node:path';
import { createRequire } from 'node:module';
import { spawnSync } from 'node:child_process';

const [phyllo, web, out, chromiumPath] = process.argv.slice(2);
const { run } = await import(path.resolve(web, 'phyllo.mjs'));

const CASES = [
  ['1,000,000 planar organs, --gltf', '--gltf', 'glb',
    'model = "planar";\ncount = 1000000;\nplanar = { scale = 0.01; dome = 0.2; };\n'],
  ['100,000 collision primordia on the dome, --csv', '--csv', 'csv',
    'model = "collision";\ncount = 100000;\ncollision = { receptacle = { shape = "hemisphere"; }; radius = 0.0037; };\n'],
  ['1,500 inhibition primordia (the angle emerging), --csv', '--csv', 'csv',
    'model = "inhibition";\ncount = 1500;\n'],
];

const best = async f => {
  let b = Infinity;
  for (let i = 0; i < 5; i++) {
    const t = performance.now();
    await f();
    b = Math.min(b, performance.now() - t);
  }
  return b;
};

console.log('the module in Node.js (each run a fresh instance) and the native program, best of 5, each writing its file (-o):');
let one = 0;
for (const [what, fmt, ext, text] of CASES) {
  const cfg = `${out}/web-bench.cfg`;
  fs.writeFileSync(cfg, text);
  const tn = await best(() => {
    const r = spawnSync(phyllo, [fmt, '-o', `${out}/web-bench.${ext}`, cfg]);
    if (r.status !== 0)
      throw new Error(r.stderr.toString());
  });
  const files = { 'bench.cfg': text };
  const tw = await best(async () => {
    const r = await run([fmt, '-o', `bench.${ext}`, 'bench.cfg'], files);
    if (r.status !== 0)
      throw new Error(r.stderr);
  });
  console.log(`  ${what}: native ${(tn / 1000).toFixed(3)} s, module ${(tw / 1000).toFixed(3)} s: ${(tw / tn).toFixed(2)}x`);
}
one = await best(() => run(['--version']));
console.log(`  a run's own cost (a fresh instance, --version): ${one.toFixed(1)} ms`);

if (chromiumPath) {
  const require = createRequire(path.resolve('src/viewer/package.json'));
  const { chromium } = require('playwright-core');
  const { serve } = await import('../../src/viewer/serve.mjs');
  const server = await serve(web);
  const base = `http://127.0.0.1:${server.address().port}`;
  const browser = await chromium.launch({ executablePath: chromiumPath,
    args: ['--no-sandbox', '--disable-gpu', '--enable-unsafe-swiftshader',
      '--disable-background-networking', '--disable-component-update',
      '--disable-sync', '--no-first-run'] });
  try {
    const page = await browser.newPage({ viewport: { width: 1400, height: 860 } });
    await page.goto(`${base}/index.html`);
    await page.waitForFunction(() => window.phylloPage && window.phylloPage.scenePath);
    await page.evaluate(() => window.phylloPage.idle());
    console.log('the page in Chromium (software GL, SwiftShader: no GPU here): divergence changed in the panel -> the new structure drawn (its draw calls made) / the frame shown (drawn by SwiftShader); median of 5:');
    for (const n of [10000, 100000]) {
      const scene = `model = "planar";\ncount = ${n};\nplanar = { scale = ${(1 / Math.sqrt(n)).toPrecision(6)}; };\n`;
      await page.setInputFiles('#files', { name: 'bench.cfg', mimeType: 'text/plain', buffer: Buffer.from(scene) });
      await page.evaluate(() => window.phylloPage.idle());
      const picture = [], frame = [];
      for (let i = 0; i < 5; i++) {
        await page.fill('input[data-path="divergence"]', (137.3 + 0.1 * i).toFixed(1));
        await page.press('input[data-path="divergence"]', 'Enter');
        await page.evaluate(() => window.phylloPage.idle());
        const t = await page.evaluate(() => window.phylloPage.timing);
        picture.push(t.picture);
        frame.push(t.frame);
      }
      const median = a => a.sort((x, y) => x - y)[2];
      const tris = await page.evaluate(() => window.phylloPage.view.renderer.info.render.triangles);
      console.log(`  ${n.toLocaleString('en')} organs (placeholder icospheres, ${tris.toLocaleString('en')} triangles): drawn ${median(picture).toFixed(0)} ms (target ${n > 10000 ? 1000 : 100}), shown ${median(frame).toFixed(0)} ms`);
    }
  } finally {
    await browser.close();
    server.close();
  }
}
