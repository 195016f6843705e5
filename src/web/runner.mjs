// runner.mjs - the page's side of worker.mjs: runs of phyllo-export in a
// Worker, one at a time, each a Promise; cancel() ends the Worker (and
// with it a run that takes too long) and the next run starts another.

export class Cancelled extends Error {
  constructor() {
    super('cancelled');
  }
}

export class Runner {
  constructor(url) {
    this.url = url;
    this.worker = null;
    this.next = 1;
    this.pending = new Map();	// id -> { resolve, reject, progress }
    this.started = 0;		// when the run going on started
    this.waiting = [];		// idle()'s
  }

  get busy() {
    return this.pending.size > 0;
  }

  start() {
    if (this.worker !== null)
      return;
    this.worker = new Worker(this.url, { type: 'module' });
    this.worker.onmessage = ({ data }) => this.message(data);
    this.worker.onerror = e => {
      e.preventDefault();
      this.failAll(new Error(`the page's worker failed: ${e.message || 'it did not start'}`));
    };
  }

  message({ id, result, error, progress }) {
    const p = this.pending.get(id);
    if (p === undefined)
      return;
    if (progress !== undefined) {
      if (p.progress)
        p.progress(progress);
      return;
    }
    this.pending.delete(id);
    this.started = performance.now();
    if (error !== undefined)
      p.reject(new Error(error));
    else
      p.resolve(result);
    this.wake();
  }

  // When no run is left.
  idle() {
    return this.busy ? new Promise(r => this.waiting.push(r)) :
      Promise.resolve();
  }

  wake() {
    if (this.busy)
      return;
    const all = this.waiting;
    this.waiting = [];
    all.forEach(r => r());
  }

  failAll(e) {
    const all = [...this.pending.values()];
    this.pending.clear();
    if (this.worker !== null)
      this.worker.terminate();
    this.worker = null;
    for (const p of all)
      p.reject(e);
    this.wake();
  }

  // Run args on files; progress(line) hears a long run's status line.
  run(args, files, progress = null) {
    this.start();
    const id = this.next++;
    if (this.pending.size === 0)
      this.started = performance.now();
    return new Promise((resolve, reject) => {
      this.pending.set(id, { resolve, reject, progress });
      this.worker.postMessage({ id, args, files, progress: progress !== null });
    });
  }

  // How long the run going on has taken, in ms (0: none).
  elapsed() {
    return this.busy ? performance.now() - this.started : 0;
  }

  cancel() {
    this.failAll(new Cancelled());
  }
}
