// phyllo.mjs - phyllo-export as a JavaScript module: the same C program,
// compiled to WebAssembly (phyllo.wasm, with emscripten's glue in
// phyllo-core.mjs), run on a command line and files held in memory.
//
//   import { run } from './phyllo.mjs';
//   const r = await run(['--csv', 'sun.cfg'], { 'sun.cfg': text });
//   // r.status: the exit status (0, 1 scene, 2 usage, 3 system)
//   // r.stdout: Uint8Array; r.stderr: string (the program's messages)
//   // r.files: { name: Uint8Array }, every file the run wrote (-o)
//
// The WebAssembly code is compiled once; every run gets an instance of
// its own, on memory that is all zeros, so no run sees what another
// left (static variables, the heap, -o's list of temporary files).
// Works in browsers (and Workers) and in Node.js 18 or newer.

import createCore from './phyllo-core.mjs';

// What a run's memory may grow to; the program's own limits (10,000,000
// organs, 1.1 GB at most) stay below it, and an allocation past it is
// the program's "out of memory" (exit 3).  phyllo.wasm is linked with
// the same bounds (the Makefile's WEB_LDFLAGS).
export const MEMORY_LIMIT = 2 * 1024 * 1024 * 1024;
const PAGE = 65536, INITIAL = 16 * 1024 * 1024;

// What a run leaves of its memory for the next, when no bigger than
// this: touching fresh memory costs the system a page fault every 4 KiB
// (a quarter of a 1,000,000-organ run), zeroing touched memory a
// fortieth of that.
export const MEMORY_KEPT = 256 * 1024 * 1024;
let spare = null;

// Memory for a run, all zeros, growing to limit at most: the one an
// ended run left, or new.
function takeMemory(limit) {
  const m = spare;
  if (limit === MEMORY_LIMIT && m !== null) {
    spare = null;
    new Uint8Array(m.buffer).fill(0);
    return m;
  }
  return new WebAssembly.Memory({ initial: INITIAL / PAGE,
    maximum: Math.max(INITIAL, Math.min(limit, MEMORY_LIMIT)) / PAGE });
}

function keepMemory(m, limit) {
  if (limit === MEMORY_LIMIT && m.buffer.byteLength <= MEMORY_KEPT)
    spare = m;
}

// The folder the files are put in and the program runs in, so that
// names given relative to it read in messages as they were given.
const HOME = '/home/phyllo';

const inNode = typeof process === 'object' && process.versions != null &&
  process.versions.node != null;

let compiled = null;

// The compiled WebAssembly module, once for all runs.
function wasmModule() {
  if (compiled === null) {
    compiled = (async () => {
      const url = new URL('./phyllo.wasm', import.meta.url);
      let bytes;
      if (inNode && url.protocol === 'file:') {
        const { readFile } = await import('node:fs/promises');
        bytes = await readFile(url);
      } else {
        const res = await fetch(url);
        if (!res.ok)
          throw new Error(`phyllo.mjs: ${url}: ${res.status} ${res.statusText}`);
        bytes = await res.arrayBuffer();
      }
      return WebAssembly.compile(bytes);
    })();
    compiled.catch(() => { compiled = null; });
  }
  return compiled;
}

const encoder = new TextEncoder();
const toBytes = data => typeof data === 'string' ? encoder.encode(data) :
  data instanceof Uint8Array ? data : new Uint8Array(data);

function concat(chunks) {
  let n = 0;
  for (const c of chunks)
    n += c.length;
  const all = new Uint8Array(n);
  n = 0;
  for (const c of chunks) {
    all.set(c, n);
    n += c.length;
  }
  return all;
}

// A terminal's status line, as progress.c writes it on stderr: "\r" and
// the line, rubbed out at the end by "\r", blanks and "\r".  Taken out
// of the messages, which are then what they are off a terminal.
const STATUS = /\r[^\r\n]*(?=\r|$)/g;

// The standard streams: stdin from bytes, stdout and stderr into
// chunks, devices of the instance's file system (a call a write, not a
// call a byte).  stderr is a terminal only where the caller listens
// for progress, so that only then the program writes its status line,
// whose latest state goes to progress().
function standardStreams(FS, input, out, err, progress) {
  let pos = 0, tail = '';
  const decoder = new TextDecoder();
  const copy = (buffer, offset, length) =>
    new Uint8Array(buffer.buffer, buffer.byteOffset + offset, length).slice();
  const devices = [
    ['stdin', {
      read(stream, buffer, offset, length) {
        const n = Math.min(length, input.length - pos);
        buffer.set(input.subarray(pos, pos + n), offset);
        pos += n;
        return n;
      },
    }],
    ['stdout', {
      write(stream, buffer, offset, length) {
        out.push(copy(buffer, offset, length));
        return length;
      },
    }],
    ['stderr', {
      open(stream) {
        if (progress)
          stream.tty = {};	// what isatty() asks
      },
      write(stream, buffer, offset, length) {
        const bytes = copy(buffer, offset, length);
        err.push(bytes);
        if (progress) {
          tail += decoder.decode(bytes, { stream: true });
          const cr = tail.lastIndexOf('\r');
          if (cr >= 0) {
            tail = tail.slice(cr);
            const line = tail.slice(1).trim();
            if (line !== '' && !line.includes('\n'))
              progress(line);
          }
        }
        return length;
      },
    }],
  ];
  devices.forEach(([name, ops], i) => {
    const dev = FS.makedev(64 + i, 0);
    FS.registerDevice(dev, ops);
    FS.mkdev(`/dev/${name}`, dev);
  });
  FS.open('/dev/stdin', 0);	// fd 0, O_RDONLY
  FS.open('/dev/stdout', 1);	// fd 1, O_WRONLY
  FS.open('/dev/stderr', 1);	// fd 2
  FS.init.initialized = true;	// so that exit flushes C's stdio
}

