// validate.mjs - the Khronos glTF-Validator (npm gltf-validator) on
// each .glb: no error, no warning, and nothing else to say but that it
// cannot check EXT_mesh_gpu_instancing (an information) and so does not
// see who uses the organs' accessors.  Prints "ok - " / "not ok - "
// lines for tests/run.sh.  Usage, from the repository:
//   node tests/gltf/validate.mjs FILE.glb ...
import fs from 'node:fs';
import path from 'node:path';
import { createRequire } from 'node:module';

const require = createRequire(path.resolve('src/viewer/package.json'));
const validator = require('gltf-validator');
let failed = 0;

for (const file of process.argv.slice(2)) {
  const bytes = new Uint8Array(fs.readFileSync(file));
  let what = `glTF-Validator ${validator.version()}: ${file}`, why = '';
  try {
    const report = await validator.validateBytes(bytes, { maxIssues: 0 });
    const json = JSON.parse(Buffer.from(bytes.subarray(20, 20 +
      new DataView(bytes.buffer).getUint32(12, true))).toString('utf8'));
    // The accessors the extension names: the validator cannot know them.
    const instancing = new Set();
    for (const node of json.nodes || [])
      for (const a of Object.values(node.extensions?.EXT_mesh_gpu_instancing?.attributes || {}))
        instancing.add(`/accessors/${a}`);
    const { numErrors, numWarnings, messages } = report.issues;
    const other = messages.filter(m => !(m.code === 'UNSUPPORTED_EXTENSION' &&
      m.pointer === '/extensionsUsed/0') && !(m.code === 'UNUSED_OBJECT' &&
      instancing.has(m.pointer)));
    what += ` (${report.info.totalVertexCount} vertices, ${json.nodes.length} nodes)`;
    if (numErrors || numWarnings || other.length)
      why = `${numErrors} errors, ${numWarnings} warnings: ` +
        other.slice(0, 5).map(m => `${m.code} ${m.pointer} ${m.message}`).join('; ');
  } catch (e) {
    why = e.message || String(e);
  }
  console.log(why ? `not ok - ${what}: ${why}` : `ok - ${what}: no errors, no warnings`);
  if (why) failed++;
}
process.exit(failed ? 1 : 0);
