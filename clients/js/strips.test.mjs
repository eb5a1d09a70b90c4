// Tests for strips.mjs against files the Rust encoder wrote. Fixtures come
// from $STRIPS_FIXTURES (the Rust integration test `strips::js_decoder`
// writes one pair per grammar there) or else from ./fixtures (committed,
// kept in sync with the encoder by the same Rust test). Each X.strips has an
// X.json holding what the Rust reference decoder read from it (format
// version 2, or 3 for the grammars over 65 536 triangles, which the Rust
// test writes; the committed fixtures are version 2).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync } from 'node:fs';
import { join, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';
import { decodeStrips, unstripify, StripsError, crc32 } from './strips.mjs';

/** Each triangle rotated so its smallest index comes first, order kept. */
function rotations(list) {
  const out = [];
  for (let t = 0; t + 2 < list.length; t += 3) {
    const [a, b, c] = [list[t], list[t + 1], list[t + 2]];
    if (a <= b && a <= c) out.push([a, b, c]);
    else if (b <= a && b <= c) out.push([b, c, a]);
    else out.push([c, a, b]);
  }
  return out;
}

const dir = process.env.STRIPS_FIXTURES || join(dirname(fileURLToPath(import.meta.url)), 'fixtures');
const names = readdirSync(dir).filter((f) => f.endsWith('.strips') && !f.includes('.zstd.')).sort();

test('fixtures exist', () => {
  assert.ok(names.length > 0, `no .strips files in ${dir}`);
});

for (const name of names) {
  test(`${name}: same vertices, strip and triangles as the Rust decoder`, () => {
    const bytes = new Uint8Array(readFileSync(join(dir, name)));
    const want = JSON.parse(readFileSync(join(dir, name.replace(/\.strips$/, '.json')), 'utf8'));
    const got = decodeStrips(bytes);
    assert.equal(got.vertexCount, want.positions.length);
    assert.equal(got.positionBits, want.position_bits);
    assert.equal(got.normalBits, want.normal_bits);
    for (let k = 0; k < got.vertexCount; k++) {
      for (let a = 0; a < 3; a++) {
        // Both decoders compute in float64 and round once: bit-identical.
        assert.equal(got.positions[k * 3 + a], Math.fround(want.positions[k][a]), `position ${k}.${a}`);
        assert.equal(got.normals[k * 3 + a], Math.fround(want.normals[k][a]), `normal ${k}.${a}`);
      }
      for (let c = 0; c < 4; c++) assert.equal(got.colours[k * 4 + c], want.colours[k][c], `colour ${k}.${c}`);
    }
    assert.equal(got.mode, 'TRIANGLE_STRIP');
    const restart = got.restartIndex;
    assert.deepEqual(
      Array.from(got.indices, (i) => (i === restart ? 0xffffffff : i)),
      want.strip,
    );
    const tris = decodeStrips(bytes, { triangles: true });
    assert.equal(tris.mode, 'TRIANGLES');
    assert.deepEqual(Array.from(tris.indices), want.triangles);
    // The strip holds the stored triangles in order, each up to rotation
    // (same winding).
    assert.deepEqual(rotations(unstripify(want.strip)), rotations(want.triangles));
  });
}

test('every truncation and every flipped byte is rejected with a StripsError', () => {
  // The smallest fixture keeps this quick.
  const smallest = names
    .map((n) => new Uint8Array(readFileSync(join(dir, n))))
    .reduce((a, b) => (a.length <= b.length ? a : b));
  for (let n = 0; n < smallest.length; n++) {
    assert.throws(() => decodeStrips(smallest.subarray(0, n)), StripsError, `truncated to ${n}`);
  }
  for (let i = 0; i < smallest.length; i++) {
    const b = smallest.slice();
    b[i] ^= 0x5a;
    assert.throws(() => decodeStrips(b), StripsError, `flipped byte ${i}`);
  }
  assert.throws(() => decodeStrips(smallest.subarray(0, smallest.length - 1)), /truncated/);
  const b = smallest.slice();
  b[60] ^= 1;
  assert.throws(() => decodeStrips(b), /corrupted: CRC32/);
});

test('zstd-wrapped payloads are refused with a clear message', () => {
  const zs = readdirSync(dir).filter((f) => f.endsWith('.zstd.strips'));
  for (const f of zs) {
    assert.throws(() => decodeStrips(readFileSync(join(dir, f))), /zstd-wrapped/);
  }
});

// Version 3 files (chunks) come only from $STRIPS_FIXTURES (the Rust test
// checks that this test ran); damaged chunk lists with a valid CRC must be
// refused before anything is decoded.
const chunked = names.map((n) => new Uint8Array(readFileSync(join(dir, n)))).filter((b) => b[4] === 3);
if (chunked.length > 0) {
  test('version 3 chunk lists that disagree with their streams are rejected', () => {
    const bytes = chunked.reduce((a, b) => (a.length <= b.length ? a : b));
    const dv = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    const at = 52 + 4 * dv.getUint32(40, true);
    assert.ok(dv.getUint32(at, true) >= 2, 'a version 3 file has chunks');
    const edits = [[at, 3], [at, 0xffffffff], [at + 4, 0xffffffff], [at + 4, 0], [at + 8, 0xffffffff], [at + 8, 1], [at + 12, 0xffffffff], [at + 12, 5]];
    for (const [off, val] of edits) {
      const b = bytes.slice();
      const v = new DataView(b.buffer);
      v.setUint32(off, val, true);
      v.setUint32(b.length - 4, crc32(b.subarray(0, b.length - 4)), true);
      assert.throws(() => decodeStrips(b), StripsError, `offset ${off} = ${val}`);
    }
  });
}
