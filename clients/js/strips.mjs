// Decoder for rulemesh's `strips` format (application/vnd.rulemesh.strips),
// specified in docs/strips-format.md. Dependency-free ES module: decodes to
// typed arrays ready for WebGL (TRIANGLE_STRIP with primitive restart, or a
// TRIANGLES list on request). Reads format versions 2 (one coded mesh) and
// 3 (independently coded chunks, for big models). meshoptimizer's vertex
// codec (versions 0 and 1) and index buffer codec (versions 0 and 1) are
// ported by hand from meshoptimizer's src/vertexcodec.cpp and
// src/indexcodec.cpp (scalar paths); the strip is rebuilt from the stored
// triangles by `restrip`, the same algorithm as rulemesh's
// geom::strip::restrip.
//
// Every length and offset is checked; damaged input throws a StripsError,
// never reads out of bounds, and never allocates more than the payload's
// size justifies.

/** Thrown for any payload that is not a valid strips file. */
export class StripsError extends Error {
  constructor(message) {
    super(message);
    this.name = 'StripsError';
  }
}

const HEADER_LEN = 52;
const TRAILER_LEN = 4;
const FLAG_ZSTD = 1;
const FLAG_PALETTE = 2;
const RESTART = 0xffffffff;
const MAX_VERTICES_PER_STREAM_BYTE = 64;
const INDEX_STREAM_OVERHEAD = 17;

let crcTable = null;
/** CRC-32 (IEEE 802.3, the zlib/PNG one) of `bytes`. */
export function crc32(bytes) {
  if (!crcTable) {
    crcTable = new Uint32Array(256);
    for (let n = 0; n < 256; n++) {
      let c = n;
      for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
      crcTable[n] = c >>> 0;
    }
  }
  let c = 0xffffffff;
  for (let i = 0; i < bytes.length; i++) c = crcTable[(c ^ bytes[i]) & 0xff] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}

// ---- meshoptimizer vertex codec (decodeVertexBuffer) ----

const kVertexBlockSizeBytes = 8192;
const kVertexBlockMaxSize = 256;
const kByteGroupSize = 16;
const kByteGroupDecodeLimit = 24;
const kBitsV0 = [0, 2, 4, 8];
const kBitsV1 = [0, 1, 2, 4, 8];

function vertexBlockSize(vertexSize) {
  const r = Math.floor(kVertexBlockSizeBytes / vertexSize) & ~(kByteGroupSize - 1);
  return r < kVertexBlockMaxSize ? r : kVertexBlockMaxSize;
}

// Decodes one group of 16 bytes with `bits` bits each into out[o..o+16];
// returns the new read position. The caller guarantees 24 readable bytes.
function decodeBytesGroup(data, p, out, o, bits) {
  if (bits === 0) {
    out.fill(0, o, o + 16);
    return p;
  }
  if (bits === 8) {
    out.set(data.subarray(p, p + 16), o);
    return p + 16;
  }
  const groups = (16 * bits) / 8; // packed bytes
  let pv = p + groups; // sentinel values follow the packed bytes
  const sentinel = (1 << bits) - 1;
  if (bits === 1) {
    // Two bytes of 8 one-bit values each, least significant bit first.
    for (let b = 0; b < 2; b++) {
      const byte = data[p + b];
      for (let k = 0; k < 8; k++) {
        const enc = (byte >> k) & 1;
        if (enc === sentinel) out[o++] = data[pv++];
        else out[o++] = enc;
      }
    }
    return pv;
  }
  const per = 8 / bits;
  for (let b = 0; b < groups; b++) {
    const byte = data[p + b];
    for (let k = 0; k < per; k++) {
      const enc = (byte >> (8 - bits * (k + 1))) & sentinel;
      if (enc === sentinel) out[o++] = data[pv++];
      else out[o++] = enc;
    }
  }
  return pv;
}

