// Validates a glTF/GLB file with the Khronos glTF validator and prints its report summary.
// Exit status: 0 with no errors, 1 with errors, 2 if the file cannot be read.
// Usage: node tools/gltf-validator/validate.mjs FILE
import { readFile } from 'node:fs/promises';
import { dirname, join } from 'node:path';
import validator from 'gltf-validator';

const file = process.argv[2];
let bytes;
try {
  bytes = new Uint8Array(await readFile(file));
} catch (error) {
  console.error(`cannot read ${file}: ${error.message}`);
  process.exit(2);
}
// A .gltf's buffers and images beside it (relative URIs, percent-encoded).
const externalResourceFunction = async (uri) =>
  new Uint8Array(await readFile(join(dirname(file), decodeURIComponent(uri))));
const report = await validator.validateBytes(bytes, { maxIssues: 50, externalResourceFunction });
const { numErrors, numWarnings, numInfos, messages } = report.issues;
for (const m of messages) if (m.severity === 0) console.log(`error: ${m.code} ${m.pointer ?? ''}: ${m.message}`);
console.log(JSON.stringify({ errors: numErrors, warnings: numWarnings, infos: numInfos }));
process.exit(numErrors === 0 ? 0 : 1);
