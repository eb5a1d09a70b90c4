#!/usr/bin/env node
// Drives the playground (/playground) of a running rulemesh server in
// headless Chromium, as a developer would: open it and see the default
// library model, find every library grammar in the menu under its language,
// load a library grammar, change a parameter and see the triangle count
// change, ask for the PNG preview, type a source with an error and see its
// line marked, all the while the URL following the state; then open links
// (an L-system with a seed, an MDG grammar with a parameter, bad values,
// a link pasted into the open tab) and see each restored and rendered as
// GET /v1/models/NAME.EXT renders it; and switch grammars while a slow
// answer about the first is still coming. Every request the page makes must go
// to the server itself (no CDN).
//
// Usage: node scripts/playground-check/check.mjs http://127.0.0.1:PORT
//
// Prints one JSON line with what it saw ({"default", "grammars",
// "languages", "triangles_before", "triangles_after", "sizes",
// "preview_width", "marked_line", "diagnostic", "hashes", "links",
// "foreign_requests", "page_errors"}) and exits 0, or prints
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
  // The language of every render the page asks for, in order.
  const renderLanguages = [];
  page.on('request', (r) => {
    if (r.method() === 'POST' && new URL(r.url()).pathname === '/v1/render') renderLanguages.push(JSON.parse(r.postData() || '{}').language ?? null);
  });
  const apiErrors = [];
  page.on('response', async (r) => {
    if (r.status() < 400) return;
    // A format the grammar's language cannot make (svg needs a 2D drawing)
    // is refused by name: the size table shows that answer (checked below
    // against the server's), and it is no API error.
    if (r.status() === 400 && /capability `/.test((await r.json().catch(() => null))?.error?.message ?? '')) return;
    if (new URL(r.url()).pathname.startsWith('/v1/')) apiErrors.push(`${r.status()} ${r.request().method()} ${r.url()} ${(r.request().postData() || '').slice(0, 160)}`);
    else pageErrors.push(`${r.status()} for the page's own ${r.url()}`);
  });
  const idleAfter = async (renders) => {
    await page.waitForFunction((n) => document.body.dataset.state === 'idle' && Number(document.body.dataset.renders) > n, renders, { timeout: 30000 });
    return page.evaluate(() => ({ renders: Number(document.body.dataset.renders), outcome: document.body.dataset.outcome }));
  };

  const hash = () => page.evaluate(() => decodeURIComponent(location.hash));
  /** What the page shows: its fields read back from the DOM, and the headers of its last render. */
  const shown = () => page.evaluate(() => {
    const $ = (id) => document.getElementById(id);
    const params = {};
    for (const i of $('params').elements) params[i.name] = i.type === 'checkbox' ? String(i.checked) : i.value;
    const headers = Object.fromEntries($('headers').textContent.split('\n').slice(1).map((l) => [l.slice(0, l.indexOf(':')), l.slice(l.indexOf(':') + 2)]));
    return {
      grammar: $('grammar').value, language: $('language').value, seed: $('seed').value, format: $('format').value, params,
      note: $('note').hidden ? null : $('note').textContent, hash: decodeURIComponent(location.hash),
      outcome: document.body.dataset.outcome, triangles: Number($('triangles').textContent),
      etag: headers.etag, header_triangles: headers['x-rulemesh-triangles'],
    };
  });
  /** The ETag and triangle count GET /v1/models/PATH answers this browser. */
  const direct = (path) => page.evaluate(async (p) => {
    const r = await fetch(p);
    return { path: p, status: r.status, etag: r.headers.get('etag'), triangles: r.headers.get('x-rulemesh-triangles') };
  }, path);

  // Opened with no state in its URL: the default library model, named in the URL.
  await page.goto(`${base}/playground`, { waitUntil: 'load' });
  let state = await idleAfter(0);
  const opened = await shown();
  expect(state.outcome === 'model' && opened.triangles > 0, `the page opened on ${opened.grammar}: ${state.outcome}, ${opened.triangles} triangles`);
  expect(opened.grammar === 'gem' && opened.hash === '#grammar=gem&seed=1&format=glb', `opened on ${opened.grammar}, URL ${opened.hash}`);
  expect(opened.note === null, `a note with no link: ${opened.note}`);

  // Every library grammar, of every language, under its language.
  const menu = Object.fromEntries(await page.$$eval('#grammar optgroup option', (os) => os.map((o) => [o.value, o.parentElement.dataset.language])));
  const listed = await page.evaluate(async () => (await (await fetch('/v1/grammars')).json()).grammars.map((g) => [g.name, g.language]));
  const unlisted = listed.filter(([n, l]) => menu[n] !== l);
  expect(unlisted.length === 0 && Object.keys(menu).length === listed.length, `grammars not in the menu under their language: ${JSON.stringify(unlisted)}`);
  expect(menu.hogeweg === 'lsystem' && menu['icon-coin'] === 'mdg' && menu.gem === 'mdg', `menu: ${JSON.stringify(menu)}`);
  const grammars = Object.keys(menu);
  const languages = [...new Set(Object.values(menu))];

  // A library grammar: its source, its form, its model.
  await page.selectOption('#grammar', 'icon-coin');
  state = await idleAfter(state.renders);
  expect(state.outcome === 'model', `icon-coin: ${state.outcome}`);
  expect((await page.inputValue('#source')).includes('startshape Coin'), 'the source of icon-coin was not loaded');
  const before = Number(await page.textContent('#triangles'));
  expect(before > 0, `icon-coin drew ${before} triangles`);
  expect((await page.textContent('#headers')).includes('x-rulemesh-triangles'), 'the response headers are not shown');
  // The size table lists every format the server's registry names, each
  // with its size, or the server's refusal where the format does not take
  // this language's models.
  const formats = await page.evaluate(async () => (await import('/playground/registry.js')).FORMATS);
  expect(formats.includes('glb') && formats.includes('png'), `registry formats: ${JSON.stringify(formats)}`);
  await page.waitForFunction((n) => document.querySelectorAll('#sizes tr').length === n && !Array.from(document.querySelectorAll('#sizes td:nth-child(2)')).some((c) => c.textContent === ''), formats.length, { timeout: 60000 });
  const sizes = Object.fromEntries(await page.$$eval('#sizes tr', (rs) => rs.map((r) => [r.dataset.format, r.cells[1].textContent])));
  const source = await page.inputValue('#source');
  for (const format of formats) {
    const direct = await page.evaluate(async ([source, format]) => {
      const r = await fetch('/v1/render', { method: 'POST', headers: { 'content-type': 'application/json' }, body: JSON.stringify({ source, format }) });
      return r.ok;
    }, [source, format]);
    // The page sends its form's parameters too (recorded in the model's
    // provenance), so only the answer's kind is compared, not the byte count.
    expect(/^[1-9][0-9]* bytes$/.test(sizes[format]) === direct, `size of ${format}: the table says ${sizes[format]}, the server answers ${direct ? 200 : 'an error'}`);
  }
  expect(['glb', 'gltf', 'stl', '3mf', 'strips', 'png'].every((f) => / bytes$/.test(sizes[f])), `sizes: ${JSON.stringify(sizes)}`);

  // A parameter from the schema-driven form changes the model.
  expect((await page.inputValue('#param-points')) === '5', 'the form does not show the default of `points`');
  await page.fill('#param-points', '8');
  await page.dispatchEvent('#param-points', 'change');
  state = await idleAfter(state.renders);
  expect(state.outcome === 'model', `points=8: ${state.outcome}`);
  const after = Number(await page.textContent('#triangles'));
  expect(after > before, `points 5 → 8 gave ${before} → ${after} triangles`);
  const hashes = { parameter: await hash() };
  expect(hashes.parameter === '#grammar=icon-coin&seed=1&format=glb&p.points=8', `URL after points=8: ${hashes.parameter}`);
  await page.fill('#seed', '42');
  await page.dispatchEvent('#seed', 'change');
  state = await idleAfter(state.renders);
  hashes.seed = await hash();
  expect(hashes.seed === '#grammar=icon-coin&seed=42&format=glb&p.points=8', `URL after seed 42: ${hashes.seed}`);

  // The PNG preview, drawn by the server.
  await page.selectOption('#format', 'png');
  state = await idleAfter(state.renders);
  expect(state.outcome === 'preview', `png: ${state.outcome}`);
  await page.waitForFunction(() => document.querySelector('#preview').naturalWidth > 0, null, { timeout: 10000 });
  const previewWidth = await page.$eval('#preview', (i) => i.naturalWidth);
  expect(previewWidth === 256, `the preview is ${previewWidth} px wide`);
  hashes.format = await hash();
  expect(hashes.format === '#grammar=icon-coin&seed=42&format=png&p.points=8', `URL after png: ${hashes.format}`);

  // A parse error is listed with its line and column and marked in the gutter.
  await page.fill('#source', 'startshape A\nrule A {\n  BOXX {}\n}\n');
  state = await idleAfter(state.renders);
  expect(state.outcome === 'parse-error', `bad source: ${state.outcome}`);
  const marked = await page.$$eval('#gutter div.error', (ds) => ds.map((d) => Number(d.dataset.line)));
  const diagnostic = await page.textContent('#diagnostics li.error');
  expect(marked.length === 1 && marked[0] === 3, `marked lines: ${marked}`);
  expect(/^3:3: error: .*BOXX/.test(diagnostic), `diagnostic: ${diagnostic}`);
  hashes.edited = await hash();
  expect(hashes.edited === '#grammar=icon-coin&edited=1&seed=42&format=png&p.points=8', `URL after editing: ${hashes.edited}`);

  // Links, each opened in a fresh page: every field restored, and the model
  // the page renders is the one GET /v1/models/NAME.EXT answers (same ETag,
  // same triangle count).
  const openLink = async (link) => {
    await page.goto('about:blank');
    const from = renderLanguages.length;
    await page.goto(`${base}/playground/#${link}`, { waitUntil: 'load' });
    const s = await idleAfter(0);
    return { link, ...(await shown()), outcome: s.outcome, render_languages: [...new Set(renderLanguages.slice(from))] };
  };
  const links = {};
  // An L-system whose every seed grows another plant, with a seed.
  let seen = await openLink('grammar=stochastic-plant&seed=7&format=glb');
  let want = await direct('/v1/models/stochastic-plant.glb?seed=7');
  expect(seen.grammar === 'stochastic-plant' && seen.language === 'lsystem' && seen.seed === '7' && seen.format === 'glb', `L-system link restored as ${JSON.stringify(seen)}`);
  expect(seen.render_languages.length === 1 && seen.render_languages[0] === 'lsystem', `renders of the L-system sent languages ${seen.render_languages}`);
  expect(seen.outcome === 'model' && seen.triangles > 0 && seen.note === null, `L-system link: ${JSON.stringify(seen)}`);
  expect(want.status === 200 && seen.etag === want.etag && seen.header_triangles === want.triangles, `L-system link rendered ${seen.etag}/${seen.header_triangles}, GET ${want.path} ${want.etag}/${want.triangles}`);
  links.lsystem = { ...seen, direct: want };
  // An MDG grammar's @param, a seed and a format other than glb.
  seen = await openLink('grammar=icosahedron-transformations&seed=5&format=stl&p.phase=1.5');
  want = await direct('/v1/models/icosahedron-transformations.stl?seed=5&p.phase=1.5');
  expect(seen.grammar === 'icosahedron-transformations' && seen.language === 'mdg' && seen.seed === '5' && seen.format === 'stl' && seen.params.phase === '1.5', `parameter link restored as ${JSON.stringify(seen)}`);
  expect(seen.outcome === 'model' && seen.triangles > 0 && seen.note === null, `parameter link: ${JSON.stringify(seen)}`);
  expect(want.status === 200 && seen.etag === want.etag && seen.header_triangles === want.triangles, `parameter link rendered ${seen.etag}/${seen.header_triangles}, GET ${want.path} ${want.etag}/${want.triangles}`);
  expect(seen.hash === `#${seen.link}`, `the URL of the parameter link became ${seen.hash}`);
  links.parameter = { ...seen, direct: want };
  // Bad values: each ignored with a note, and the model still renders.
  seen = await openLink('grammar=gem&seed=banana&format=obj&p.nope=2');
  expect(seen.outcome === 'model' && seen.triangles > 0, `bad link: ${seen.outcome}, ${seen.triangles} triangles`);
  expect(seen.note !== null && ['seed "banana"', 'format "obj"', 'p.nope'].every((w) => seen.note.includes(w)), `bad link's note: ${seen.note}`);
  expect(seen.grammar === 'gem' && seen.seed === '1' && seen.format === 'glb' && seen.hash === '#grammar=gem&seed=1&format=glb', `bad link restored as ${JSON.stringify(seen)}`);
  links.bad = seen;
  // A link pasted into the open tab (a hashchange, no reload).
  const renders = Number(await page.evaluate(() => document.body.dataset.renders));
  await page.evaluate(() => { location.hash = 'grammar=hogeweg&seed=3'; });
  state = await idleAfter(renders);
  seen = await shown();
  expect(seen.grammar === 'hogeweg' && seen.language === 'lsystem' && seen.seed === '3' && seen.format === 'glb' && seen.note === null && seen.outcome === 'model', `pasted link: ${JSON.stringify(seen)}`);
  expect(seen.hash === '#grammar=hogeweg&seed=3&format=glb', `the URL of the pasted link became ${seen.hash}`);
  links.pasted = seen;

  // A slow answer about the grammar just left: icon-coin's schema arrives
  // after hogeweg's, and must not rebuild the form (icon-coin's `points`
  // would then be sent with hogeweg's source and refused as unknown).
  await page.route('**/v1/schema', async (route) => {
    if ((route.request().postData() || '').includes('startshape Coin')) await new Promise((ok) => setTimeout(ok, 1500));
    await route.continue();
  });
  const beforeRace = Number(await page.evaluate(() => document.body.dataset.renders));
  await page.selectOption('#grammar', 'icon-coin');
  await page.waitForFunction(() => document.getElementById('source').value.includes('startshape Coin'), null, { timeout: 30000 });
  await page.selectOption('#grammar', 'hogeweg');
  state = await idleAfter(beforeRace);
  await page.waitForTimeout(2000); // the delayed answer arrives and is dropped
  seen = await shown();
  await page.unroute('**/v1/schema');
  expect(seen.grammar === 'hogeweg' && seen.outcome === 'model' && !('points' in seen.params) && seen.hash === '#grammar=hogeweg&seed=3&format=glb', `after a late answer about icon-coin: ${JSON.stringify(seen)}`);

  // Every API answer the page got was a success, but for the one source that does not parse.
  expect(apiErrors.length === 0, `API errors: ${apiErrors}`);
  expect(foreign.length === 0, `requests to other hosts: ${foreign}`);
  expect(pageErrors.length === 0, `page errors: ${pageErrors}`);
  console.log(JSON.stringify({ default: opened, grammars: grammars.length, languages, hashes, links, triangles_before: before, triangles_after: after, sizes, preview_width: previewWidth, marked_line: marked[0], diagnostic, foreign_requests: foreign.length, page_errors: pageErrors.length }));
} catch (e) {
  console.error(`playground-check: ${e instanceof CheckFailed ? e.message : e.stack || e}`);
  status = 1;
} finally {
  if (session) await session.close();
}
process.exit(status);