function decodeBytes(data, p, end, out, o, size, bits) {
  const headerSize = ((size / kByteGroupSize + 3) >> 2);
  if (end - p < headerSize) return -1;
  const header = p;
  p += headerSize;
  for (let i = 0; i < size; i += kByteGroupSize) {
    if (end - p < kByteGroupDecodeLimit) return -1;
    const g = i / kByteGroupSize;
    const bitsk = (data[header + (g >> 2)] >> ((g & 3) * 2)) & 3;
    p = decodeBytesGroup(data, p, out, o + i, bits[bitsk]);
  }
  return p;
}

function decodeVertexBlock(data, p, end, dest, destOff, count, vertexSize, last, channels, version) {
  const aligned = (count + kByteGroupSize - 1) & ~(kByteGroupSize - 1);
  const buffer = new Uint8Array(count * 4 + kByteGroupSize);
  const controlSize = version === 0 ? 0 : vertexSize / 4;
  if (end - p < controlSize) return -1;
  const control = p;
  p += controlSize;
  for (let k = 0; k < vertexSize; k += 4) {
    const ctrlByte = version === 0 ? 0 : data[control + k / 4];
    for (let j = 0; j < 4; j++) {
      const ctrl = (ctrlByte >> (j * 2)) & 3;
      if (ctrl === 3) {
        if (end - p < count) return -1;
        buffer.set(data.subarray(p, p + count), j * count);
        p += count;
      } else if (ctrl === 2) {
        buffer.fill(0, j * count, j * count + count);
      } else {
        p = decodeBytes(data, p, end, buffer, j * count, aligned, version === 0 ? kBitsV0 : kBitsV1.slice(ctrl));
        if (p < 0) return -1;
      }
    }
    const channel = version === 0 ? 0 : channels[k / 4];
    const mode = channel & 3;
    if (mode === 0) {
      for (let j = 0; j < 4; j++) {
        let prev = last[k + j];
        for (let i = 0; i < count; i++) {
          const v = buffer[j * count + i];
          prev = (((v & 1) ? ~(v >> 1) : (v >> 1)) + prev) & 0xff;
          dest[destOff + i * vertexSize + k + j] = prev;
        }
      }
    } else if (mode === 1) {
      for (let j = 0; j < 4; j += 2) {
        let prev = last[k + j] | (last[k + j + 1] << 8);
        for (let i = 0; i < count; i++) {
          const v = buffer[j * count + i] | (buffer[(j + 1) * count + i] << 8);
          prev = (((v & 1) ? ~(v >>> 1) : (v >>> 1)) + prev) & 0xffff;
          const q = destOff + i * vertexSize + k + j;
          dest[q] = prev & 0xff;
          dest[q + 1] = prev >> 8;
        }
      }
    } else if (mode === 2) {
      const rot = (32 - (channel >> 4)) & 31;
      let prev = (last[k] | (last[k + 1] << 8) | (last[k + 2] << 16) | (last[k + 3] << 24)) >>> 0;
      for (let i = 0; i < count; i++) {
        let v = (buffer[i] | (buffer[count + i] << 8) | (buffer[2 * count + i] << 16) | (buffer[3 * count + i] << 24)) >>> 0;
        v = ((((v << rot) | (v >>> ((32 - rot) & 31))) >>> 0) ^ prev) >>> 0;
        const q = destOff + i * vertexSize + k;
        dest[q] = v & 0xff;
        dest[q + 1] = (v >>> 8) & 0xff;
        dest[q + 2] = (v >>> 16) & 0xff;
        dest[q + 3] = v >>> 24;
        prev = v;
      }
    } else {
      return -1;
    }
  }
  const lastOff = destOff + (count - 1) * vertexSize;
  for (let b = 0; b < vertexSize; b++) last[b] = dest[lastOff + b];
  return p;
}

/**
 * meshopt_decodeVertexBuffer: decodes `count` vertices of `vertexSize` bytes
 * (a multiple of 4, at most 256). Throws StripsError on malformed data.
 */
