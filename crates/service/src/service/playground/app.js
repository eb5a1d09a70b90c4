// The rulemesh playground: pick a library grammar or paste source, edit its
// parameters through a form built from the server's parameter schema
// (POST /v1/schema), and see the model in three.js with its diagnostics
// (POST /v1/check) marked at their lines, the response headers and the size
// of every format. Everything it loads comes from this server.
//
// It opens on a library model (DEFAULT_GRAMMAR), and its URL's fragment
// carries its state (grammar, seed, format, parameters: see "the link"
// below and docs/service.md, "Links"), so a link shows the same model.
//
// For tests (scripts/playground-check/), the page reports its state on
// <body>: data-state is "busy" while a render is in flight and "idle"
// after, data-renders counts finished renders, data-outcome says how the
// last one ended ("model", "preview", "parse-error", "error: …").
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { MeshoptDecoder } from 'three/addons/libs/meshopt_decoder.module.js';
// The server's registries: every language it reads, every format it writes.
import { LANGUAGES, FORMATS } from './registry.js';

const $ = (id) => document.getElementById(id);
/** How the grammar menu labels each language's group (others by their name). */
const LANGUAGE_LABELS = { mdg: 'MDG', lsystem: 'L-system', eisenscript: 'EisenScript', stack: 'Stack', ug: 'UG', etol: 'ETOL' };
/**
 * The library grammar the page opens on when its URL names none: `gem`, an
 * icon-sized gem (about 3700 triangles, 33 primitives) in three colours, so
 * the first model shows quickly on any machine and still shows facets,
 * colour and a mirrored, repeated structure. A library without it opens on
 * its first grammar.
 */
const DEFAULT_GRAMMAR = 'gem';
/** The largest seed (2^64 - 1): seeds are 64-bit unsigned everywhere. */
const MAX_SEED = 18446744073709551615n;

let schemaParams = {};
let lastSchema = '';
let seq = 0;
let renders = 0;
let changeTimer = null;
/** The library's grammars by name: { language, description }, in the server's order. */
const library = new Map();
/** The text of the library grammar last loaded into the editor (to tell edited source). */
let librarySource = null;
/** A link's format and parameters, applied once its grammar's schema is read (then null). */
let pending = null;
/** What the note (#note) lists as ignored from the last link opened. */
let linkProblems = [];
const viewer = makeViewer();
const loader = new GLTFLoader();
loader.setMeshoptDecoder(MeshoptDecoder);

function headers(json) {
  const h = {};
  if (json) h['content-type'] = 'application/json';
  const key = $('api-key').value.trim();
  if (key) h['x-api-key'] = key;
  return h;
}

function get(path) {
  return fetch(path, { headers: headers(false) });
}

function post(path, body) {
  return fetch(path, { method: 'POST', headers: headers(true), body: JSON.stringify(body) });
}

function setState(state, outcome) {
  document.body.dataset.state = state;
  if (outcome !== undefined) document.body.dataset.outcome = outcome;
}

function fillSelect(select, values, keep) {
  const current = select.value;
  const fixed = Array.from(select.options).filter((o) => o.value === '');
  select.replaceChildren(...fixed);
  for (const v of values) select.append(new Option(v, v));
  if (keep && values.includes(current)) select.value = current;
}

// ---- the editor: line numbers and marked lines -------------------------

function drawGutter(marks = new Map()) {
  const lines = $('source').value.split('\n').length;
  const gutter = $('gutter');
  gutter.replaceChildren();
  for (let n = 1; n <= lines; n++) {
    const d = document.createElement('div');
    d.textContent = String(n);
    d.dataset.line = String(n);
    if (marks.has(n)) {
      d.className = marks.get(n);
      d.title = 'see the diagnostics below';
    }
    gutter.append(d);
  }
  gutter.scrollTop = $('source').scrollTop;
}

function showDiagnostics(diagnostics) {
  const list = $('diagnostics');
  list.replaceChildren();
  const marks = new Map();
  for (const d of diagnostics) {
    const li = document.createElement('li');
    li.className = d.severity || 'error';
    li.textContent = `${d.line}:${d.column}: ${d.severity || 'error'}: ${d.message}`;
    li.dataset.line = String(d.line);
    li.addEventListener('click', () => selectLine(d.line));
    list.append(li);
    if (d.line > 0 && marks.get(d.line) !== 'error') marks.set(d.line, d.severity || 'error');
  }
  drawGutter(marks);
}

