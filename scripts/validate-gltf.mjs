#!/usr/bin/env node
// Validates .glb / .gltf files with the Khronos glTF Validator.
//
// Usage: node scripts/validate-gltf.mjs FILE...
//
// Prints one JSON line per file: {"file", "numErrors", "numWarnings",
// "numInfos", "numHints", "messages": [{"code","severity","message","pointer"}]}
// and exits 1 if any file has errors (2 if the validator cannot be found or
// a file cannot be read).
//
// The `gltf-validator` npm package is looked up, in order:
//   1. in $GLTF_VALIDATOR_DIR: a folder holding node_modules/gltf-validator
//      (an `npm install --prefix DIR` target), a node_modules folder, or the
//      package folder itself;
//   2. in .tools/ at the repository root (`npm install --prefix .tools gltf-validator`);
//   3. by Node's usual resolution from this script's folder.
import { createRequire } from 'node:module';
import { readFileSync } from 'node:fs';
import { dirname, join, resolve, basename } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const repoRoot = resolve(here, '..');

function loadValidator() {
  const attempts = [];
  const tryFrom = (base, spec) => {
    try {
      // createRequire takes a file path; resolution starts at its folder's
      // node_modules and walks up (folders named node_modules are searched directly).
      return createRequire(join(base, '__validate_gltf__.js'))(spec);
    } catch (e) {
      attempts.push(`${spec} from ${base}: ${e.code || e.message}`);
      return null;
    }
  };
  const env = process.env.GLTF_VALIDATOR_DIR;
  if (env) {
    const dir = resolve(env);
    const v = tryFrom(dir, 'gltf-validator') || tryFrom(dir, dir);
    if (v) return v;
  }
  const v = tryFrom(join(repoRoot, '.tools'), 'gltf-validator') || tryFrom(here, 'gltf-validator');
  if (v) return v;
  console.error('gltf-validator not found; install it with `npm install --prefix .tools gltf-validator` ' +
    'or set GLTF_VALIDATOR_DIR.\n  ' + attempts.join('\n  '));
  process.exit(2);
}

const files = process.argv.slice(2);
if (files.length === 0) {
  console.error('usage: node scripts/validate-gltf.mjs FILE...');
  process.exit(2);
}
const validator = loadValidator();
let failed = false;
let unreadable = false;
for (const file of files) {
  let bytes;
  try {
    bytes = new Uint8Array(readFileSync(file));
  } catch (e) {
    console.log(JSON.stringify({ file, error: e.message }));
    unreadable = true;
    continue;
  }
  const report = await validator.validateBytes(bytes, {
    uri: basename(file),
    maxIssues: 0,
    // Our outputs are self-contained; refuse to fetch anything else.
    externalResourceFunction: (uri) => Promise.reject(new Error(`external resource not allowed: ${uri}`)),
  });
  const issues = report.issues;
  const severities = ['error', 'warning', 'info', 'hint'];
  const line = {
    file,
    numErrors: issues.numErrors,
    numWarnings: issues.numWarnings,
    numInfos: issues.numInfos,
    numHints: issues.numHints,
    messages: issues.messages.map((m) => ({
      code: m.code,
      severity: severities[m.severity] ?? m.severity,
      message: m.message,
      pointer: m.pointer,
    })),
  };
  console.log(JSON.stringify(line));
  if (issues.numErrors > 0) failed = true;
}
process.exit(unreadable ? 2 : failed ? 1 : 0);
