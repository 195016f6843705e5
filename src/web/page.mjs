// page.mjs - the page: a scene (an example, or your own files), its text
// in the editor, its settings in the panel, and on every change the
// program run again in a Worker (runner.mjs) for the structure in
// three.js (--gltf), the SVG preview (--svg) and the summary (--info);
// a download a writer.  For scripts and tests: window.phyllo (the
// module) and window.phylloPage (what the page shows).
import * as phyllo from './phyllo.mjs';
import { Runner, Cancelled } from './runner.mjs';
import { Editor, parseMessage } from './editor.mjs';
import { Panel } from './panel.mjs';
import { View } from './view.mjs';

// The largest file the page opens, and the most output a change may
// make (the program refuses more, before it writes a byte).
const FILE_MAX = 16 * 1024 * 1024;
const VIEW_OUTPUT = '256M';
const DOWNLOAD_OUTPUT = '1G';
// A run still going after this long when the scene changes again is
// cancelled rather than waited for.
const STALE_MS = 250;
// Text edits are run once typing pauses this long.
const TYPING_MS = 150;

const $ = id => document.getElementById(id);

const state = {
  files: {},		// path -> text: the scene, its parts, meshes, templates
  scene: null,		// the scene's path
  changes: new Map(),	// the panel's --set PATH=VALUE, in order
  applies: new Map(),	// path -> whether it applies (--settings)
  frames: { used: false, count: 10, at: 1, glb: [], svg: [], info: [] },
  generation: 0,
  reframe: true,
  messages: [],
  timing: {},
  changedAt: null,	// when the change being run was made
  pending: 0,		// what idle() waits for: updates, files being read
  idle: [],
  fault: null,
};

const runner = new Runner(new URL('./worker.mjs', import.meta.url));
const view = new View($('view'));
const editor = new Editor({ select: $('file'), gutter: $('gutter'),
  text: $('text'), messages: $('messages') }, edited);
editor.onSwitch = path => editor.show(path, state.files[path]);
const panel = new Panel($('settings'), $('last'), setting);
let previewUrl = null;

// --- What the page runs. ---

// The panel's changes as --set arguments: those that apply (all: every
// one, as --settings takes them to say which apply).
function sets(all = false) {
  const args = [];
  for (const [path, value] of state.changes)
    if (all || state.applies.get(path) !== false)
      args.push('--set', `${path}=${value}`);
  return args;
}