function selectLine(line) {
  const text = $('source').value;
  let start = 0;
  for (let n = 1; n < line; n++) start = text.indexOf('\n', start) + 1;
  const end = text.indexOf('\n', start);
  $('source').focus();
  $('source').setSelectionRange(start, end < 0 ? text.length : end);
}

// ---- the parameter form, from the schema --------------------------------

function paramInput(name, spec) {
  const presets = spec['x-rulemesh-presets'];
  const variants = spec.anyOf || [spec];
  let input;
  if (presets) {
    input = document.createElement('select');
    for (const p of presets) input.append(new Option(p, p));
    input.dataset.kind = 'preset';
  } else if (variants.some((v) => v.type === 'boolean')) {
    input = document.createElement('input');
    input.type = 'checkbox';
    input.checked = spec.default === true;
    input.dataset.kind = 'bool';
  } else if (spec.enum) {
    input = document.createElement('select');
    for (const v of spec.enum) input.append(new Option(String(v), String(v)));
    input.dataset.kind = 'enum';
  } else if (spec.type === 'integer' || spec.type === 'number') {
    input = document.createElement('input');
    input.type = 'number';
    input.step = spec.type === 'integer' ? '1' : 'any';
    if (spec.minimum !== undefined) input.min = String(spec.minimum);
    if (spec.maximum !== undefined) input.max = String(spec.maximum);
    input.dataset.kind = 'number';
  } else {
    input = document.createElement('input');
    input.type = 'text';
    input.dataset.kind = 'text';
  }
  if (input.type !== 'checkbox' && spec.default !== undefined) input.value = String(spec.default);
  input.name = name;
  input.id = `param-${name}`;
  input.addEventListener('change', scheduleRender);
  return input;
}

function buildForm(schema) {
  // The same schema as before (a parameter or the seed changed): keep the form as it is.
  const text = JSON.stringify(schema);
  if (text === lastSchema && $('params').childElementCount > 0) return;
  lastSchema = text;
  const form = $('params');
  const previous = formValues();
  schemaParams = schema?.properties?.params?.properties || {};
  form.replaceChildren();
  for (const [name, spec] of Object.entries(schemaParams)) {
    const label = document.createElement('label');
    label.htmlFor = `param-${name}`;
    label.textContent = name;
    const input = paramInput(name, spec);
    if (name in previous) {
      if (input.type === 'checkbox') input.checked = previous[name];
      else input.value = String(previous[name]);
    }
    form.append(label, input);
  }
  const formats = schema?.properties?.format?.enum;
  if (formats) fillSelect($('format'), formats, true);
  const languages = schema?.properties?.language?.enum;
  if (languages) fillSelect($('language'), languages, true);
}

function formValues() {
  const values = {};
  for (const input of $('params').querySelectorAll('input, select')) {
    switch (input.dataset.kind) {
      case 'bool': values[input.name] = input.checked; break;
      case 'number': if (input.value !== '') values[input.name] = Number(input.value); break;
      default: if (input.value !== '') values[input.name] = input.value;
    }
  }
  return values;
}

// ---- the viewer ---------------------------------------------------------

function makeViewer() {
  const canvas = $('viewer');
  let renderer;
  try {
    renderer = new THREE.WebGLRenderer({ canvas, antialias: true, alpha: true });
  } catch (e) {
    $('no-webgl').hidden = false;
    return { show() {}, hide() {} };
  }
  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(35, 1, 0.01, 1000);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x444444, 2.0));
  const key = new THREE.DirectionalLight(0xffffff, 2.0);
  key.position.set(3, 5, 4);
  scene.add(key);
  const controls = new OrbitControls(camera, canvas);
  let model = null;
  const resize = () => {
    const w = canvas.clientWidth || 1;
    const h = canvas.clientHeight || 1;
    renderer.setSize(w, h, false);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
  };
  renderer.setAnimationLoop(() => {
    resize();
    controls.update();
    renderer.render(scene, camera);
  });
  return {
    show(object) {
      if (model) scene.remove(model);
      model = object;
      scene.add(object);
      const box = new THREE.Box3().setFromObject(object);
      const size = box.getSize(new THREE.Vector3()).length() || 1;
      const centre = box.getCenter(new THREE.Vector3());
      controls.target.copy(centre);
      camera.position.copy(centre).add(new THREE.Vector3(0.6, 0.45, 1).multiplyScalar(size * 1.2));
      camera.near = size / 100;
      camera.far = size * 100;
      camera.updateProjectionMatrix();
      canvas.hidden = false;
    },
    hide() {
      canvas.hidden = true;
    },
  };
}

