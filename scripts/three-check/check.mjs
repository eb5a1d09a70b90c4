#!/usr/bin/env node
// Loads glTF files in three.js (GLTFLoader, with MeshoptDecoder for
// EXT_meshopt_compression) and USDZ packages (USDLoader, which
// USDZLoader now aliases) in headless Chromium, one browser session for all
// files, and reports per file whether it loaded and how many triangles it has.
//
// Usage: node scripts/three-check/check.mjs FILE.glb|FILE.usdz...
//
// Prints one JSON line per file: {"file", "ok", "triangles" (instanced
// meshes count once per instance), "meshes", "instances", "coloured" (instances
// with an instanceColor),
// "animations", "error"?}, then a closing line `three-check: N passed, M failed`
// on stderr; exits 1 if any file failed, 2 if the browser or three.js is
// missing. Needs (scripts/test installs them): Debian's `chromium`
// (/usr/bin/chromium, or $CHROMIUM) and the npm packages `three` and
// `playwright-core` in .tools/ (or $THREE_CHECK_MODULES, a node_modules folder).
//
// The page is served from 127.0.0.1 on an ephemeral port by a tiny static
// server in this script: `/` is page.html, `/three/` is the three package,
// `/files/N` is the N-th file. Reusable for other checks (e.g. animated
// models: the report counts animation clips).
import { createServer } from 'node:http';
import { createRequire } from 'node:module';
import { readFileSync, existsSync } from 'node:fs';
import { dirname, join, resolve, extname } from 'node:path';
import { fileURLToPath } from 'node:url';
import { openPage } from '../lib/chromium.mjs';

const here = dirname(fileURLToPath(import.meta.url));
const repoRoot = resolve(here, '../..');
const modules = resolve(process.env.THREE_CHECK_MODULES || join(repoRoot, '.tools/node_modules'));
const chromium = process.env.CHROMIUM || '/usr/bin/chromium';
const files = process.argv.slice(2);

function fail(msg) {
  console.error(`three-check: ${msg}`);
  process.exit(2);
}
if (!existsSync(join(modules, 'three/package.json'))) fail(`three not found in ${modules} (run scripts/test, which installs it)`);
if (!existsSync(chromium)) fail(`no Chromium at ${chromium} (apt-get install chromium)`);
let playwright;
try {
  playwright = createRequire(join(modules, '__three_check__.js'))('playwright-core');
} catch (e) {
  fail(`playwright-core not found in ${modules}: ${e.message}`);
}

const types = { '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript', '.glb': 'model/gltf-binary', '.gltf': 'model/gltf+json', '.wasm': 'application/wasm' };
const threeRoot = join(modules, 'three');
const server = createServer((req, res) => {
  const url = new URL(req.url, 'http://127.0.0.1');
  let path = null;
  if (url.pathname === '/') path = join(here, 'page.html');
  else if (url.pathname.startsWith('/three/')) {
    const p = resolve(threeRoot, '.' + decodeURIComponent(url.pathname.slice('/three'.length)));
    if (p.startsWith(threeRoot + '/')) path = p;
  } else if (url.pathname.startsWith('/files/')) {
    const n = Number(url.pathname.slice('/files/'.length));
    if (Number.isInteger(n) && n >= 0 && n < files.length) path = resolve(files[n]);
  }
  if (!path || !existsSync(path)) {
    res.writeHead(404).end();
    return;
  }
  res.writeHead(200, { 'Content-Type': types[extname(path)] || 'application/octet-stream' });
  res.end(readFileSync(path));
});
await new Promise((ok) => server.listen(0, '127.0.0.1', ok));
const base = `http://127.0.0.1:${server.address().port}`;

let session;
let failed = 0;
try {
  session = await openPage(playwright, chromium, 'three-check');
  const { page } = session;
  const consoleErrors = [];
  page.on('console', (m) => { if (m.type() === 'error') consoleErrors.push(m.text()); });
  page.on('pageerror', (e) => consoleErrors.push(String(e)));
  await page.goto(base + '/');
  await page.waitForFunction(() => window.threeCheckReady === true, null, { timeout: 30000 });
  for (let i = 0; i < files.length; i++) {
    consoleErrors.length = 0;
    const kind = extname(files[i]).slice(1).toLowerCase();
    const r = await page.evaluate(([url, kind]) => window.threeCheck(url, kind), [`${base}/files/${i}`, kind]);
    r.file = files[i];
    if (r.ok && consoleErrors.length) {
      r.ok = false;
      r.error = 'console: ' + consoleErrors.join(' | ');
    }
    if (!r.ok) failed++;
    console.log(JSON.stringify(r));
  }
} catch (e) {
  console.error(`three-check: browser session failed: ${e.stack || e}`);
  failed = Math.max(failed, 1);
  process.exitCode = 2;
} finally {
  if (session) await session.close().catch(() => {});
  server.close();
}
console.error(`three-check: ${files.length - failed} passed, ${failed} failed`);
if (!process.exitCode) process.exitCode = failed ? 1 : 0;
