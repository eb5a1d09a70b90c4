// Decode-time benchmark of clients/js/strips.mjs (run by scripts/bench-sizes):
// node bench/decode_strips.mjs FILE... prints `FILE triangles ns_per_decode`.
import { readFileSync } from 'node:fs';
import { decodeStrips } from '../clients/js/strips.mjs';

for (const path of process.argv.slice(2)) {
  const bytes = new Uint8Array(readFileSync(path));
  const triangles = decodeStrips(bytes, { triangles: true }).indices.length / 3;
  for (let i = 0; i < 3; i++) decodeStrips(bytes); // warm up the JIT
  const start = process.hrtime.bigint();
  let runs = 0;
  while (process.hrtime.bigint() - start < 200_000_000n || runs < 5) {
    decodeStrips(bytes);
    runs++;
  }
  console.log(`${path} ${triangles} ${(process.hrtime.bigint() - start) / BigInt(runs)}`);
}
