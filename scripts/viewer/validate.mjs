// Checks a .glb with the Khronos glTF validator:  node scripts/viewer/validate.mjs FILE.glb
// Prints the counts (and the messages, if any); exits 1 when there is an error or a warning.
import fs from 'fs';
import validator from 'gltf-validator';

const file = process.argv[2];
if (!file || !fs.existsSync(file)) {
  console.error('usage: node validate.mjs FILE.glb');
  process.exit(2);
}
const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)));
const { numErrors, numWarnings, numInfos, numHints, messages } = report.issues;
console.log(`${file}: ${numErrors} errors, ${numWarnings} warnings, ${numInfos} infos, ${numHints} hints`);
for (const m of messages) console.log(`  ${m.severity === 0 ? 'error' : 'note'} ${m.code} at ${m.pointer}: ${m.message}`);
process.exit(numErrors > 0 || numWarnings > 0 ? 1 : 0);