export function decodeVertexBuffer(data, count, vertexSize) {
  if (data.length < 1) throw new StripsError('vertex stream empty');
  const header = data[0];
  if ((header & 0xf0) !== 0xa0) throw new StripsError('vertex stream: bad header');
  const version = header & 0x0f;
  if (version > 1) throw new StripsError(`vertex stream: unsupported codec version ${version}`);
  const tailSize = vertexSize + (version === 0 ? 0 : vertexSize / 4);
  const tailMin = version === 0 ? 32 : 24;
  const tailPad = tailSize < tailMin ? tailMin : tailSize;
  const end = data.length;
  let p = 1;
  if (end - p < tailPad) throw new StripsError('vertex stream truncated');
  const tail = end - tailSize;
  const last = data.slice(tail, tail + vertexSize);
  const channels = version === 0 ? null : data.subarray(tail + vertexSize, tail + vertexSize + vertexSize / 4);
  const dest = new Uint8Array(count * vertexSize);
  const blockSize = vertexBlockSize(vertexSize);
  for (let off = 0; off < count; off += blockSize) {
    const n = Math.min(blockSize, count - off);
    p = decodeVertexBlock(data, p, end, dest, off * vertexSize, n, vertexSize, last, channels, version);
    if (p < 0) throw new StripsError('vertex stream does not decode (truncated or corrupt)');
  }
  if (end - p !== tailPad) throw new StripsError('vertex stream has the wrong length');
  return dest;
}

// ---- meshoptimizer index buffer codec (decodeIndexBuffer) ----

const kCodeAuxTableSize = 16;

// varint of up to 5 bytes, then zigzag delta from `last`; the caller
// guarantees 16 readable bytes (the codeaux table makes that safe).
function decodeVByte(data, p) {
  const lead = data[p++];
  if (lead < 128) return [lead, p];
  let v = lead & 127;
  let shift = 7;
  for (let k = 0; k < 4; k++) {
    const g = data[p++];
    v = (v + (g & 127) * 2 ** shift) >>> 0;
    shift += 7;
    if (g < 128) break;
  }
  return [v, p];
}

/**
 * meshopt_decodeIndexBuffer: decodes `count` 32-bit indices (a multiple of
 * 3) into a Uint32Array. Throws StripsError on malformed data; like the C
 * decoder it may return out-of-range indices, which the caller checks.
 */
