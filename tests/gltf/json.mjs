// json.mjs - the JSON chunk of a .glb as JSON.parse (strict) reads it,
// written back one property a line: what the escaping tests grep.
// Usage: node tests/gltf/json.mjs FILE.glb
import fs from 'node:fs';

const b = fs.readFileSync(process.argv[2]);
const text = new TextDecoder('utf-8', { fatal: true }).decode(b.subarray(20, 20 + b.readUInt32LE(12)));
console.log(JSON.stringify(JSON.parse(text), null, 1));
