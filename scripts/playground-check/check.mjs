#!/usr/bin/env node
// Drives the playground (/playground) of a running rulemesh server in
// headless Chromium, as a developer would: load a library grammar, change a
// parameter and see the triangle count change, ask for the PNG preview,
// type a source with an error and see its line marked. Every request the
// page makes must go to the server itself (no CDN).
//
// Usage: node scripts/playground-check/check.mjs http://127.0.0.1:PORT
//
// Prints one JSON line with what it saw ({"grammars", "triangles_before",
// "triangles_after", "sizes", "preview_width", "marked_line",
// "diagnostic", "foreign_requests", "page_errors"}) and exits 0, or prints
// `playground-check: <what failed>` on stderr and exits 1; 2 when the
// browser or playwright-core is missing (tests/it/service/playground.rs
// runs it; scripts/test installs both).
import { createRequire } from 'node:module';
import { existsSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { openPage } from '../lib/chromium.mjs';

const here = dirname(fileURLToPath(import.meta.url));
const modules = resolve(process.env.THREE_CHECK_MODULES || join(here, '../../.tools/node_modules'));
const chromium = process.env.CHROMIUM || '/usr/bin/chromium';
const base = process.argv[2];

function missing(msg) {
  console.error(`playground-check: ${msg}`);
  process.exit(2);
}
if (!base) missing('usage: check.mjs BASE_URL');
if (!existsSync(chromium)) missing(`no Chromium at ${chromium} (apt-get install chromium)`);
let playwright;
try {
  playwright = createRequire(join(modules, '__playground_check__.js'))('playwright-core');
} catch (e) {
  missing(`playwright-core not found in ${modules}: ${e.message}`);
}

class CheckFailed extends Error {}
function expect(ok, what) {
  if (!ok) throw new CheckFailed(what);
}

let session;
let status = 0;
try {
  session = await openPage(playwright, chromium, 'playground-check');
  const { page } = session;
  const foreign = [];
  const pageErrors = [];
  page.on('request', (r) => { if (!r.url().startsWith(base) && !r.url().startsWith('blob:') && !r.url().startsWith('data:')) foreign.push(r.url()); });
  page.on('pageerror', (e) => pageErrors.push(String(e)));
  page.on('console', (m) => {
    // Without a GPU, three.js reports that it cannot make a WebGL context,
    // and Chromium logs every API answer of 4xx; the page handles both (the
    // page's own files are checked by status below).
    if (m.type() === 'error' && !/webgl|failed to load resource/i.test(m.text())) pageErrors.push(m.text());
  });
  const apiErrors = [];
  page.on('response', (r) => {
    if (r.status() < 400) return;
    if (new URL(r.url()).pathname.startsWith('/v1/')) apiErrors.push(`${r.status()} ${r.request().method()} ${r.url()}`);
    else pageErrors.push(`${r.status()} for the page's own ${r.url()}`);
  });
  const idleAfter = async (renders) => {
    await page.waitForFunction((n) => document.body.dataset.state === 'idle' && Number(document.body.dataset.renders) > n, renders, { timeout: 30000 });
    return page.evaluate(() => ({ renders: Number(document.body.dataset.renders), outcome: document.body.dataset.outcome }));
  };

  await page.goto(`${base}/playground`, { waitUntil: 'load' });
  await page.waitForFunction(() => document.body.dataset.state === 'idle', null, { timeout: 30000 });
  const grammars = await page.$$eval('#grammar option', (os) => os.map((o) => o.value).filter((v) => v));
  expect(grammars.includes('icon-coin') && grammars.includes('gem'), `the grammar list lacks icon-coin or gem: ${grammars}`);

  // A library grammar: its source, its form, its model.
  await page.selectOption('#grammar', 'icon-coin');
  let state = await idleAfter(0);
  expect(state.outcome === 'model', `icon-coin: ${state.outcome}`);
  expect((await page.inputValue('#source')).includes('startshape Coin'), 'the source of icon-coin was not loaded');
  const before = Number(await page.textContent('#triangles'));
  expect(before > 0, `icon-coin drew ${before} triangles`);
  expect((await page.textContent('#headers')).includes('x-rulemesh-triangles'), 'the response headers are not shown');
  await page.waitForFunction(() => document.querySelectorAll('#sizes tr').length === 6 && !Array.from(document.querySelectorAll('#sizes td:nth-child(2)')).some((c) => c.textContent === ''), null, { timeout: 30000 });
  const sizes = Object.fromEntries(await page.$$eval('#sizes tr', (rs) => rs.map((r) => [r.dataset.format, r.cells[1].textContent])));
  expect(Object.values(sizes).every((s) => / bytes$/.test(s)), `sizes: ${JSON.stringify(sizes)}`);

  // A parameter from the schema-driven form changes the model.
  expect((await page.inputValue('#param-points')) === '5', 'the form does not show the default of `points`');
  await page.fill('#param-points', '8');
  await page.dispatchEvent('#param-points', 'change');
  state = await idleAfter(state.renders);
  expect(state.outcome === 'model', `points=8: ${state.outcome}`);
  const after = Number(await page.textContent('#triangles'));
  expect(after > before, `points 5 → 8 gave ${before} → ${after} triangles`);

  // The PNG preview, drawn by the server.
  await page.selectOption('#format', 'png');
  state = await idleAfter(state.renders);
  expect(state.outcome === 'preview', `png: ${state.outcome}`);
  await page.waitForFunction(() => document.querySelector('#preview').naturalWidth > 0, null, { timeout: 10000 });
  const previewWidth = await page.$eval('#preview', (i) => i.naturalWidth);
  expect(previewWidth === 256, `the preview is ${previewWidth} px wide`);

  // A parse error is listed with its line and column and marked in the gutter.
  await page.fill('#source', 'startshape A\nrule A {\n  BOXX {}\n}\n');
  state = await idleAfter(state.renders);
  expect(state.outcome === 'parse-error', `bad source: ${state.outcome}`);
  const marked = await page.$$eval('#gutter div.error', (ds) => ds.map((d) => Number(d.dataset.line)));
  const diagnostic = await page.textContent('#diagnostics li.error');
  expect(marked.length === 1 && marked[0] === 3, `marked lines: ${marked}`);
  expect(/^3:3: error: .*BOXX/.test(diagnostic), `diagnostic: ${diagnostic}`);

  // Every API answer the page got was a success, but for the one source that does not parse.
  expect(apiErrors.length === 0, `API errors: ${apiErrors}`);
  expect(foreign.length === 0, `requests to other hosts: ${foreign}`);
  expect(pageErrors.length === 0, `page errors: ${pageErrors}`);
  console.log(JSON.stringify({ grammars: grammars.length, triangles_before: before, triangles_after: after, sizes, preview_width: previewWidth, marked_line: marked[0], diagnostic, foreign_requests: foreign.length, page_errors: pageErrors.length }));
} catch (e) {
  console.error(`playground-check: ${e instanceof CheckFailed ? e.message : e.stack || e}`);
  status = 1;
} finally {
  if (session) await session.close();
}
process.exit(status);