export function decodeIndexBuffer(data, count) {
  if (count % 3 !== 0) throw new StripsError('index count not a multiple of 3');
  if (data.length < 1 + count / 3 + kCodeAuxTableSize) throw new StripsError('index stream too short for its triangle count');
  if ((data[0] & 0xf0) !== 0xe0) throw new StripsError('index stream: bad header');
  const version = data[0] & 0x0f;
  if (version > 1) throw new StripsError(`index stream: unsupported codec version ${version}`);
  const out = new Uint32Array(count);
  const edge0 = new Uint32Array(16).fill(0xffffffff);
  const edge1 = new Uint32Array(16).fill(0xffffffff);
  const vfifo = new Uint32Array(16).fill(0xffffffff);
  let eo = 0;
  let vo = 0;
  let next = 0;
  let last = 0;
  const fecmax = version >= 1 ? 13 : 15;
  let code = 1;
  const codeEnd = 1 + count / 3;
  let p = codeEnd;
  const safeEnd = data.length - kCodeAuxTableSize;
  const aux = safeEnd;
  let o = 0;
  const pushV = (v, cond) => {
    vfifo[vo] = v;
    vo = (vo + cond) & 15;
  };
  const pushE = (a, b) => {
    edge0[eo] = a;
    edge1[eo] = b;
    eo = (eo + 1) & 15;
  };
  while (code < codeEnd) {
    const codetri = data[code++];
    if (codetri < 0xf0) {
      const fe = codetri >> 4;
      const a = edge0[(eo - 1 - fe) & 15];
      const b = edge1[(eo - 1 - fe) & 15];
      let c;
      const fec = codetri & 15;
      if (fec < fecmax) {
        const cf = vfifo[(vo - 1 - fec) & 15];
        c = fec === 0 ? next : cf;
        const fec0 = fec === 0 ? 1 : 0;
        next = (next + fec0) >>> 0;
        pushV(c, fec0);
      } else {
        if (p > safeEnd) throw new StripsError('index stream truncated');
        if (fec !== 15) {
          c = (last + (fec * 2 - 27)) >>> 0;
        } else {
          let v;
          [v, p] = decodeVByte(data, p);
          c = (last + ((v >>> 1) ^ -(v & 1))) >>> 0;
        }
        last = c;
        pushV(c, 1);
      }
      pushE(c, b);
      pushE(a, c);
      out[o++] = a;
      out[o++] = b;
      out[o++] = c;
    } else if (codetri < 0xfe) {
      const codeaux = data[aux + (codetri & 15)];
      const feb = codeaux >> 4;
      const fec = codeaux & 15;
      const a = next;
      next = (next + 1) >>> 0;
      const bf = vfifo[(vo - feb) & 15];
      const b = feb === 0 ? next : bf;
      const feb0 = feb === 0 ? 1 : 0;
      next = (next + feb0) >>> 0;
      const cf = vfifo[(vo - fec) & 15];
      const c = fec === 0 ? next : cf;
      const fec0 = fec === 0 ? 1 : 0;
      next = (next + fec0) >>> 0;
      out[o++] = a;
      out[o++] = b;
      out[o++] = c;
      pushV(a, 1);
      pushV(b, feb0);
      pushV(c, fec0);
      pushE(b, a);
      pushE(c, b);
      pushE(a, c);
    } else {
      if (p > safeEnd) throw new StripsError('index stream truncated');
      const codeaux = data[p++];
      const fea = codetri === 0xfe ? 0 : 15;
      const feb = codeaux >> 4;
      const fec = codeaux & 15;
      if (codeaux === 0) next = 0;
      let a = 0;
      if (fea === 0) {
        a = next;
        next = (next + 1) >>> 0;
      }
      let b;
      if (feb === 0) {
        b = next;
        next = (next + 1) >>> 0;
      } else {
        b = vfifo[(vo - feb) & 15];
      }
      let c;
      if (fec === 0) {
        c = next;
        next = (next + 1) >>> 0;
      } else {
        c = vfifo[(vo - fec) & 15];
      }
      let v;
      if (fea === 15) {
        [v, p] = decodeVByte(data, p);
        last = a = (last + ((v >>> 1) ^ -(v & 1))) >>> 0;
      }
      if (feb === 15) {
        [v, p] = decodeVByte(data, p);
        last = b = (last + ((v >>> 1) ^ -(v & 1))) >>> 0;
      }
      if (fec === 15) {
        [v, p] = decodeVByte(data, p);
        last = c = (last + ((v >>> 1) ^ -(v & 1))) >>> 0;
      }
      out[o++] = a;
      out[o++] = b;
      out[o++] = c;
      pushV(a, 1);
      pushV(b, feb === 0 || feb === 15 ? 1 : 0);
      pushV(c, fec === 0 || fec === 15 ? 1 : 0);
      pushE(b, a);
      pushE(c, b);
      pushE(a, c);
    }
  }
  if (p !== safeEnd) throw new StripsError('index stream has the wrong length');
  return out;
}

// ---- the strips container ----

/** Octahedral decode, in float64 like the Rust reference decoder. */
function octDecode(qx, qy, max, out, o) {
  let x = (qx / max) * 2 - 1;
  let y = (qy / max) * 2 - 1;
  const z = 1 - Math.abs(x) - Math.abs(y);
  if (z < 0) {
    const ox = x;
    const oy = y;
    x = (1 - Math.abs(oy)) * (ox >= 0 ? 1 : -1);
    y = (1 - Math.abs(ox)) * (oy >= 0 ? 1 : -1);
  }
  const len = Math.sqrt(x * x + y * y + z * z);
  out[o] = x / len;
  out[o + 1] = y / len;
  out[o + 2] = z / len;
}

