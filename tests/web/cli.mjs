// cli.mjs - the WebAssembly build's module (phyllo.mjs) in Node.js held
// against the native program, run by run: the exit status and the
// messages exactly, the output byte for byte or, where emscripten's
// maths library rounds a last bit apart, to the last printed digit
// (same.mjs says which); every example scene with every writer, every
// regression case, the command line's behaviours, the limits, and that
// no run sees another's state.  Prints "ok - " and "not ok - " lines
// for tests/run.sh, and the writers and scenes that differ in a last
// digit to OUT/last-digit.txt.  From the top of the tree:
//   node tests/web/cli.mjs PHYLLO WEB OUT
import fs from 'node:fs';
import path from 'node:path';
import { spawnSync } from 'node:child_process';
import { compare } from './same.mjs';

const [phyllo, web, out] = process.argv.slice(2);
const { run, MEMORY_LIMIT } = await import(path.resolve(web, 'phyllo.mjs'));

let failed = 0;
function report(ok, what, why = '') {
  console.log(ok ? `ok - ${what}` : `not ok - ${what}: ${why}`);
  if (!ok)
    failed++;
}

// Every file under dirs a scene may read, by its path from the top.
function collect(dirs, exts) {
  const files = {};
  const walk = d => {
    for (const e of fs.readdirSync(d, { withFileTypes: true })) {
      const p = `${d}/${e.name}`;
      if (e.isDirectory())
        walk(p);
      else if (exts.test(p))
        files[p] = fs.readFileSync(p);
    }
  };
  dirs.forEach(walk);
  return files;
}
// Scenes, parts, meshes, templates, and the measured model's points.
const FILES = collect(['scenes', 'tests/regress', 'tests/gltf'],
  /\.(cfg|obj|mtl|tmpl)$|\/points\/[^/]+$/);
FILES['tests/placeholders.tmpl'] = fs.readFileSync('tests/placeholders.tmpl');

function native(args, input) {
  const r = spawnSync(phyllo, args, { maxBuffer: 1 << 30, input });
  return { status: r.status, stdout: new Uint8Array(r.stdout),
    stderr: r.stderr.toString() };
}

const lastDigit = [];

// One command both ways: '' where they agree, else why not; the
// module's result in last.
let last = null;
async function both(args, files = FILES, options = {}) {
  const n = native(args, options.stdin);
  const w = last = await run(args, files, options);
  if (n.status !== w.status)
    return `exit ${w.status}, native ${n.status} (${w.stderr.slice(0, 200)})`;
  if (n.stderr !== w.stderr)
    return `stderr ${JSON.stringify(w.stderr.slice(0, 300))}, native ${JSON.stringify(n.stderr.slice(0, 300))}`;
  const c = compare(n.stdout, w.stdout);
  if (!c.close)
    return `output differs: ${c.first}`;
  if (!c.identical)
    lastDigit.push(`${args.join(' ')}: ${c.count} numbers (first: ${c.first})`);
  return '';
}

// --- Every example scene, every writer. ---
const WRITERS = ['--pov', '--blender', '--gltf', '--csv', '--svg', '--info',
  '--settings', '--cfg'];
const scenes = fs.readdirSync('scenes').filter(f => f.endsWith('.cfg')).sort();
for (const s of scenes) {
  const bad = [];
  for (const w of WRITERS) {
    const why = await both([w, `scenes/${s}`]);
    if (why)
      bad.push(`${w}: ${why}`);
  }
  report(bad.length === 0, `module = native: scenes/${s}, every writer`, bad.join('; '));
}

// --- Every regression case, as tests/regress.sh runs it. ---
const groups = fs.readdirSync('tests/regress', { withFileTypes: true })
  .filter(e => e.isDirectory()).map(e => e.name).sort();
