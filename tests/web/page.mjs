// page.mjs - the page (build/web/index.html) in headless Chromium, as a
// user meets it, held against the native program: it loads with no
// error and nothing from the network; every example scene's organs in
// three.js, count and instance matrices, are the native --csv's; so
// after a change in the settings panel, and at a frame of a growing
// scene; every download is the native program's output for the same
// scene and changes; errors read as the native messages, at their line;
// scenes holding markup and script run none of it; files that are not
// text or too big are refused; a long run shows its progress and is
// cancelled.  Prints "ok - " and "not ok - " lines for tests/run.sh.
//   node tests/web/page.mjs CHROMIUM PHYLLO WEB OUT
import fs from 'node:fs';
import path from 'node:path';
import { createRequire } from 'node:module';
import { spawnSync } from 'node:child_process';
import { serve } from '../../src/viewer/serve.mjs';
import { compare } from './same.mjs';

const require = createRequire(path.resolve('src/viewer/package.json'));
const { chromium } = require('playwright-core');
const [chromiumPath, phyllo, web, out] = process.argv.slice(2);

let failed = 0;
function report(ok, what, why = '') {
  console.log(ok ? `ok - ${what}` : `not ok - ${what}: ${why}`);
  if (!ok)
    failed++;
}

function native(args, cwd = '.') {
  const r = spawnSync(path.resolve(phyllo), args, { cwd, maxBuffer: 1 << 30 });
  return { status: r.status, stdout: new Uint8Array(r.stdout),
    stderr: r.stderr.toString() };
}

// The CSV's rows.
function rows(text) {
  const [head, ...lines] = text.trim().split('\n');
  const keys = head.split(',');
  return lines.map(l => {
    const f = l.split(',');
    const r = {};
    keys.forEach((k, i) => { r[k] = k === 'object' ? f[i] : Number(f[i]); });
    return r;
  });
}

// glTF is Y up: our (x, y, z) is (x, z, -y) there; an organ's matrix
// takes local X to u, Y to w and Z to u x w = -v, times its scale.
const C = (x, y, z) => [x, z, -y];
function expected(r) {
  const s = r.scale, u = C(r.ux, r.uy, r.uz), v = C(r.vx, r.vy, r.vz);
  const w = C(r.wx, r.wy, r.wz), t = C(r.x, r.y, r.z);
  return [u[0] * s, u[1] * s, u[2] * s, 0, w[0] * s, w[1] * s, w[2] * s, 0,
    -v[0] * s, -v[1] * s, -v[2] * s, 0, t[0], t[1], t[2], 1];
}

// What three.js draws: each organ object's InstancedMesh (the first of
// a mesh of several materials), its name and world instance matrices.
function readBack() {
  const out = [], seen = new Set();
  const root = window.phylloPage.view.shown;
  root.updateMatrixWorld(true);
  root.traverse(o => {
    if (!o.isInstancedMesh)
      return;
    const object = o.parent !== root && o.parent.isGroup ? o.parent : o;
    if (seen.has(object))
      return;
    seen.add(object);
    const m = [];
    const tmp = o.matrixWorld.clone(), im = o.matrixWorld.clone();
    for (let i = 0; i < o.count; i++) {
      o.getMatrixAt(i, im);
      m.push(...tmp.clone().multiply(im).elements);
    }
    out.push({ name: object.name, count: o.count, m });
  });
  return out;
}

// Hold what the page shows against CSV text: '' if the same organs.
async function sameOrgans(page, csv) {
  const want = rows(csv);
  const by = new Map();
  for (const r of want) {
    if (!by.has(r.object))
      by.set(r.object, []);
    by.get(r.object).push(r);
  }
  let lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  for (const r of want)
    [r.x, r.y, r.z].forEach((x, i) => { lo[i] = Math.min(lo[i], x); hi[i] = Math.max(hi[i], x); });
  const tol = 1e-5 * (Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) || 1);
  const got = await page.evaluate(readBack);
  const drawn = await page.evaluate(() => window.phylloPage.instances);
  if (drawn !== want.length)
    return `phylloPage.instances ${drawn}, --csv ${want.length} organs`;
  if (got.length !== by.size)
    return `${got.length} organ objects drawn, --csv ${by.size}`;
  let worst = 0;
  for (const g of got) {
    const w = by.get(g.name);
    if (!w)
      return `an InstancedMesh of no organ object (${g.name})`;
    if (w.length !== g.count)
      return `${g.name}: ${g.count} drawn, --csv ${w.length}`;
    w.forEach((r, i) => {
      const e = expected(r);
      for (let k = 0; k < 16; k++)
        worst = Math.max(worst, Math.abs(g.m[16 * i + k] - e[k]));
    });
  }
  return worst <= tol ? '' : `an instance matrix off by ${worst} (allowed ${tol})`;
}

