// First-decode benchmark (run by scripts/bench, once per fresh Node process):
// node bench/first_decode.mjs scene|strips FILE prints `import_ns first_ns`:
// the time to load the decoder module (clients/js/scene.mjs with its
// WebAssembly kernel, or clients/js/strips.mjs) and the time of its first
// decode of FILE, the cost an app pays for the first icon it shows.
import { readFileSync } from 'node:fs';

const [which, path] = process.argv.slice(2);
const bytes = new Uint8Array(readFileSync(path));
const t0 = process.hrtime.bigint();
const mod = await import(which === 'scene' ? '../clients/js/scene.mjs' : '../clients/js/strips.mjs');
const t1 = process.hrtime.bigint();
if (which === 'scene') mod.decodeScene(bytes);
else mod.decodeStrips(bytes);
const t2 = process.hrtime.bigint();
console.log(`${t1 - t0} ${t2 - t1}`);