const TMPL_SCENE = 'tests/regress/planar/vogel90.cfg';
for (const g of groups) {
  const dir = `tests/regress/${g}`;
  const errArgs = fs.existsSync(`${dir}/args`) ?
    fs.readFileSync(`${dir}/args`, 'utf8').trim().split(/\s+/) : ['--csv'];
  const bad = [];
  let cases = 0;
  for (const f of fs.readdirSync(dir).sort()) {
    const m = /^(.*)\.(cfg|tmpl)$/.exec(f);
    if (m === null)
      continue;
    const base = `${dir}/${m[1]}`;
    if (fs.existsSync(`${base}.err`)) {
      // As regress.sh: -o a file that must stay as it was.
      cases++;
      const args = [...errArgs, '-o', `${out}/target`,
        ...(m[2] === 'tmpl' ? ['--template', `${dir}/${f}`, TMPL_SCENE] : [`${dir}/${f}`])];
      fs.writeFileSync(`${out}/target`, 'precious\n');
      const files = { ...FILES, [`${out}/target`]: 'precious\n' };
      const why = await both(args, files);
      const w = last;
      if (why)
        bad.push(`${f}: ${why}`);
      else if (w.stderr !== fs.readFileSync(`${base}.err`, 'utf8'))
        bad.push(`${f}: not the message of ${base}.err`);
      else if (Object.keys(w.files).length !== 0)
        bad.push(`${f}: wrote ${Object.keys(w.files)}`);
      continue;
    }
    if (m[2] !== 'cfg')
      continue;
    for (const [ext, fmt] of [['csv', '--csv'], ['info', '--info'], ['pov', '--pov'], ['py', '--blender'], ['svg', '--svg']]) {
      if (!fs.existsSync(`${base}.${ext}`))
        continue;
      cases++;
      const why = await both([fmt, `${dir}/${f}`]);
      if (why)
        bad.push(`${f} ${fmt}: ${why}`);
    }
  }
  report(bad.length === 0, `module = native: tests/regress/${g}, ${cases} cases`, bad.join('; '));
}

// --- The command line. ---
const SUN = 'scenes/sunflower.cfg';
const sunText = fs.readFileSync(SUN, 'utf8');
const behaviours = [
  ['--help', ['--help']],
  ['--version', ['--version']],
  ['no format: a usage error', [SUN]],
  ['an unknown option, and its nearest', ['--inof', SUN]],
  ['two formats', ['--csv', '--pov', SUN]],
  ['--set, two of them', ['--csv', '--set', 'count=300', '--set', 'planar.scale=0.05', SUN]],
  ['--set of a misspelt setting: did you mean', ['--csv', '--set', 'planar.scael=0.1', SUN]],
  ['--set of a value out of range', ['--csv', '--set', 'count=0', SUN]],
  ['--set of a part\'s setting', ['--csv', '--flatten', '--set', 'Achene:count=30', 'scenes/goatsbeard.cfg']],
  ['--template', ['--pov', '--template', 'tests/placeholders.tmpl', TMPL_SCENE]],
  ['--arrays', ['--pov', '--arrays', SUN]],
  ['--blender-objects', ['--blender', '--blender-objects', SUN]],
  ['--csv --flatten of a compound', ['--csv', '--flatten', 'scenes/flowershop.cfg']],
  ['--max-output refuses before writing', ['--csv', '--max-output', '10K', SUN]],
  ['a scene that is not there', ['--csv', 'scenes/none.cfg']],
  ['--frames 0', ['--csv', '--frames', '0', 'scenes/stages.cfg']],
  ['--frames 100001: over the limit', ['--csv', '--frames', '100001', '-o', 'x%d.csv', 'scenes/stages.cfg']],
  ['--frames without %d in -o', ['--csv', '--frames', '3', '-o', 'x.csv', 'scenes/stages.cfg']],
  ['count over the limit', ['--csv', '--set', 'count=10000001', SUN]],
  ['a growing --frames past the output limit', ['--csv', '--frames', '100000', '--set', 'count="100 + 1000000 * f"', '-o', 'x%d.csv', 'scenes/stages.cfg']],
];
for (const [what, args] of behaviours) {
  if (!fs.existsSync(args[args.length - 1]) && what !== 'a scene that is not there' &&
      !args.includes('--help') && !args.includes('--version')) {
    report(false, `module = native: ${what}`, `${args[args.length - 1]} is not there`);
    continue;
  }
  const why = await both(args);
  report(why === '', `module = native: ${what} (${args.join(' ').slice(0, 70)})`, why);
}
{
  const why = await both(['--csv', '-'], FILES, { stdin: sunText });
  report(why === '', 'module = native: the scene from standard input (-)', why);
}