function countTriangles(root) {
  let triangles = 0;
  root.traverse((o) => {
    if (!o.isMesh) return;
    const g = o.geometry;
    const n = (g.index ? g.index.count : g.attributes.position.count) / 3;
    triangles += o.isInstancedMesh ? n * o.count : n;
  });
  return triangles;
}

function parseGlb(bytes) {
  return new Promise((ok, fail) => loader.parse(bytes, '', ok, fail));
}

// ---- requests -----------------------------------------------------------

function request(format) {
  const body = { source: $('source').value, format, params: formValues() };
  const language = $('language').value;
  if (language) body.language = language;
  const seed = $('seed').value.trim();
  if (seed !== '') body.seed = seed;
  return body;
}

async function errorText(response) {
  try {
    const e = (await response.json()).error;
    return `${e.code}: ${e.message}`;
  } catch {
    return `HTTP ${response.status}`;
  }
}

function showHeaders(response) {
  const lines = [`HTTP ${response.status}`];
  response.headers.forEach((value, name) => lines.push(`${name}: ${value}`));
  $('headers').textContent = lines.join('\n');
}

/**
 * Checks the source (diagnostics) and reads its schema (the form); true when
 * it parses. `mine` is the render asking: once a newer render has started,
 * the answers are dropped, so a slow answer about the previous grammar can
 * never rebuild the form after the new grammar's (its parameters would then
 * be sent with the new source and refused as unknown).
 */
async function analyse(mine) {
  const body = { source: $('source').value };
  if ($('language').value) body.language = $('language').value;
  const check = await (await post('/v1/check', body)).json();
  if (mine !== seq) return false;
  showDiagnostics(check.diagnostics || []);
  if (!check.ok) return false;
  const schema = await post('/v1/schema', body);
  if (!schema.ok) return false;
  const json = await schema.json();
  if (mine !== seq) return false;
  buildForm(json);
  return true;
}

async function render() {
  const mine = ++seq;
  setState('busy');
  const finish = (outcome, status) => {
    if (mine !== seq) return;
    $('status').textContent = status;
    renders += 1;
    document.body.dataset.renders = String(renders);
    setState('idle', outcome);
  };
  try {
    const parsed = await analyse(mine);
    if (mine !== seq) return;
    applyPending(parsed);
    writeLink();
    if (!parsed) {
      finish('parse-error', 'The source does not parse: see the marked lines.');
      return;
    }
    const format = $('format').value || 'glb';
    // The request as it stands now: the glb twin and the size table below
    // describe this model, not whatever the editor holds by the time they
    // are sent (an edit waits out the render debounce before it starts a
    // new render, and a request read from the editor then could carry a
    // half-typed source).
    const sent = request(format);
    const response = await post('/v1/render', sent);
    if (mine !== seq) return;
    showHeaders(response);
    if (!response.ok) {
      const text = await errorText(response);
      finish(`error: ${text}`, text);
      return;
    }
    const bytes = await response.arrayBuffer();
    $('bytes').textContent = String(bytes.byteLength);
    $('cache').textContent = response.headers.get('x-rulemesh-cache') || '–';
    $('primitives').textContent = response.headers.get('x-rulemesh-primitives') || '–';
    const preview = $('preview');
    if (format === 'png') {
      preview.src = URL.createObjectURL(new Blob([bytes], { type: 'image/png' }));
      preview.hidden = false;
      viewer.hide();
      $('triangles').textContent = response.headers.get('x-rulemesh-triangles') || '–';
      finish('preview', `PNG preview, ${bytes.byteLength} bytes.`);
    } else {
      // Other formats are shown through their glb twin (from the cache when repeated).
      const glb = format === 'glb' || format === 'gltf' ? bytes : await (await post('/v1/render', { ...sent, format: 'glb' })).arrayBuffer();
      if (mine !== seq) return;
      const gltf = await parseGlb(glb);
      if (mine !== seq) return;
      preview.hidden = true;
      viewer.show(gltf.scene);
      $('triangles').textContent = String(countTriangles(gltf.scene));
      finish('model', `${format}: ${bytes.byteLength} bytes.`);
    }
    listSizes(mine, sent);
  } catch (e) {
    finish(`error: ${e.message || e}`, String(e.message || e));
  }
}

/** Fills the size-per-format table, one request at a time, for the render `mine` of `sent`. */
async function listSizes(mine, sent) {
  const rows = $('sizes').tBodies[0];
  rows.replaceChildren();
  for (const format of FORMATS) {
    if (mine !== seq) return;
    const row = rows.insertRow();
    row.insertCell().textContent = format;
    const cell = row.insertCell();
    row.dataset.format = format;
    const response = await post('/v1/render', { ...sent, format });
    const bytes = response.ok ? (await response.arrayBuffer()).byteLength : null;
    cell.textContent = bytes === null ? (await errorText(response)) : `${bytes} bytes`;
  }
}