const idle = page => page.evaluate(() => window.phylloPage.idle());
const messages = page => page.evaluate(() => window.phylloPage.messages);
const lines = text => text.split('\n').filter(l => l !== '');

const server = await serve(web);
const base = `http://127.0.0.1:${server.address().port}`;
const browser = await chromium.launch({
  executablePath: chromiumPath,
  args: ['--no-sandbox', '--disable-gpu', '--enable-unsafe-swiftshader',
    '--disable-background-networking', '--disable-component-update',
    '--disable-sync', '--no-first-run', '--disable-quic'],
});
const page = await browser.newPage({ viewport: { width: 1400, height: 860 },
  acceptDownloads: true });
const errors = [], elsewhere = [], dialogs = [];
page.on('pageerror', e => errors.push(e.message));
page.on('console', m => { if (m.type() === 'error') errors.push(m.text()); });
page.on('request', r => { if (!r.url().startsWith(base + '/') && !r.url().startsWith('blob:') && !r.url().startsWith('data:')) elsewhere.push(r.url()); });
page.on('dialog', d => { dialogs.push(d.message()); d.dismiss(); });
// Any policy violation is something of a scene the page tried to run.
await page.addInitScript(() => {
  window.__violations = [];
  document.addEventListener('securitypolicyviolation', e =>
    window.__violations.push(`${e.violatedDirective} ${e.blockedURI}`));
});

