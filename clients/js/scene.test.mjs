// Tests for scene.mjs against files the Rust encoder wrote. Fixtures come
// from $SCENE_FIXTURES (the Rust integration test `scene::decoded_scene_…`
// writes one pair per golden case there) or else from ./fixtures
// (committed). Each X.rmscene has an X.scene.json holding what the Rust reference
// decoder made of it: per mesh its name, counts and the CRC-32 of its
// positions, normals, colours and indices. Equal CRCs over every array:
// the same float32 bits, triangle for triangle.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync } from 'node:fs';
import { join, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';
import { decodeScene, SceneError } from './scene.mjs';
import { crc32 } from './strips.mjs';

const dir = process.env.SCENE_FIXTURES || join(dirname(fileURLToPath(import.meta.url)), 'fixtures');
const names = readdirSync(dir).filter((f) => f.endsWith('.rmscene')).sort();
const bytesOf = (a) => new Uint8Array(a.buffer, a.byteOffset, a.byteLength);

test('fixtures exist', () => {
  assert.ok(names.length > 0, `no .rmscene files in ${dir}`);
});

test('every fixture decodes to the Rust decoder\'s meshes', () => {
  for (const name of names) {
    const bytes = new Uint8Array(readFileSync(join(dir, name)));
    const want = JSON.parse(readFileSync(join(dir, name.replace(/\.rmscene$/, '.scene.json')), 'utf8'));
    const got = decodeScene(bytes);
    assert.equal(got.detail, want.detail, name);
    assert.equal(got.truncated, want.truncated, name);
    assert.equal(got.meshes.length, want.meshes.length, `${name}: mesh count`);
    got.meshes.forEach((m, k) => {
      const w = want.meshes[k];
      const at = `${name} mesh ${k} (${w.name})`;
      assert.equal(m.name, w.name, at);
      assert.equal(m.positions.length / 3, w.vertices, `${at}: vertices`);
      assert.equal(m.indices.length / 3, w.triangles, `${at}: triangles`);
      assert.equal(crc32(bytesOf(m.positions)), w.positions, `${at}: positions`);
      assert.equal(crc32(bytesOf(m.normals)), w.normals, `${at}: normals`);
      assert.equal(crc32(m.colours), w.colours, `${at}: colours`);
      assert.equal(crc32(bytesOf(m.indices)), w.indices, `${at}: indices`);
    });
  }
});

test('damaged files are SceneErrors', () => {
  const name = names.find((n) => !n.startsWith('v1-')) || names[0];
  const good = new Uint8Array(readFileSync(join(dir, name)));
  assert.throws(() => decodeScene(good.subarray(0, good.length - 1)), SceneError);
  assert.throws(() => decodeScene(new Uint8Array([0x52, 0x4d, 0x53, 0x43])), SceneError);
  const bad = good.slice();
  bad[0] = 0x58;
  assert.throws(() => decodeScene(bad), SceneError);
  const extra = new Uint8Array(good.length + 1);
  extra.set(good);
  assert.throws(() => decodeScene(extra), SceneError);
  // Every single-byte truncation point: an error, never anything else.
  for (let n = 0; n < Math.min(good.length, 400); n++) {
    assert.throws(() => decodeScene(good.subarray(0, n)), SceneError, `cut at ${n}`);
  }
});

// A checksummed file (X.crc.rmscene: `checksum: true`, docs/scene-format.md,
// "Checksum") refuses every truncation and every byte flipped three ways:
// past the magic, version and flags (8 bytes) always as a checksum error
// (`code` 'checksum'). The flag bit cleared leaves the CRC as trailing
// bytes; set on an unchecked file, its last four bytes are no CRC.
test('checksummed files refuse every damaged byte', () => {
  const crcNames = names.filter((n) => n.endsWith('.crc.rmscene'));
  assert.ok(crcNames.length > 0, `no .crc.rmscene files in ${dir}`);
  for (const name of crcNames) {
    const good = new Uint8Array(readFileSync(join(dir, name)));
    assert.equal(good[6] & 8, 8, `${name}: the CHECKSUM flag`);
    assert.equal(crc32(good.subarray(0, good.length - 4)), new DataView(good.buffer, good.byteOffset).getUint32(good.length - 4, true), `${name}: the CRC`);
    for (let n = 0; n < good.length; n++) {
      assert.throws(() => decodeScene(good.subarray(0, n)), (e) => e instanceof SceneError && (n < 12 || e.code === 'checksum'), `${name} cut at ${n}`);
    }
    for (const x of [0x01, 0x80, 0xff]) {
      for (let i = 0; i < good.length; i++) {
        const bad = good.slice();
        bad[i] ^= x;
        assert.throws(() => decodeScene(bad), (e) => e instanceof SceneError && (i < 8 || e.code === 'checksum'), `${name} xor ${x} at ${i}`);
      }
    }
    const cleared = good.slice();
    cleared[6] ^= 8;
    assert.throws(() => decodeScene(cleared), /trailing bytes/, `${name}: the flag cleared`);
  }
  const plain = names.find((n) => !n.startsWith('v1-') && !n.endsWith('.crc.rmscene'));
  const set = new Uint8Array(readFileSync(join(dir, plain)));
  set[6] ^= 8;
  assert.throws(() => decodeScene(set), (e) => e instanceof SceneError && e.code === 'checksum', `${plain}: the flag set`);
});
