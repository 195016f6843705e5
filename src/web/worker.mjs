// worker.mjs - the page's runs of phyllo-export, off the page's thread:
// one message a run, { id, args, files, progress }, answered by
// { id, result } (phyllo.mjs's, its bytes transferred, not copied) or
// { id, error }, and meanwhile { id, progress: line } on a long run.
// The page stops a run by ending this worker.
import { run } from './phyllo.mjs';

onmessage = async ({ data }) => {
  const { id, args, files, progress } = data;
  try {
    const result = await run(args, files, progress ?
      { progress: line => postMessage({ id, progress: line }) } : {});
    const buffers = [result.stdout, ...Object.values(result.files)]
      .map(b => b.buffer);
    postMessage({ id, result }, [...new Set(buffers)]);
  } catch (e) {
    postMessage({ id, error: String(e && e.message || e) });
  }
};
