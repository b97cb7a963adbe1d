// Runs the Khronos glTF validator (npm gltf-validator) on every .glb in a folder, prints each
// report and fails on any error, or when a file does not use KHR_draco_mesh_compression.
// Usage: node validate_glb.mjs <folder>

import { readFile, readdir } from 'node:fs/promises';
import path from 'node:path';

const INSTALL_HINT = 'run `npm ci --prefix tests/node` in the repository root';

function fail(message) {
  console.error(`FAIL: ${message}`);
  process.exit(1);
}

async function loadValidator() {
  try {
    return (await import('gltf-validator')).default;
  } catch (error) {
    fail(`cannot load npm gltf-validator (${error.message}): ${INSTALL_HINT}`);
  }
}

async function validate(validator, folder, name) {
  const bytes = await readFile(path.join(folder, name));
  const report = await validator.validateBytes(new Uint8Array(bytes), {
    uri: name,
    maxIssues: 0, // report them all
    externalResourceFunction: (uri) => readFile(path.join(folder, decodeURIComponent(uri))),
  });
  const { numErrors, numWarnings, numInfos, numHints } = report.issues;
  const extensions = report.info?.extensionsUsed ?? [];
  console.log(`${name}: ${numErrors} errors, ${numWarnings} warnings, ${numInfos} infos, ` +
    `${numHints} hints; extensions used: ${extensions.join(', ') || 'none'}`);
  if (report.issues.messages.length > 0) {
    console.log(JSON.stringify(report.issues.messages, null, 2));
  }
  const problems = [];
  if (numErrors > 0) problems.push(`${numErrors} validation errors`);
  if (!extensions.includes('KHR_draco_mesh_compression')) {
    problems.push('KHR_draco_mesh_compression is not used');
  }
  return problems;
}

async function main() {
  const folder = process.argv[2];
  if (!folder) fail('usage: node validate_glb.mjs <folder with .glb files>');
  const validator = await loadValidator();
  const names = (await readdir(folder)).filter((name) => name.endsWith('.glb')).sort();
  if (names.length === 0) fail(`no .glb files in ${folder}`);
  let failures = 0;
  for (const name of names) {
    const problems = await validate(validator, folder, name);
    if (problems.length > 0) {
      failures++;
      console.error(`FAIL ${name}: ${problems.join('; ')}`);
    }
  }
  if (failures > 0) fail(`${failures} of ${names.length} .glb files failed validation`);
  console.log(`all ${names.length} .glb files pass the Khronos glTF validator with 0 errors`);
}

await main();