// Whether the scene or a part of it (--settings' "parts") reads f or F
// (the frame) in an expression: a string not naming something.
function usesFrames(json) {
  const expr = /(^|[^"\w])(?!object\b|name\b|model\b|mesh\b|scene\b|shape\b)\w+\s*=\s*"[^"\n]*\b[fF]\b[^"\n]*"/m;
  return [json.scene, ...json.parts.map(p => p.scene)]
    .some(p => expr.test(state.files[p] || ''));
}

function status(text) {
  $('status').textContent = text;
}

// Run args on the scene's files; throws Cancelled if cancelled.
async function run(what, args, progress = true) {
  const t0 = performance.now();
  let line = '';
  const tick = setInterval(() => {
    const s = (performance.now() - t0) / 1000;
    status(`${what}: ${s.toFixed(1)} s${line ? ' — ' + line : ''}`);
    $('cancel').hidden = false;
  }, 300);
  try {
    return await runner.run(args, state.files, progress ? l => { line = l; } : null);
  } finally {
    clearInterval(tick);
    $('cancel').hidden = true;
    status('');
  }
}

function lines(stderr) {
  return stderr.split('\n').filter(l => l !== '');
}

function showMessages(list) {
  state.messages = list;
  const parsed = list.map(parseMessage);
  const rest = panel.errors(parsed);
  addedErrors(rest);
  editor.setMessages(list);
}

/*
 * The scene as it stands, run again: the structure first (the picture),
 * then its settings for the panel, the preview and the summary.  The
 * changes that apply are those of the last --settings; where the new
 * one says otherwise, the structure is run again.  A run still going
 * for an older state is waited for, or cancelled once it has taken
 * STALE_MS.
 */
async function update() {
  const gen = ++state.generation;
  const t0 = state.changedAt ?? performance.now();
  state.changedAt = null;
  state.pending++;
  try {
    if (runner.busy && runner.elapsed() > STALE_MS)
      runner.cancel();
    await runner.idle();
    if (gen !== state.generation)
      return;
    await build(gen, t0);
  } catch (e) {
    if (e instanceof Cancelled)
      status('cancelled');
    else
      fault(e);
  } finally {
    settled();
  }
}

// One thing idle() waits for is done.
function settled() {
  state.pending--;
  if (state.pending === 0) {
    const all = state.idle;
    state.idle = [];
    all.forEach(r => r());
  }
}

// The frames' files of a run with -o view%d.EXT, or its standard output.
function framesOf(r, ext) {
  const f = state.frames;
  return f.used ? Array.from({ length: f.count },
    (_, i) => r.files[`view${i + 1}.${ext}`]) : [r.stdout];
}

// The arguments of a run for the page: the changes, the output bound,
// and with frames every frame, one file each.
function viewArgs(format, ext) {
  const f = state.frames;
  return [`--${format}`, ...sets(), '--max-output', VIEW_OUTPUT,
    ...(f.used ? ['--frames', String(f.count), '-o', `view%d.${ext}`] : []),
    state.scene];
}

async function build(gen, t0) {
  const frames = state.frames;
  const stale = () => gen !== state.generation;
  let glb = null, applied;
  do {
    applied = sets().join('\n');
    glb = await run('the structure', viewArgs('gltf', 'glb'));
    if (stale())
      return;
    if (glb.status === 0) {
      view.parent.classList.remove('stale');
      frames.glb = framesOf(glb, 'glb');
      frames.at = Math.min(Math.max(1, frames.at), frames.used ? frames.count : 1);
      await view.show(frames.glb[frames.at - 1], state.reframe);
      state.reframe = false;
      // Timed: the picture drawn (its draw calls made), then the frame
      // handed on to be shown, which waits for the GPU to draw it.
      state.timing = { picture: performance.now() - t0 };
      await new Promise(r => requestAnimationFrame(() => setTimeout(r, 0)));
      state.timing.frame = performance.now() - t0;
    } else {
      view.parent.classList.add('stale');
    }
    const set = await run('the settings', ['--settings', ...sets(true), state.scene]);
    if (stale())
      return;
    showMessages([...new Set(lines(set.stderr).concat(lines(glb.stderr)))]);
    if (set.status !== 0)
      return;
    const json = JSON.parse(new TextDecoder().decode(set.stdout));
    state.applies = new Map(json.settings.map(s => [s.path, s.applies !== false]));
    panel.build(json.settings, state.changes);
    added(json.settings);
    const used = usesFrames(json);
    $('frames').hidden = !used;
    if (used !== frames.used) {
      frames.used = used;
      applied = null;	// run again, frame by frame or not
    }
  } while (applied !== sets().join('\n'));
  if (glb.status !== 0)
    return;

  const svg = await run('the preview', viewArgs('svg', 'svg'));
  if (stale())
    return;
  frames.svg = svg.status === 0 ? framesOf(svg, 'svg') : [];
  const info = await run('the summary', viewArgs('info', 'info'));
  if (stale())
    return;
  frames.info = info.status === 0 ? framesOf(info, 'info') : [];
  showFrame();
  state.timing.all = performance.now() - t0;
}

// The frame the slider is at: its structure, preview and summary.
function showFrame() {
  const f = state.frames, i = f.at - 1;
  $('frame').max = f.count;
  $('frame').value = f.at;
  $('frame-at').textContent = f.at;
  if (previewUrl !== null)
    URL.revokeObjectURL(previewUrl);
  previewUrl = f.svg[i] ? URL.createObjectURL(new Blob([f.svg[i]],
    { type: 'image/svg+xml' })) : null;
  if (previewUrl !== null)
    $('preview').src = previewUrl;
  else
    $('preview').removeAttribute('src');
  $('info').textContent = f.info[i] ? new TextDecoder().decode(f.info[i]) : '';
}

function fault(e) {
  state.fault = e;
  status(`the page failed: ${e.message}`);
  console.error(e);
}

// --- Changes. ---

function changed(reframe = false) {
  state.changedAt ??= performance.now();
  if (reframe)
    state.reframe = true;
  update();
}

let typing = null;
function edited(path, text) {
  state.files[path] = text;
  state.changedAt ??= performance.now();
  if (typing === null)
    state.pending++;	// for idle(): a run is on its way
  clearTimeout(typing);
  typing = setTimeout(() => {
    typing = null;
    changed();
    settled();
  }, TYPING_MS);
}

function setting(path, value) {
  if (value === null || value === '')
    state.changes.delete(path);
  else
    state.changes.set(path, value);
  panelButtons();
  changed();
}

function panelButtons() {
  $('apply').disabled = $('revert').disabled = state.changes.size === 0;
}

// Changes the panel has no field for (added as path=value): listed
// under the box, each with its ↺ and the program's message.
const addedList = document.createElement('ul');
addedList.className = 'added';
$('add').after(addedList);

function added(settings) {
  const known = new Set(settings.map(s => s.path));
  state.unlisted = [...state.changes].filter(([p]) => !known.has(p));
  renderAdded();
}

function renderAdded(errors = []) {
  addedList.replaceChildren(...(state.unlisted || []).map(([p, v]) => {
    const li = document.createElement('li');
    const undo = document.createElement('button');
    undo.type = 'button';
    undo.textContent = '↺';
    undo.title = 'Undo';
    undo.addEventListener('click', () => setting(p, null));
    const err = document.createElement('div');
    err.className = 'err';
    err.textContent = errors.filter(m => m.set === p).map(m => m.text).join('\n');
    li.append(`${p}=${v} `, undo, err);
    return li;
  }));
}

function addedErrors(rest) {
  const known = new Set(state.changes.keys());
  state.unlisted = (state.unlisted || []).concat([...state.changes]
    .filter(([p]) => rest.some(m => m.set === p) &&
      !(state.unlisted || []).some(([q]) => q === p)));
  renderAdded(rest.filter(m => known.has(m.set)));
}

$('add').addEventListener('submit', e => {
  e.preventDefault();
  const text = $('add-setting').value;
  const eq = text.indexOf('=');
  if (eq <= 0)
    return;
  $('add-setting').value = '';
  setting(text.slice(0, eq).trim(), text.slice(eq + 1).trim());
});

$('revert').addEventListener('click', () => {
  state.changes.clear();
  panelButtons();
  changed();
});

// The changes written into the scene's text (--cfg), as Save does in
// the Blender panel; the changes are then the text's.
$('apply').addEventListener('click', async () => {
  const r = await run('writing the changes', ['--cfg', ...sets(), state.scene], false);
  if (r.status !== 0) {
    showMessages(lines(r.stderr));
    return;
  }
  state.files[state.scene] = new TextDecoder().decode(r.stdout);
  state.changes.clear();
  panelButtons();
  if (editor.path === state.scene)
    editor.show(state.scene, state.files[state.scene]);
  changed();
});

$('frame').addEventListener('input', () => {
  state.frames.at = Number($('frame').value);
  if (state.frames.glb[state.frames.at - 1])
    view.show(state.frames.glb[state.frames.at - 1], false);
  showFrame();
});

$('frame-count').addEventListener('change', () => {
  const n = Number($('frame-count').value);
  // The program says what it takes: 1 to 100000 (a usage error else).
  state.frames.count = Number.isInteger(n) && n >= 1 ? n : 1;
  changed();
});

$('cancel').addEventListener('click', () => runner.cancel());

// --- Downloads: each writer's file for the scene as it stands. ---

const EXT = { pov: 'inc', blender: 'py', gltf: 'glb', csv: 'csv', svg: 'svg', cfg: 'cfg' };
const MIME = { glb: 'model/gltf-binary', svg: 'image/svg+xml' };

function downloadArgs(format) {
  const f = state.frames;
  const ext = EXT[format];
  const args = [`--${format}`, ...sets()];
  if (format !== 'cfg')
    args.push('--max-output', DOWNLOAD_OUTPUT);
  // A growing scene: every frame, the Blender script animating them,
  // else the file of the frame shown.
  if (f.used && format !== 'cfg')
    args.push('--frames', String(f.count), '-o', format === 'blender' ?
      `out.${ext}` : `out%d.${ext}`);
  return [...args, state.scene];
}

async function download(format) {
  const ext = EXT[format];
  const f = state.frames;
  const r = await run(`the .${ext}`, downloadArgs(format));
  if (r.status !== 0) {
    showMessages(lines(r.stderr));
    return;
  }
  const bytes = !(f.used && format !== 'cfg') ? r.stdout :
    r.files[format === 'blender' ? `out.${ext}` : `out${f.at}.${ext}`];
  const base = state.scene.replace(/^.*\//, '').replace(/\.cfg$/, '');
  const name = f.used && format !== 'cfg' && format !== 'blender' ?
    `${base}-${f.at}.${ext}` : `${base}.${ext}`;
  const url = URL.createObjectURL(new Blob([bytes],
    { type: MIME[ext] || 'text/plain' }));
  const a = document.createElement('a');
  a.href = url;
  a.download = name;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10000);
}

for (const b of document.querySelectorAll('.downloads button')) {
  b.addEventListener('click', async () => {
    b.disabled = true;
    try {
      await download(b.dataset.format);
    } catch (e) {
      if (!(e instanceof Cancelled))
        fault(e);
    } finally {
      b.disabled = false;
    }
  });
}

// --- Scenes: the examples, or your own files. ---

let examples = null;

async function loadExamples() {
  const index = await (await fetch('scenes/index.json')).json();
  const files = {};
  await Promise.all(index.files.map(async f => {
    files[f] = await (await fetch(f)).text();
  }));
  examples = { index, files };
  $('example').replaceChildren(...index.examples.map(e => {
    const o = document.createElement('option');
    o.value = e.scene;
    o.textContent = e.scene.replace(/^scenes\//, '').replace(/\.cfg$/, '');
    o.title = e.about;
    return o;
  }), Object.assign(document.createElement('option'),
    { value: '', textContent: '(your files)', disabled: true }));
}

function open(files, scene, about = '') {
  state.files = files;
  state.scene = scene;
  state.changes.clear();
  state.applies.clear();
  state.frames.at = 1;
  panelButtons();
  $('about').textContent = about;
  $('about').title = about;
  const texts = Object.keys(files).filter(p => !/\.(obj|mtl)$/i.test(p));
  editor.setFiles([scene, ...texts.filter(p => p !== scene).sort()], scene);
  editor.show(scene, files[scene]);
  changed(true);
}

function openExample(scene) {
  const e = examples.index.examples.find(x => x.scene === scene);
  if (e === undefined)
    return false;
  $('example').value = scene;
  open({ ...examples.files }, scene, e.about);
  return true;
}

$('example').addEventListener('change', () => openExample($('example').value));

/*
 * Files opened or dropped ([{ path, file }]): text files of up to
 * FILE_MAX, the scene the .cfg no other names (or the shallowest).
 */
async function openFiles(list) {
  state.pending++;	// for idle(): the files are being read
  try {
    await readFiles(list);
  } finally {
    settled();
  }
}

async function readFiles(list) {
  const files = {}, problems = [];
  const decoder = new TextDecoder('utf-8', { fatal: true, ignoreBOM: true });
  for (const { path, file } of list) {
    if (file.size > FILE_MAX) {
      problems.push(`${path}: ${file.size.toLocaleString('en')} bytes: the page opens files of up to ${FILE_MAX / 1048576} MiB`);
      continue;
    }
    const bytes = new Uint8Array(await file.arrayBuffer());
    let text = null;
    try {
      text = bytes.includes(0) ? null : decoder.decode(bytes);
    } catch {
      text = null;
    }
    if (text === null) {
      problems.push(`${path}: not a text file: the page opens scene files (.cfg), OBJ meshes and their .mtl, and templates`);
      continue;
    }
    files[path] = text;
  }
  const scenes = Object.keys(files).filter(p => p.endsWith('.cfg'));
  const named = p => scenes.some(q => q !== p &&
    files[q].includes(p.replace(/^.*\//, '')));
  const scene = scenes.filter(p => !named(p))
    .sort((a, b) => a.split('/').length - b.split('/').length || a.localeCompare(b))[0] ||
    scenes[0];
  if (scene === undefined) {
    if (Object.keys(files).length > 0 || problems.length === 0)
      problems.push('no scene file (.cfg) among the files opened');
    showProblems(problems);
    return;
  }
  $('example').value = '';
  open(files, scene, list.length === 1 ? '' : `${Object.keys(files).length} files`);
  showProblems(problems);
}

function showProblems(problems) {
  if (problems.length === 0)
    return;
  const li = problems.map(p => {
    const e = document.createElement('li');
    e.className = 'err';
    e.textContent = p;
    return e;
  });
  $('messages').prepend(...li);
}

$('open').addEventListener('click', () => $('files').click());
$('open-folder').addEventListener('click', () => $('folder').click());
for (const id of ['files', 'folder']) {
  $(id).addEventListener('change', () => {
    const list = [...$(id).files].map(file => ({
      path: file.webkitRelativePath || file.name, file }));
    $(id).value = '';
    openFiles(list).catch(fault);
  });
}

// Dropped files and folders, their paths kept (organs/seed.obj).
async function entries(entry, prefix, out) {
  if (entry.isFile) {
    const file = await new Promise((res, rej) => entry.file(res, rej));
    out.push({ path: prefix + entry.name, file });
  } else if (entry.isDirectory) {
    const reader = entry.createReader();
    for (;;) {
      const batch = await new Promise((res, rej) => reader.readEntries(res, rej));
      if (batch.length === 0)
        break;
      for (const e of batch)
        await entries(e, `${prefix}${entry.name}/`, out);
    }
  }
  return out;
}

document.addEventListener('dragover', e => {
  e.preventDefault();
  document.body.classList.add('dropping');
});
document.addEventListener('dragleave', e => {
  if (e.relatedTarget === null)
    document.body.classList.remove('dropping');
});
document.addEventListener('drop', async e => {
  e.preventDefault();
  document.body.classList.remove('dropping');
  state.pending++;	// for idle(): the files are being gathered
  try {
    await dropped(e);
  } finally {
    settled();
  }
});

async function dropped(e) {
  const items = [...e.dataTransfer.items].map(i => i.webkitGetAsEntry && i.webkitGetAsEntry());
  let list = [];
  if (items.length > 0 && items.every(Boolean)) {
    for (const entry of items)
      await entries(entry, '', list);
  } else {
    list = [...e.dataTransfer.files].map(file => ({ path: file.name, file }));
  }
  await openFiles(list);
}

// --- For scripts and tests. ---

window.phyllo = phyllo;
window.phylloPage = {
  get scene() { return state.files[state.scene]; },
  get scenePath() { return state.scene; },
  get files() { return state.files; },
  get changes() { return [...state.changes].map(([p, v]) => `${p}=${v}`); },
  get applied() { return sets(); },
  get instances() { return view.instances; },
  get messages() { return state.messages; },
  get frames() { return { ...state.frames }; },
  get timing() { return state.timing; },
  get fault() { return state.fault && state.fault.message; },
  view,
  // Resolves once every change asked for is shown.
  idle() {
    return state.pending === 0 ? Promise.resolve() :
      new Promise(r => state.idle.push(r));
  },
  load: scene => openExample(scene),
  set: setting,
};

try {
  await loadExamples();
  const want = new URLSearchParams(location.search).get('scene');
  if (!(want && openExample(`scenes/${want}.cfg`)))
    openExample('scenes/sunflower.cfg');
} catch (e) {
  fault(e);
}
