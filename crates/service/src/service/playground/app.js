// The rulemesh playground: pick a library grammar or paste source, edit its
// parameters through a form built from the server's parameter schema
// (POST /v1/schema), and see the model in three.js with its diagnostics
// (POST /v1/check) marked at their lines, the response headers and the size
// of every format. Everything it loads comes from this server.
//
// For tests (scripts/playground-check/), the page reports its state on
// <body>: data-state is "busy" while a render is in flight and "idle"
// after, data-renders counts finished renders, data-outcome says how the
// last one ended ("model", "preview", "parse-error", "error: …").
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { MeshoptDecoder } from 'three/addons/libs/meshopt_decoder.module.js';

const $ = (id) => document.getElementById(id);
/** Formats whose size the page lists after each render. */
const SIZE_FORMATS = ['glb', 'gltf', 'stl', '3mf', 'strips', 'png'];
/** The languages the server reads (replaced by the schema's list once one arrives). */
const LANGUAGES = ['mdg', 'lsystem', 'eisenscript', 'stack', 'ug', 'etol'];

let schemaParams = {};
let lastSchema = '';
let seq = 0;
let renders = 0;
let changeTimer = null;
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

/** Checks the source (diagnostics) and reads its schema (the form); true when it parses. */
async function analyse() {
  const body = { source: $('source').value };
  if ($('language').value) body.language = $('language').value;
  const check = await (await post('/v1/check', body)).json();
  showDiagnostics(check.diagnostics || []);
  if (!check.ok) return false;
  const schema = await post('/v1/schema', body);
  if (!schema.ok) return false;
  buildForm(await schema.json());
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
    if (!(await analyse())) {
      finish('parse-error', 'The source does not parse: see the marked lines.');
      return;
    }
    if (mine !== seq) return;
    const format = $('format').value || 'glb';
    const response = await post('/v1/render', request(format));
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
      const glb = format === 'glb' || format === 'gltf' ? bytes : await (await post('/v1/render', request('glb'))).arrayBuffer();
      if (mine !== seq) return;
      const gltf = await parseGlb(glb);
      if (mine !== seq) return;
      preview.hidden = true;
      viewer.show(gltf.scene);
      $('triangles').textContent = String(countTriangles(gltf.scene));
      finish('model', `${format}: ${bytes.byteLength} bytes.`);
    }
    listSizes(mine);
  } catch (e) {
    finish(`error: ${e.message || e}`, String(e.message || e));
  }
}

/** Fills the size-per-format table, one request at a time, for the render `mine`. */
async function listSizes(mine) {
  const rows = $('sizes').tBodies[0];
  rows.replaceChildren();
  for (const format of SIZE_FORMATS) {
    if (mine !== seq) return;
    const row = rows.insertRow();
    row.insertCell().textContent = format;
    const cell = row.insertCell();
    row.dataset.format = format;
    const response = await post('/v1/render', request(format));
    const bytes = response.ok ? (await response.arrayBuffer()).byteLength : null;
    cell.textContent = bytes === null ? (await errorText(response)) : `${bytes} bytes`;
  }
}

function scheduleRender() {
  if (!$('auto').checked) return;
  clearTimeout(changeTimer);
  changeTimer = setTimeout(render, 250);
}

async function pickGrammar() {
  const name = $('grammar').value;
  if (!name) return;
  const response = await get(`/v1/grammars/${encodeURIComponent(name)}`);
  if (!response.ok) {
    $('status').textContent = await errorText(response);
    return;
  }
  $('source').value = await response.text();
  $('language').value = $('grammar').selectedOptions[0].dataset.language || '';
  $('params').replaceChildren();
  drawGutter();
  render();
}

async function start() {
  fillSelect($('language'), LANGUAGES, false);
  fillSelect($('format'), SIZE_FORMATS, false);
  $('source').addEventListener('input', () => {
    drawGutter();
    scheduleRender();
  });
  $('source').addEventListener('scroll', () => { $('gutter').scrollTop = $('source').scrollTop; });
  for (const id of ['seed', 'format', 'language']) $(id).addEventListener('change', scheduleRender);
  $('grammar').addEventListener('change', pickGrammar);
  $('render').addEventListener('click', render);
  drawGutter();
  const response = await get('/v1/grammars');
  if (response.ok) {
    for (const g of (await response.json()).grammars) {
      const option = new Option(g.name, g.name);
      option.dataset.language = g.language;
      option.title = g.description || '';
      $('grammar').append(option);
    }
  } else {
    $('status').textContent = `grammar list: ${await errorText(response)}`;
  }
  document.body.dataset.renders = '0';
  setState('idle', 'none');
}

start();
