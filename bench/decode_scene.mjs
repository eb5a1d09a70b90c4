// Decode-time benchmark of clients/js/scene.mjs (run by scripts/bench):
// node bench/decode_scene.mjs FILE... prints `FILE triangles cold_ns warm_ns`:
// the first decode in a fresh process (primitives tessellated, JIT cold) and
// the mean of repeated decodes after warming up (prototypes cached).
import { readFileSync } from 'node:fs';
import { decodeScene } from '../clients/js/scene.mjs';

for (const path of process.argv.slice(2)) {
  const bytes = new Uint8Array(readFileSync(path));
  const t0 = process.hrtime.bigint();
  const first = decodeScene(bytes);
  const cold = process.hrtime.bigint() - t0;
  const triangles = first.meshes.reduce((s, m) => s + m.indices.length / 3, 0);
  for (let i = 0; i < 20; i++) decodeScene(bytes); // warm up the JIT
  const start = process.hrtime.bigint();
  let runs = 0;
  while (process.hrtime.bigint() - start < 200_000_000n || runs < 5) {
    decodeScene(bytes);
    runs++;
  }
  console.log(`${path} ${triangles} ${cold} ${(process.hrtime.bigint() - start) / BigInt(runs)}`);
}