// A file -o writes grows fourfold (emscripten's MEMFS grows one past
// 1 MiB by an eighth: a 40 MB .glb was copied some 30 times).  What a
// new buffer holds beyond the file is never touched, so the system
// gives it no memory.
function growFourfold(MEMFS) {
  MEMFS.expandFileStorage = (node, want) => {
    const had = node.contents ? node.contents.length : 0;
    if (had >= want)
      return;
    const old = node.contents;
    node.contents = new Uint8Array(Math.max(want, 4 * had, 256));
    if (node.usedBytes > 0)
      node.contents.set(old.subarray(0, node.usedBytes));
  };
}

// A file's bytes, copied out of the room it had to grow in, if any.
function contents(FS, path) {
  const node = FS.lookupPath(path).node;
  const bytes = node.contents || new Uint8Array(0);
  return node.usedBytes === bytes.length && bytes.byteOffset === 0 &&
    bytes.buffer.byteLength === bytes.length ? bytes :
    bytes.slice(0, node.usedBytes);
}

function mkdirs(FS, path) {
  const parts = path.split('/');
  let dir = path.startsWith('/') ? '' : '.';
  for (const p of parts.slice(0, -1)) {
    if (p === '' || p === '.')
      continue;
    dir += '/' + p;
    if (!FS.analyzePath(dir).exists)
      FS.mkdir(dir);
  }
}

// Every regular file under dir, by its path.
function walk(FS, dir, found) {
  for (const name of FS.readdir(dir)) {
    if (name === '.' || name === '..')
      continue;
    const path = dir === '/' ? '/' + name : `${dir}/${name}`;
    if (path === '/dev' || path === '/proc')
      continue;
    const st = FS.lstat(path);
    if (FS.isDir(st.mode))
      walk(FS, path, found);
    else if (FS.isFile(st.mode))
      found.push(path);
  }
  return found;
}

/*
 * Run phyllo-export with args (its command line, without the program's
 * name) on files ({ name: string or bytes }: the scene, its parts,
 * meshes and templates; names relative to the folder the program runs
 * in, or absolute).  options.stdin: what "-" reads; options.progress:
 * called with the status line a terminal would show on a long run;
 * options.memory: bytes the run's memory may grow to, below
 * MEMORY_LIMIT (an allocation past them is the program's "out of
 * memory").
 * Resolves to { status, stdout, stderr, files }, files every file the
 * run wrote, by the name it was given (-o).  Rejects only where the
 * program itself failed (a crash: a bug to report) or a name of files
 * cannot be a file.
 */
export async function run(args, files = {}, options = {}) {
  const module = await wasmModule();
  const out = [], err = [];
  const input = toBytes(options.stdin ?? new Uint8Array(0));
  const limit = Math.min(options.memory ?? MEMORY_LIMIT, MEMORY_LIMIT);
  const memory = takeMemory(limit);
  const core = await createCore({
    wasmMemory: memory,
    noFSInit: true,
    instantiateWasm(imports, done) {
      WebAssembly.instantiate(module, imports).then(i => done(i, module));
      return {};
    },
    // exit() unwinds to callMain() as an exception, never to the host's
    // own exit.
    quit(status, toThrow) { throw toThrow; },
    print() {},
    printErr() {},
  });
  const FS = core.FS;
  standardStreams(FS, input, out, err, options.progress);
  growFourfold(FS.filesystems.MEMFS);
  FS.mkdir(HOME);
  FS.chdir(HOME);
  // A file the run writes is one not given, or given and replaced (-o
  // renames a new file over it).
  const given = new Map();
  for (const [name, data] of Object.entries(files)) {
    try {
      mkdirs(FS, name);
      FS.writeFile(name, toBytes(data));
    } catch (e) {
      throw new Error(`phyllo.mjs: files: ${JSON.stringify(name)} cannot be a file beside the others`);
    }
    const { path, node } = FS.lookupPath(name);
    given.set(path, node);
  }
  const status = core.callMain(args.map(String));
  // The program's umask is emscripten's 0777: what it writes has mode 0.
  FS.ignorePermissions = true;
  const written = {};
  for (const path of walk(FS, '/', [])) {
    if (given.get(path) === FS.lookupPath(path).node)
      continue;
    const name = path.startsWith(HOME + '/') ? path.slice(HOME.length + 1) :
      path;
    written[name] = contents(FS, path);
  }
  keepMemory(memory, limit);
  return {
    status,
    stdout: concat(out),
    stderr: new TextDecoder().decode(concat(err)).replace(STATUS, '')
      .replace(/\r/g, ''),
    files: written,
  };
}