try {
  // --- Loading. ---
  await page.goto(`${base}/index.html`);
  await page.waitForFunction(() => window.phylloPage && window.phylloPage.scenePath);
  await idle(page);
  const version = await page.evaluate(async () =>
    new TextDecoder().decode((await window.phyllo.run(['--version'])).stdout));
  report(errors.length === 0 && version === new TextDecoder().decode(native(['--version']).stdout),
    'the page loads with no error; window.phyllo runs the program (--version)', `${errors.join('; ')} ${version}`);

  // --- Every example scene: the organs three.js draws are --csv's. ---
  const index = JSON.parse(fs.readFileSync(`${web}/scenes/index.json`, 'utf8'));
  for (const { scene } of index.examples) {
    await page.selectOption('#example', scene);
    await idle(page);
    const f = await page.evaluate(() => window.phylloPage.frames);
    let csv;
    if (f.used) {
      const dir = `${out}/frames-${path.basename(scene, '.cfg')}`;
      fs.mkdirSync(dir, { recursive: true });
      const n = native(['--csv', '--flatten', '--frames', String(f.count), '-o', `${dir}/f%d.csv`, scene]);
      csv = n.status === 0 ? fs.readFileSync(`${dir}/f${f.at}.csv`, 'utf8') : '';
    } else {
      csv = new TextDecoder().decode(native(['--csv', '--flatten', scene]).stdout);
    }
    const why = await sameOrgans(page, csv);
    const shown = await page.evaluate(() => window.phylloPage.scenePath);
    report(!why && shown === scene, `page: ${scene}: the organs three.js draws are --csv --flatten's${f.used ? `, frame ${f.at} of ${f.count}` : ''}`, why || shown);
  }

  // --- A change in the panel, then the downloads. ---
  await page.selectOption('#example', 'scenes/sunflower.cfg');
  await idle(page);
  for (const [p, v] of [['count', '300'], ['divergence', '137.3']]) {
    await page.fill(`input[data-path="${p}"]`, v);
    await page.press(`input[data-path="${p}"]`, 'Enter');
  }
  await idle(page);
  const sets = ['--set', 'count=300', '--set', 'divergence=137.3'];
  {
    const changes = await page.evaluate(() => window.phylloPage.changes);
    const why = await sameOrgans(page, new TextDecoder().decode(
      native(['--csv', '--flatten', ...sets, 'scenes/sunflower.cfg']).stdout));
    report(!why && changes.join() === 'count=300,divergence=137.3',
      'page: count and divergence changed in the panel: the organs drawn are --csv --set\'s', why || changes.join());
    const marked = await page.locator('.setting:has(input[data-path="count"]) .name').textContent();
    report(marked === 'count *', 'page: the changed setting is marked', marked);
  }
  const lastDigit = [];
  for (const [format, ext] of [['pov', 'inc'], ['blender', 'py'], ['gltf', 'glb'], ['csv', 'csv'], ['svg', 'svg'], ['cfg', 'cfg']]) {
    const [download] = await Promise.all([page.waitForEvent('download'),
      page.click(`.downloads button[data-format="${format}"]`)]);
    const file = `${out}/download.${ext}`;
    await download.saveAs(file);
    const got = new Uint8Array(fs.readFileSync(file));
    const n = native([`--${format}`, ...sets, 'scenes/sunflower.cfg']);
    const c = compare(n.stdout, got);
    if (c.close && !c.identical)
      lastDigit.push(`.${ext} (${c.count} numbers)`);
    report(n.status === 0 && c.close && download.suggestedFilename() === `sunflower.${ext}`,
      `page: the .${ext} download is native --${format} --set count=300 --set divergence=137.3 ${c.identical ? 'byte for byte' : 'to the last digit'}`,
      `${c.first} (${download.suggestedFilename()})`);
  }
  fs.writeFileSync(`${out}/last-digit-page.txt`, lastDigit.join('\n') + '\n');

  // --- Errors: as the native messages, where they belong. ---
  {
    await page.fill('input[data-path="count"]', 'abc');
    await page.press('input[data-path="count"]', 'Enter');
    await idle(page);
    const set = ['--set', 'count=abc', '--set', 'divergence=137.3'];
    const want = new Set([...lines(native(['--settings', ...set, 'scenes/sunflower.cfg']).stderr),
      ...lines(native(['--gltf', ...set, 'scenes/sunflower.cfg']).stderr)]);
    const got = await messages(page);
    const under = await page.locator('.setting:has(input[data-path="count"]) div.err').textContent();
    report(got.length > 0 && got.length === want.size && got.every(m => want.has(m)) && under === got[0],
      'page: a bad value in the panel: the native message, under its field', `${got} / ${[...want]} / ${under}`);
  }
  await page.click('#revert');
  await idle(page);
  {
    await page.fill('#add-setting', 'planar.scael=0.1');
    await page.press('#add-setting', 'Enter');
    await idle(page);
    const want = lines(native(['--settings', '--set', 'planar.scael=0.1', 'scenes/sunflower.cfg']).stderr);
    const shown = await page.locator('.added .err').textContent();
    report(want.length === 1 && shown === want[0] && /did you mean planar\.scale/.test(shown),
      'page: a misspelt setting added: the native message, with its "did you mean"', `${shown} / ${want}`);
  }
  await page.click('#revert');
  await idle(page);
  {
    // The text edited: a count of 0 on its line.
    const text = await page.evaluate(() => window.phylloPage.scene);
    const bad = text.replace('count = 630;', 'count = 0;');
    await page.fill('#text', bad);
    await idle(page);
    const dir = `${out}/edited`;
    fs.rmSync(dir, { recursive: true, force: true });
    fs.mkdirSync(`${dir}/scenes`, { recursive: true });
    fs.cpSync('scenes/organs', `${dir}/scenes/organs`, { recursive: true });
    fs.writeFileSync(`${dir}/scenes/sunflower.cfg`, bad);
    const want = [...new Set([...lines(native(['--settings', 'scenes/sunflower.cfg'], dir).stderr),
      ...lines(native(['--gltf', 'scenes/sunflower.cfg'], dir).stderr)])];
    const got = await messages(page);
    const line = Number(/:(\d+):/.exec(want[0] || '')?.[1]);
    const marked = await page.locator('#gutter span.err').allTextContents();
    const scene = await page.evaluate(() => window.phylloPage.scene);
    report(want.length > 0 && got.join('\n') === want.join('\n') && marked.length === 1 &&
      Number(marked[0]) === line && scene === bad,
      `page: count = 0 typed in the text: the native message (${want[0]}), its line marked`,
      `${got} / ${want} / marked ${marked}`);
    await page.click('#messages li');
    const sel = await page.evaluate(() => {
      const t = document.getElementById('text');
      return t.value.slice(0, t.selectionStart).split('\n').length;
    });
    report(sel === line, 'page: a message clicked selects its line in the text', `line ${sel}`);
  }

  {
    // An expression's error: its line and column.
    const text = await page.evaluate(() => window.phylloPage.scene);
    await page.fill('#text', text.replace('count = 0;', 'count = 630;').replace('"1.1 * r"', '"1.1 * q"'));
    await idle(page);
    const got = await messages(page);
    const at = /:(\d+):(\d+): /.exec(got[0] || '');
    await page.click('#messages li');
    const sel = await page.evaluate(() => {
      const t = document.getElementById('text');
      const before = t.value.slice(0, t.selectionStart).split('\n');
      return [before.length, before[before.length - 1].length + 1,
        t.value.slice(t.selectionStart, t.selectionEnd)];
    });
    report(at !== null && sel[0] === Number(at[1]) && sel[1] === Number(at[2]) && sel[2] === 'q',
      `page: an expression's error (${got[0]}) clicked selects its line and column`, `${got} / ${sel}`);
  }

  // --- A setting the others leave unused: greyed, with the reason. ---
  await page.selectOption('#example', 'scenes/sunflower-emerged.cfg');
  await idle(page);
  {
    const s = JSON.parse(new TextDecoder().decode(native(['--settings', 'scenes/sunflower-emerged.cfg']).stdout))
      .settings.find(x => x.path === 'divergence');
    const row = page.locator('.setting:has(input[data-path="divergence"])');
    const why = await row.locator('.why').textContent();
    const disabled = await page.isDisabled('input[data-path="divergence"]');
    const grey = await row.evaluate(e => e.classList.contains('unused'));
    report(s.applies === false && disabled && grey && why === s.why,
      `page: with the inhibition model the divergence is greyed out, with --settings' reason ("${s.why}")`, `${disabled} ${grey} ${why}`);
  }

  // --- The limits: 10,000,000 organs shown are over the output bound. ---
  await page.selectOption('#example', 'scenes/sunflower.cfg');
  await idle(page);
  {
    await page.fill('input[data-path="count"]', '10000000');
    await page.press('input[data-path="count"]', 'Enter');
    await idle(page);
    const n = native(['--gltf', '--set', 'count=10000000', '--max-output', '256M', 'scenes/sunflower.cfg']);
    const got = await messages(page);
    report(n.status === 1 && got.join('\n') === lines(n.stderr).join('\n'),
      'page: 10,000,000 organs: refused as natively with the page\'s --max-output 256M, before any is placed',
      `${got} / ${n.stderr}`);
    await page.fill('input[data-path="count"]', '10000001');
    await page.press('input[data-path="count"]', 'Enter');
    await idle(page);
    const n2 = native(['--settings', '--set', 'count=10000001', 'scenes/sunflower.cfg']);
    const got2 = await messages(page);
    report(n2.status === 1 && got2[0] === lines(n2.stderr)[0],
      'page: 10,000,001 organs: the native count limit\'s message', `${got2} / ${n2.stderr}`);
  }

  // --- A growing scene: the frames slider. ---
  await page.selectOption('#example', 'scenes/stages.cfg');
  await idle(page);
  {
    const visible = await page.isVisible('#frames');
    await page.fill('#frame-count', '4');
    await page.press('#frame-count', 'Enter');
    await idle(page);
    await page.evaluate(() => {
      const r = document.getElementById('frame');
      r.value = 3;
      r.dispatchEvent(new Event('input'));
    });
    await page.waitForFunction(() => window.phylloPage.frames.at === 3);
    await page.waitForTimeout(300);
    const dir = `${out}/stages4`;
    fs.mkdirSync(dir, { recursive: true });
    native(['--csv', '--flatten', '--frames', '4', '-o', `${dir}/s%d.csv`, 'scenes/stages.cfg']);
    const why = await sameOrgans(page, fs.readFileSync(`${dir}/s3.csv`, 'utf8'));
    report(visible && !why, 'page: stages.cfg reads f: a frames slider; at frame 3 of 4 the organs are --frames 4\'s third', why || `slider shown: ${visible}`);
    const [download] = await Promise.all([page.waitForEvent('download'),
      page.click('.downloads button[data-format="csv"]')]);
    await download.saveAs(`${out}/stages-3.csv`);
    const c = compare(fs.readFileSync(`${dir}/s3.csv`), fs.readFileSync(`${out}/stages-3.csv`));
    // --flatten changes nothing for a scene without parts.
    report(c.close && download.suggestedFilename() === 'stages-3.csv',
      'page: the .csv download at frame 3 is native --frames 4\'s third file', `${c.first} ${download.suggestedFilename()}`);
    await page.fill('#frame-count', '100001');
    await page.press('#frame-count', 'Enter');
    await idle(page);
    const n = native(['--gltf', '--frames', '100001', '-o', 'x%d.glb', 'scenes/stages.cfg']);
    const got = await messages(page);
    report(n.status === 2 && got.join('\n') === lines(n.stderr).join('\n'),
      'page: 100001 frames: the native --frames limit\'s message', `${got} / ${n.stderr}`);
    await page.fill('#frame-count', '10');
    await page.press('#frame-count', 'Enter');
    await idle(page);
  }

  // --- A long run: its progress, and Cancel. ---
  {
    const long = 'model = "collision";\ncount = 2000000;\ncollision = { receptacle = { shape = "hemisphere"; }; radius = 0.0012; };\n';
    await page.setInputFiles('#files', { name: 'long.cfg', mimeType: 'text/plain', buffer: Buffer.from(long) });
    await page.waitForSelector('#cancel', { state: 'visible', timeout: 20000 });
    await page.waitForFunction(() => /placed [0-9]+ primordia|written/.test(
      document.getElementById('status').textContent), null, { timeout: 20000 });
    const progress = await page.textContent('#status');
    // Clicked in the page, timed there: the time to stop the run.
    const stopped = Math.round(await page.evaluate(() => {
      const t = performance.now();
      document.getElementById('cancel').click();
      return window.phylloPage.idle().then(() => performance.now() - t);
    }));
    const after = await page.textContent('#status');
    await page.selectOption('#example', 'scenes/sunflower.cfg');
    await idle(page);
    const n = await page.evaluate(() => window.phylloPage.instances);
    report(after === 'cancelled' && n === 630 && stopped < 1000,
      `page: a long run shows the program's progress ("${progress}"), Cancel stops it (in ${stopped} ms), the next scene runs`,
      `status ${after} after ${stopped} ms, then ${n} organs`);
  }

  // --- Files that are not text, or too big. ---
  {
    const before = await page.evaluate(() => window.phylloPage.scenePath);
    await page.setInputFiles('#files', { name: 'picture.png', mimeType: 'image/png',
      buffer: fs.readFileSync('scenes/sunflower.png') });
    const shown = await page.locator('#messages li').first().textContent();
    const big = `${out}/big.cfg`;
    fs.writeFileSync(big, '');
    fs.truncateSync(big, 100 * 1024 * 1024);
    await page.setInputFiles('#files', big);
    await page.waitForFunction(() => /big\.cfg/.test(document.getElementById('messages').textContent));
    const shownBig = await page.locator('#messages li').first().textContent();
    const after = await page.evaluate(() => window.phylloPage.scenePath);
    fs.rmSync(big);
    report(/^picture\.png: not a text file/.test(shown) &&
      /^big\.cfg: 104,857,600 bytes: the page opens files of up to 16 MiB$/.test(shownBig) && after === before,
      'page: a file that is not text, and a 100 MB one, are refused with a message; the scene stays', `${shown} / ${shownBig} / ${after}`);
  }

  // --- Files dropped on the page: the scene and its mesh. ---
  {
    const scene = 'model = "planar";\ncount = 40;\norgans = ( { object = "Arrow"; mesh = "arrow.obj"; } );\n';
    await page.evaluate(([scene, obj, mtl]) => {
      const dt = new DataTransfer();
      dt.items.add(new File([scene], 'dropped.cfg'));
      dt.items.add(new File([obj], 'arrow.obj'));
      dt.items.add(new File([mtl], 'arrow.mtl'));
      document.body.dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
    }, [scene, fs.readFileSync('tests/gltf/arrow.obj', 'utf8'), fs.readFileSync('tests/gltf/arrow.mtl', 'utf8')]);
    await page.waitForFunction(() => window.phylloPage.scenePath === 'dropped.cfg');
    await idle(page);
    const dir = `${out}/dropped`;
    fs.mkdirSync(dir, { recursive: true });
    fs.writeFileSync(`${dir}/dropped.cfg`, scene);
    fs.copyFileSync('tests/gltf/arrow.obj', `${dir}/arrow.obj`);
    fs.copyFileSync('tests/gltf/arrow.mtl', `${dir}/arrow.mtl`);
    const n = native(['--csv', 'dropped.cfg'], dir);
    const why = await sameOrgans(page, new TextDecoder().decode(n.stdout));
    const got = await messages(page);
    report(!why && got.length === 0, 'page: a scene and its mesh dropped on the page: shown, the organs --csv\'s, no message', why || got.join('; '));
  }

  // --- Markup and script in a scene run nowhere. ---
  {
    const evil = '<img src=x onerror="window.__pwned=1"><script>window.__pwned=2</script>';
    const scene = `# ${evil}\nname = "Evil";\nmodel = "planar";\ncount = 50;\n` +
      `organs = ( { object = "Seed"; mesh = "evil.obj"; tilt = "${evil.replace(/"/g, "'")}"; } );\n`;
    const obj = `# ${evil}\nmtllib evil.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl ${evil}\nf 1 2 3\n`;
    const mtl = `newmtl ${evil}\nKd 1 0 0\n`;
    const files = [
      { name: 'evil.cfg', mimeType: 'text/plain', buffer: Buffer.from(scene) },
      { name: 'evil.obj', mimeType: 'text/plain', buffer: Buffer.from(obj) },
      { name: 'evil.mtl', mimeType: 'text/plain', buffer: Buffer.from(mtl) },
    ];
    await page.setInputFiles('#files', files);
    await idle(page);
    const got1 = await messages(page);
    // Without the bad tilt, the names of the mesh's material reach the
    // .glb and three.js.
    await page.fill('#text', scene.replace(/tilt = "[^"]*"; /, ''));
    await idle(page);
    await page.fill('#add-setting', `name=${evil}`);
    await page.press('#add-setting', 'Enter');
    await idle(page);
    const got2 = await messages(page);
    const state = await page.evaluate(() => ({
      pwned: window.__pwned,
      violations: window.__violations,
      handlers: [...document.querySelectorAll('*')].filter(e =>
        [...e.attributes].some(a => a.name.startsWith('on'))).length,
      foreign: document.querySelectorAll('script:not([src]):not([type="importmap"]), img[src="x"], iframe, object, embed').length,
      text: document.getElementById('text').value,
      listed: document.getElementById('messages').textContent + document.querySelector('.added').textContent,
      drawn: window.phylloPage.instances,
    }));
    report(state.pwned === undefined && state.violations.length === 0 && dialogs.length === 0 &&
      state.handlers === 0 && state.foreign === 0 && state.text.includes('<script>') &&
      state.listed.includes('<img src=x') && got1.length > 0 && got2.length > 0,
      'page: a scene, mesh and .mtl holding markup and script, and a --set of it: shown as text, nothing ran, no policy violated',
      JSON.stringify({ ...state, text: undefined, listed: undefined, dialogs, got1, got2 }));
  }

  // The README's picture: the coneflower, its divergence changed.
  await page.selectOption('#example', 'scenes/coneflower.cfg');
  await idle(page);
  await page.fill('input[data-path="divergence"]', '137.45');
  await page.press('input[data-path="divergence"]', 'Enter');
  await idle(page);
  await page.waitForTimeout(500);
  await page.screenshot({ path: `${out}/page.png` });

  report(elsewhere.length === 0, `page: nothing fetched but from ${base} (offline)`, elsewhere.join(' '));
  report(errors.length === 0, 'page: no error in the console all along', errors.join('; '));
} catch (e) {
  report(false, 'page: the tests ran to their end', e.stack);
} finally {
  await browser.close();
  server.close();
}
process.exit(failed ? 1 : 0);