/**
 * Triangle list in strip order → strip with RESTART between runs (the spec's
 * rule, identical to rulemesh's geom::strip::restrip). A run starts at a
 * triangle in the first of its rotations (a,b,c), (b,c,a), (c,a,b) that the
 * next triangle can continue; with x, y the run's last two indices and k the
 * number of the next triangle inside the run, a triangle continues the run
 * if it holds the directed edge x→y (k even) or y→x (k odd), and its third
 * corner is appended.
 */
export function restrip(list) {
  const n = Math.floor(list.length / 3);
  // third corner of triangle t if it holds the directed edge p→q, else -1
  const third = (t, p, q) => {
    const a = list[3 * t];
    const b = list[3 * t + 1];
    const c = list[3 * t + 2];
    if (a === p && b === q) return c;
    if (b === p && c === q) return a;
    if (c === p && a === q) return b;
    return -1;
  };
  const out = [];
  let i = 0;
  while (i < n) {
    if (i > 0) out.push(RESTART);
    const a = list[3 * i];
    const b = list[3 * i + 1];
    const c = list[3 * i + 2];
    let start = [a, b, c];
    if (i + 1 < n) {
      for (const r of [[a, b, c], [b, c, a], [c, a, b]]) {
        if (third(i + 1, r[2], r[1]) >= 0) {
          start = r;
          break;
        }
      }
    }
    out.push(start[0], start[1], start[2]);
    i++;
    let k = 1;
    while (i < n) {
      const x = out[out.length - 2];
      const y = out[out.length - 1];
      const z = k % 2 === 0 ? third(i, x, y) : third(i, y, x);
      if (z < 0) break;
      out.push(z);
      i++;
      k++;
    }
  }
  return Uint32Array.from(out);
}

/** Strip indices → triangle list (GL rule for odd triangles; joins skipped). */
export function unstripify(strip) {
  const out = [];
  let start = 0;
  for (let i = 0; i < strip.length; i++) {
    if (strip[i] === RESTART) {
      start = i + 1;
    } else if (i - start >= 2) {
      let a = strip[i - 2];
      let b = strip[i - 1];
      const c = strip[i];
      if ((i - start) & 1) {
        const t = a;
        a = b;
        b = t;
      }
      if (a !== b && a !== c && b !== c) out.push(a, b, c);
    }
  }
  return out;
}

/**
 * Decodes a strips payload (Uint8Array or ArrayBuffer).
 *
 * Returns { positions: Float32Array (xyz), normals: Float32Array (xyz),
 * colours: Uint8Array (RGBA), indices, mode, restartIndex, vertexCount,
 * bboxMin, bboxMax, positionBits, normalBits, palette }.
 * By default `indices` is the strip for gl.TRIANGLE_STRIP with primitive
 * restart (WebGL 2 always restarts at the largest index value): a
 * Uint16Array with restart 0xFFFF when there are fewer than 65535 vertices,
 * else a Uint32Array with restart 0xFFFFFFFF. With { triangles: true } it is
 * a triangle list for gl.TRIANGLES instead.
 */