function scheduleRender() {
  writeLink();
  if (!$('auto').checked) return;
  clearTimeout(changeTimer);
  changeTimer = setTimeout(render, 250);
}

/** Loads the library grammar `name` into the editor, with its language; true when loaded. */
async function loadGrammar(name) {
  const response = await get(`/v1/grammars/${encodeURIComponent(name)}`);
  if (!response.ok) {
    $('status').textContent = await errorText(response);
    return false;
  }
  $('grammar').value = name;
  $('source').value = await response.text();
  librarySource = $('source').value;
  // The library's language is sent with every render of its grammar (no detection).
  $('language').value = library.get(name)?.language || '';
  $('params').replaceChildren();
  drawGutter();
  return true;
}

/** The user picked a grammar: load it and render (seed and format stay). */
async function pickGrammar() {
  const name = $('grammar').value;
  if (!name) {
    writeLink();
    return;
  }
  showNote([]);
  pending = null;
  if (await loadGrammar(name)) render();
}

// ---- the link: the page's state in its URL's fragment --------------------
//
// #grammar=NAME&seed=N&format=F&p.NAME=V, the names of GET
// /v1/models/NAME.EXT?seed=N&p.NAME=V. The fragment, not the query: it never
// reaches the server, so the page stays one embedded, cached file whatever
// the link, and the state stays out of access logs and caches. Parameters at
// their default are left out. Source typed or edited in the editor is not
// carried: the link then says `edited=1` (beside the grammar it started
// from), and opening it shows the library grammar with a note. Values a
// link gets wrong are ignored with a note (#note), never an error.

/** Whether the editor holds something other than the picked library grammar as it is. */
function edited() {
  const name = $('grammar').value;
  return !name || $('source').value !== librarySource || $('language').value !== (library.get(name)?.language || '');
}

/** The parameters whose value differs from their declared default. */
function changedParams() {
  const changed = {};
  for (const [name, value] of Object.entries(formValues())) {
    const spec = schemaParams[name];
    if (spec?.default === undefined || String(spec.default) !== String(value)) changed[name] = value;
  }
  return changed;
}

/** Writes the state into the URL (replacing, not adding, a history entry). */
function writeLink() {
  if (pending !== null) return; // a link is being opened: it is the URL already
  const link = new URLSearchParams();
  const name = $('grammar').value;
  if (name) link.set('grammar', name);
  if (edited()) link.set('edited', '1');
  const seed = $('seed').value.trim();
  if (seed !== '') link.set('seed', seed);
  link.set('format', $('format').value || 'glb');
  for (const [k, v] of Object.entries(changedParams())) link.set(`p.${k}`, String(v));
  const hash = `#${link}`;
  if (location.hash !== hash) history.replaceState(null, '', hash);
}

function showNote(problems) {
  linkProblems = problems;
  $('note').textContent = problems.length ? `Ignored from the link: ${problems.join('; ')}.` : '';
  $('note').hidden = problems.length === 0;
}

/** A seed as the server reads it (a decimal from 0 to 2^64 - 1, normalised), or null. */
function validSeed(text) {
  if (!/^[0-9]{1,20}$/.test(text)) return null;
  const n = BigInt(text);
  return n <= MAX_SEED ? String(n) : null;
}

/** Sets the form's input `name` to the link's `text`; a problem's description, or null. */
function setParam(name, text) {
  const input = Array.from($('params').elements).find((i) => i.name === name);
  if (!input) return `p.${name} (the grammar has no parameter ${JSON.stringify(name)})`;
  switch (input.dataset.kind) {
    case 'bool':
      if (text !== 'true' && text !== 'false') return `p.${name}=${text} (not true or false)`;
      input.checked = text === 'true';
      return null;
    case 'number': {
      const v = text.trim() === '' ? NaN : Number(text);
      const integer = input.step === '1';
      const low = input.min === '' ? -Infinity : Number(input.min);
      const high = input.max === '' ? Infinity : Number(input.max);
      if (!Number.isFinite(v) || (integer && !Number.isInteger(v)) || v < low || v > high) {
        const range = `${integer ? 'a whole number' : 'a number'}${input.min !== '' ? ` from ${input.min}` : ''}${input.max !== '' ? ` to ${input.max}` : ''}`;
        return `p.${name}=${text} (not ${range})`;
      }
      input.value = String(v);
      return null;
    }
    case 'preset':
    case 'enum':
      if (!Array.from(input.options).some((o) => o.value === text)) return `p.${name}=${text} (not one of its choices)`;
      input.value = text;
      return null;
    default:
      input.value = text;
      return null;
  }
}

