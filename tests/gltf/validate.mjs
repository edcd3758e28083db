// Runs the Khronos glTF validator on each file given; prints one JSON line
// per file: {"file", "errors", "warnings", "messages": [first few errors]}.
// Exit code 1 when any file has errors.
import { createRequire } from 'module';
import fs from 'fs';
import path from 'path';
const require = createRequire(process.env.NPM_DIR ? path.join(process.env.NPM_DIR, 'x.js') : import.meta.url);
const validator = require('gltf-validator');
let bad = 0;
for (const file of process.argv.slice(2)) {
  const bytes = new Uint8Array(fs.readFileSync(file));
  const report = await validator.validateBytes(bytes, {
    uri: path.basename(file),
    externalResourceFunction: (uri) =>
      new Promise((resolve, reject) => {
        try { resolve(new Uint8Array(fs.readFileSync(path.join(path.dirname(file), decodeURIComponent(uri))))); }
        catch (e) { reject(e.toString()); }
      }),
  });
  const issues = report.issues;
  const messages = issues.messages.filter((m) => m.severity === 0).slice(0, 5)
    .map((m) => `${m.code} ${m.pointer || ''}: ${m.message}`);
  console.log(JSON.stringify({ file, errors: issues.numErrors, warnings: issues.numWarnings, messages }));
  if (issues.numErrors > 0) bad = 1;
}
process.exit(bad);