export function decodeStrips(input, options = {}) {
  const bytes = input instanceof Uint8Array ? input : new Uint8Array(input);
  const min = HEADER_LEN + TRAILER_LEN;
  if (bytes.length < min) throw new StripsError(`strips payload truncated: ${bytes.length} bytes, the header and CRC alone need ${min}`);
  if (bytes[0] !== 0x52 || bytes[1] !== 0x4d || bytes[2] !== 0x53 || bytes[3] !== 0x54) throw new StripsError('not a strips payload (bad magic)');
  const dv = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const bodyLen = dv.getUint32(44, true);
  const expected = bodyLen + min;
  if (expected !== bytes.length) throw new StripsError(`strips payload truncated or padded: the header promises ${expected} bytes, got ${bytes.length}`);
  const end = bytes.length - TRAILER_LEN;
  const stored = dv.getUint32(end, true);
  const computed = crc32(bytes.subarray(0, end));
  if (stored !== computed) throw new StripsError(`strips payload corrupted: CRC32 is ${computed.toString(16).padStart(8, '0')}, the file says ${stored.toString(16).padStart(8, '0')}`);
  const version = bytes[4];
  const flags = bytes[5];
  const pbits = bytes[6];
  const nbits = bytes[7];
  if (version !== 2 && version !== 3) throw new StripsError(`unsupported strips version ${version} (this decoder reads versions 2 and 3)`);
  if (flags & ~(FLAG_ZSTD | FLAG_PALETTE)) throw new StripsError(`invalid strips header: unknown flags ${flags}`);
  if (flags & FLAG_ZSTD) throw new StripsError('this payload is zstd-wrapped; the JavaScript decoder reads only unwrapped payloads (request zstd=false)');
  if (![8, 10, 12, 16].includes(pbits) || ![8, 16].includes(nbits)) throw new StripsError(`invalid strips header: position bits ${pbits}, normal bits ${nbits}`);
  const bboxMin = [dv.getFloat32(8, true), dv.getFloat32(12, true), dv.getFloat32(16, true)];
  const bboxMax = [dv.getFloat32(20, true), dv.getFloat32(24, true), dv.getFloat32(28, true)];
  for (let a = 0; a < 3; a++) {
    if (!Number.isFinite(bboxMin[a]) || !Number.isFinite(bboxMax[a]) || bboxMin[a] > bboxMax[a]) throw new StripsError('invalid strips header: bounding box not finite or min > max');
  }
  const vertexCount = dv.getUint32(32, true);
  const triangleCount = dv.getUint32(36, true);
  const paletteLen = dv.getUint32(40, true);
  const rawLen = dv.getUint32(48, true);
  const hasPalette = (flags & FLAG_PALETTE) !== 0;
  if (hasPalette !== paletteLen > 0 || paletteLen > 256) throw new StripsError(`invalid strips header: palette of ${paletteLen} entries with palette flag ${hasPalette}`);
  const body = bytes.subarray(HEADER_LEN, end);
  if (body.length !== rawLen) throw new StripsError(`invalid strips body: body is ${body.length} bytes, the header says ${rawLen}`);
  if (body.length < paletteLen * 4) throw new StripsError('invalid strips body: palette cut short');
  const palette = hasPalette ? body.slice(0, paletteLen * 4) : null;
  let at = paletteLen * 4;
  const bdv = new DataView(body.buffer, body.byteOffset, body.byteLength);
  const takeU32 = (what) => {
    if (body.length - at < 4) throw new StripsError(`invalid strips body: ${what} missing`);
    const n = bdv.getUint32(at, true);
    at += 4;
    return n;
  };
  const takeStream = (what) => {
    const n = takeU32(`${what} stream length`);
    if (body.length - at < n) throw new StripsError(`invalid strips body: ${what} stream says ${n} bytes, only ${body.length - at} left`);
    const s = body.subarray(at, at + n);
    at += n;
    return s;
  };
  if (vertexCount >= RESTART) throw new StripsError(`invalid strips header: ${vertexCount} vertices: the restart index is no vertex`);
  // Every chunk's counts are checked against its streams before anything is decoded.
  const chunk = (name, cv, ct) => {
    const vstream = takeStream('vertex');
    const istream = takeStream('index');
    if (cv > vstream.length * MAX_VERTICES_PER_STREAM_BYTE + 256) throw new StripsError(`invalid strips header: ${name}${cv} vertices cannot fit in a ${vstream.length}-byte vertex stream`);
    if (ct + INDEX_STREAM_OVERHEAD > istream.length) throw new StripsError(`invalid strips header: ${name}${ct} triangles cannot fit in a ${istream.length}-byte index stream`);
    return { name, vertices: cv, triangles: ct, vstream, istream };
  };
  const chunks = [];
  if (version === 2) {
    chunks.push(chunk('', vertexCount, triangleCount));
  } else {
    const count = takeU32('chunk count');
    if (count * 16 > body.length - at) throw new StripsError(`invalid strips header: ${count} chunks cannot fit in ${body.length - at} bytes`);
    let v = 0;
    let t = 0;
    for (let k = 0; k < count; k++) {
      const cv = takeU32('chunk vertex count');
      const ct = takeU32('chunk triangle count');
      chunks.push(chunk(`chunk ${k}: `, cv, ct));
      v += cv;
      t += ct;
    }
    if (v !== vertexCount || t !== triangleCount) throw new StripsError(`invalid strips header: chunks hold ${v} vertices and ${t} triangles, the header says ${vertexCount} and ${triangleCount}`);
  }
  if (at !== body.length) throw new StripsError(`invalid strips body: ${body.length - at} stray bytes after the index stream`);

  const pmax = 2 ** pbits - 1;
  const nmax = 2 ** nbits - 1;
  const positions = new Float32Array(vertexCount * 3);
  const normals = new Float32Array(vertexCount * 3);
  const colours = new Uint8Array(vertexCount * 4);
  const tris = new Uint32Array(triangleCount * 3);
  let base = 0;
  let tbase = 0;
  for (const c of chunks) {
    const raw = decodeVertexBuffer(c.vstream, c.vertices, 16);
    const ct = decodeIndexBuffer(c.istream, c.triangles * 3);
    for (let i = 0; i < ct.length; i++) {
      if (ct[i] >= c.vertices) throw new StripsError(`invalid strips body: ${c.name}index ${ct[i]} out of range (${c.vertices} vertices)`);
    }
    for (let t = 0; t < ct.length; t += 3) {
      if (ct[t] === ct[t + 1] || ct[t + 1] === ct[t + 2] || ct[t] === ct[t + 2]) throw new StripsError(`invalid strips body: ${c.name}triangle ${t / 3} has a repeated index`);
    }
    for (let i = 0; i < ct.length; i++) tris[tbase + i] = ct[i] + base;
    tbase += ct.length;
    const rv = new DataView(raw.buffer, raw.byteOffset, raw.byteLength);
    for (let j = 0; j < c.vertices; j++) {
      const o = j * 16;
      const k = base + j;
      const q = [0, 1, 2, 3, 4, 5].map((w) => rv.getUint16(o + 2 * w, true));
      if (q[0] > pmax || q[1] > pmax || q[2] > pmax || q[3] !== 0 || q[4] > nmax || q[5] > nmax) throw new StripsError(`invalid strips body: ${c.name}vertex ${j} has a value out of range for its bit count`);
      for (let a = 0; a < 3; a++) positions[k * 3 + a] = bboxMin[a] + (q[a] * (bboxMax[a] - bboxMin[a])) / pmax;
      octDecode(q[4], q[5], nmax, normals, k * 3);
      if (palette) {
        const idx = raw[o + 12];
        if (raw[o + 13] || raw[o + 14] || raw[o + 15]) throw new StripsError(`invalid strips body: ${c.name}vertex ${j}: palette padding not zero`);
        if (idx >= paletteLen) throw new StripsError(`invalid strips body: ${c.name}vertex ${j}: palette index ${idx} out of range`);
        colours.set(palette.subarray(idx * 4, idx * 4 + 4), k * 4);
      } else {
        colours.set(raw.subarray(o + 12, o + 16), k * 4);
      }
    }
    base += c.vertices;
  }

  const small = vertexCount < 0xffff;
  let indices;
  let mode;
  let restartIndex = null;
  if (options.triangles) {
    indices = small ? Uint16Array.from(tris) : tris;
    mode = 'TRIANGLES';
    return { positions, normals, colours, indices, mode, restartIndex, vertexCount, bboxMin, bboxMax, positionBits: pbits, normalBits: nbits, palette };
  }
  const strip = restrip(tris);
  if (small) {
    indices = new Uint16Array(strip.length);
    for (let i = 0; i < strip.length; i++) indices[i] = strip[i] === RESTART ? 0xffff : strip[i];
    mode = 'TRIANGLE_STRIP';
    restartIndex = 0xffff;
  } else {
    indices = strip;
    mode = 'TRIANGLE_STRIP';
    restartIndex = RESTART;
  }
  return { positions, normals, colours, indices, mode, restartIndex, vertexCount, bboxMin, bboxMax, positionBits: pbits, normalBits: nbits, palette };
}
