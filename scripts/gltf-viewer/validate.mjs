// Validates a glTF file with the Khronos glTF Validator and prints its report's summary as JSON:
//   node validate.mjs FILE.glb|FILE.gltf
// A .gltf's external buffers are read from beside it. Exit status 0 whatever the findings; the
// caller reads the counts (numErrors, numWarnings, numInfos, numHints) and the messages.
import fs from 'node:fs';
import path from 'node:path';
import validator from 'gltf-validator';

const file = process.argv[2];
if (!file) {
  console.error('usage: node validate.mjs FILE.glb|FILE.gltf');
  process.exit(2);
}
const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
  uri: path.basename(file),
  maxIssues: 0,
  externalResourceFunction: (uri) =>
    new Promise((resolve, reject) => {
      fs.readFile(path.join(path.dirname(file), decodeURIComponent(uri)), (err, data) =>
        err ? reject(err.toString()) : resolve(new Uint8Array(data)));
    }),
});
const issues = report.issues;
console.log(JSON.stringify({
  numErrors: issues.numErrors,
  numWarnings: issues.numWarnings,
  numInfos: issues.numInfos,
  numHints: issues.numHints,
  messages: issues.messages.map((m) => ({ code: m.code, severity: m.severity, pointer: m.pointer, message: m.message })),
  info: report.info,
}, null, 1));
