// The scene decoder's WebAssembly kernel (kernel/place.c, kernel/tessellate.c;
// built into kernel-wasm.mjs by scripts/build-js-kernel), compiled and
// instantiated once, when this module loads. Dependency-free ES module.
//
// Why WebAssembly: the decoder's work is float arithmetic on every vertex,
// and a first decode runs in V8's interpreter, where each floating-point
// operation allocates a boxed number (about 2 µs a vertex, several
// milliseconds for a small icon). Compiled, the same loops cost
// nanoseconds, and WebAssembly's arithmetic is IEEE 754 without fused
// multiply-add, so the bits are the server's. The module is 11 KB:
// synchronous compilation is allowed for it in Node and in current browsers
// (Chromium allows up to 8 MB on the main thread; versions before that
// change allowed only 4 KB there, so use a worker in those).
import { KERNEL_WASM } from './kernel-wasm.mjs';

function base64Bytes(text) {
  // Native decoders where there is one (a loop over 15 000 characters costs
  // about half a millisecond in a cold interpreter).
  if (typeof Uint8Array.fromBase64 === 'function') return Uint8Array.fromBase64(text);
  if (typeof Buffer === 'function') return new Uint8Array(Buffer.from(text, 'base64'));
  const raw = atob(text);
  const bytes = new Uint8Array(raw.length);
  for (let i = 0; i < raw.length; i++) bytes[i] = raw.charCodeAt(i);
  return bytes;
}

/**
 * The kernel's exports: `memory`, `__heap_base` (the first free byte; the
 * callers lay out everything above it and grow the memory as they need),
 * the place_* functions and `indices` (scene.mjs), and `tessellate`,
 * `tessellation_vertices`, `tessellation_triangles` (primitives.mjs).
 * cos, sin and atan2 come from Math, the functions the tessellation was
 * ported with.
 */
export const kernel = new WebAssembly.Instance(new WebAssembly.Module(base64Bytes(KERNEL_WASM)), {
  math: { cos: Math.cos, sin: Math.sin, atan2: Math.atan2 },
}).exports;

/** The first 16-byte-aligned free byte of the kernel's memory. */
export const HEAP_BASE = (kernel.__heap_base.value + 15) & ~15;

// V8 compiles a WebAssembly function lazily, on its first call, and builds
// the JavaScript-to-WebAssembly call wrapper for each signature then too;
// that is about half a millisecond a process. Calling every export once
// here, with nothing to do, moves that to load time, so a first decode does
// not pay it.
kernel.tessellation_vertices(0, 3);
kernel.tessellation_triangles(0, 3);
kernel.tessellate(-1 >>> 0, 3, HEAP_BASE, HEAP_BASE, HEAP_BASE);
kernel.indices(HEAP_BASE, 0, 0, 0, HEAP_BASE);
kernel.shape_prototype(HEAP_BASE, HEAP_BASE, 0, HEAP_BASE, HEAP_BASE, HEAP_BASE);
kernel.place_batch(HEAP_BASE, 0, HEAP_BASE);

/** Grows the kernel's memory to hold at least `end` bytes; returns its buffer. */
export function reserve(end) {
  const pages = Math.ceil(end / 65536) - kernel.memory.buffer.byteLength / 65536;
  if (pages > 0) kernel.memory.grow(pages);
  return kernel.memory.buffer;
}