// -o: the file, whole, in files; nothing on stdout; an input never.
{
  const w = await run(['--gltf', '-o', 'sun.glb', SUN], FILES);
  const n = native(['--gltf', SUN]);
  const c = compare(n.stdout, w.files['sun.glb'] || new Uint8Array(0));
  report(w.status === 0 && w.stdout.length === 0 && c.close &&
    Object.keys(w.files).join() === 'sun.glb',
    '-o sun.glb: the .glb in files, as native --gltf writes it, nothing on stdout',
    `exit ${w.status}, files ${Object.keys(w.files)}, ${c.first}`);
}
{
  const why = await both(['--pov', '-o', 'scenes/organs/seed.obj', SUN]);
  const w = last;
  report(why === '' && w.status === 2 && Object.keys(w.files).length === 0,
    '-o naming an input (a mesh) is the native usage error; nothing written', why || `files ${Object.keys(w.files)}`);
}
{
  const args = ['--csv', '--frames', '4', '-o', 'stage%d.csv', 'scenes/stages.cfg'];
  const w = await run(args, FILES);
  let bad = '';
  fs.mkdirSync(`${out}/frames`, { recursive: true });
  const n = spawnSync(phyllo, ['--csv', '--frames', '4', '-o', `${out}/frames/stage%d.csv`, 'scenes/stages.cfg']);
  for (let i = 1; i <= 4; i++) {
    const got = w.files[`stage${i}.csv`];
    const want = fs.readFileSync(`${out}/frames/stage${i}.csv`);
    if (!got || !compare(want, got).close)
      bad += ` stage${i}.csv`;
  }
  report(w.status === 0 && n.status === 0 && !bad && Object.keys(w.files).length === 4,
    '--frames 4 -o stage%d.csv: four files, each native\'s', `exit ${w.status}; differ:${bad}`);
}
{
  // A file given and replaced by -o comes back new; one given and not
  // written does not come back.
  const w = await run(['--csv', '-o', 'old.csv', SUN], { ...FILES, 'old.csv': 'old\n', 'other.txt': 'x' });
  report(w.status === 0 && Object.keys(w.files).join() === 'old.csv' &&
    new TextDecoder().decode(w.files['old.csv']).startsWith('n,object,'),
    '-o over a file given: the new file in files, the others not', Object.keys(w.files).join());
}

// --- Limits. ---
{
  const w = await run(['--csv', '-o', 'x.csv', 's.cfg'],
    { 's.cfg': 'model = "planar";\ncount = 1000000;\n' }, { memory: 64 << 20 });
  report(w.status === 3 && w.stderr === 'phyllo-export: out of memory\n' &&
    Object.keys(w.files).length === 0,
    'memory bound (options.memory, 64 MiB here): past it, the program\'s own "out of memory", exit 3, no file left',
    `exit ${w.status}, ${JSON.stringify(w.stderr)}, files ${Object.keys(w.files)}`);
  report(MEMORY_LIMIT === 2 ** 31, 'MEMORY_LIMIT is 2 GiB, as the page says', String(MEMORY_LIMIT));
}

// --- No run sees another's state. ---
{
  const args = ['--csv', SUN];
  const first = await run(args, FILES);
  // A failed run (diag's status, which only rises), an out-of-memory
  // run (exit() with -o's temporary file pending) and a run leaving a
  // file in between.
  await run(['--csv', '--set', 'count=0', SUN], FILES);
  await run(['--csv', '-o', 'x.csv', 's.cfg'], { 's.cfg': 'model = "planar";\ncount = 1000000;\n' }, { memory: 64 << 20 });
  const left = await run(['--pov', '-o', 'left.tmpl', SUN], FILES);
  const after = await run(args, FILES);
  const same = (a, b) => a.status === b.status && a.stderr === b.stderr &&
    compare(a.stdout, b.stdout).identical;
  report(first.status === 0 && same(first, after),
    'a run after a failed one and an out-of-memory one: exit 0, the same bytes', `exit ${after.status} ${after.stderr}`);
  const reads = await run(['--pov', '--template', 'left.tmpl', SUN], FILES);
  report(left.status === 0 && reads.status === 1 && reads.stderr ===
    'phyllo-export: left.tmpl: cannot read template: No such file or directory\n',
    'a file one run wrote is not there for the next', reads.stderr);
  // Side by side: runs started together, each on its own instance.
  const scenesTried = ['scenes/sunflower.cfg', 'scenes/pinecone.cfg', 'scenes/coneflower.cfg', 'scenes/goatsbeard.cfg'];
  const alone = [];
  for (const s of scenesTried)
    alone.push(await run(['--csv', s], FILES));
  const together = await Promise.all(scenesTried.map(s => run(['--csv', s], FILES)));
  report(together.every((r, i) => same(r, alone[i])),
    'runs started together: each the bytes it makes alone');
}

fs.writeFileSync(`${out}/last-digit.txt`, lastDigit.join('\n') + '\n');
report(true, `module = native byte for byte but ${lastDigit.length} outputs, equal to their last printed digit (emscripten's maths: see ${out}/last-digit.txt)`);
process.exit(failed ? 1 : 0);