/** Opens the state the URL names (or the default grammar) and renders it. */
async function openLink() {
  const problems = [];
  let name = null;
  let seed = null;
  let format = null;
  let wasEdited = false;
  const params = new Map();
  for (const [k, v] of new URLSearchParams(location.hash.replace(/^#/, ''))) {
    if (k === 'grammar') name = v;
    else if (k === 'seed') seed = v;
    else if (k === 'format') format = v;
    else if (k === 'edited') wasEdited = true;
    else if (k.startsWith('p.') && k.length > 2) params.set(k.slice(2), v);
    else problems.push(`${k} (not a setting of the playground)`);
  }
  if (name !== null && !library.has(name)) {
    problems.push(`grammar ${JSON.stringify(name)} (not in the library)`);
    name = null;
  }
  if (wasEdited) problems.push('edited source (links do not carry source: this is the library grammar)');
  if (name === null && library.size > 0) {
    name = library.has(DEFAULT_GRAMMAR) ? DEFAULT_GRAMMAR : library.keys().next().value;
  }
  // What a link leaves out takes the page's defaults: seed 1, glb.
  const valid = validSeed(seed ?? '1');
  if (valid === null) problems.push(`seed ${JSON.stringify(seed)} (not a whole number from 0 to ${MAX_SEED})`);
  $('seed').value = valid ?? '1';
  showNote(problems);
  if (name === null) return;
  pending = { format: format ?? 'glb', params };
  if (await loadGrammar(name)) render();
  else pending = null;
}

/**
 * After the opened grammar's schema is read (its formats and its form): the
 * link's format and parameters, each checked against it.
 */
function applyPending(parsed) {
  if (pending === null) return;
  const problems = [];
  const formats = Array.from($('format').options).map((o) => o.value);
  if (formats.includes(pending.format)) $('format').value = pending.format;
  else {
    problems.push(`format ${JSON.stringify(pending.format)} (not one of ${formats.join(', ')})`);
    $('format').value = 'glb';
  }
  for (const [name, text] of pending.params) {
    const problem = parsed ? setParam(name, text) : `p.${name} (the source does not parse)`;
    if (problem) problems.push(problem);
  }
  pending = null;
  if (problems.length) showNote([...linkProblems, ...problems]);
}

/** Lists the library in the grammar menu, one group per language. */
async function loadLibrary() {
  const response = await get('/v1/grammars');
  if (!response.ok) {
    $('status').textContent = `grammar list: ${await errorText(response)}`;
    return false;
  }
  library.clear();
  const groups = new Map();
  for (const g of (await response.json()).grammars) {
    library.set(g.name, { language: g.language, description: g.description || '' });
    if (!groups.has(g.language)) {
      const group = document.createElement('optgroup');
      group.label = LANGUAGE_LABELS[g.language] || g.language;
      group.dataset.language = g.language;
      groups.set(g.language, group);
    }
    const option = new Option(g.name, g.name);
    option.dataset.language = g.language;
    option.title = g.description || '';
    groups.get(g.language).append(option);
  }
  const own = Array.from($('grammar').options).filter((o) => o.value === '');
  $('grammar').replaceChildren(...own, ...groups.values());
  return true;
}

async function start() {
  fillSelect($('language'), LANGUAGES, false);
  fillSelect($('format'), FORMATS, false);
  $('source').addEventListener('input', () => {
    drawGutter();
    scheduleRender();
  });
  $('source').addEventListener('scroll', () => { $('gutter').scrollTop = $('source').scrollTop; });
  for (const id of ['seed', 'format', 'language']) $(id).addEventListener('change', scheduleRender);
  $('grammar').addEventListener('change', pickGrammar);
  $('render').addEventListener('click', render);
  // A link pasted into this tab (replaceState, the page's own writes, fires no hashchange).
  window.addEventListener('hashchange', openLink);
  // Without the key a keyed server asks for, the library did not load: retry with it.
  $('api-key').addEventListener('change', async () => {
    if (library.size === 0 && (await loadLibrary())) openLink();
  });
  drawGutter();
  const loaded = await loadLibrary();
  document.body.dataset.renders = '0';
  setState('idle', 'none');
  if (loaded) await openLink();
}

start();
