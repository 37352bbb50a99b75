// Runs the Khronos glTF validator (vendored npm package gltf-validator, tests/vendor/) on each file
// named and prints one JSON line per file: errors, warnings, and what the validator saw. Exit
// status 1 when any file has an error. Used by the head3d tests; nothing is downloaded.
'use strict';
const fs = require('fs');
const path = require('path');
const validator = require(path.join(__dirname, '..', 'vendor', 'gltf-validator'));

async function main() {
  let failed = false;
  for (const file of process.argv.slice(2)) {
    const bytes = new Uint8Array(fs.readFileSync(file));
    const report = await validator.validateBytes(bytes, {
      uri: path.basename(file),
      maxIssues: 50,
      externalResourceFunction: () => Promise.reject(new Error('no external resources')),
    });
    const line = {
      file,
      errors: report.issues.numErrors,
      warnings: report.issues.numWarnings,
      messages: report.issues.messages.filter((m) => m.severity <= 1).map((m) => `${m.code} ${m.pointer || ''} ${m.message}`),
      animationCount: report.info.animationCount,
      hasMorphTargets: report.info.hasMorphTargets,
      morphedPrimitivesCount: report.info.morphedPrimitivesCount,
      totalVertexCount: report.info.totalVertexCount,
    };
    process.stdout.write(JSON.stringify(line) + '\n');
    if (report.issues.numErrors > 0) failed = true;
  }
  process.exit(failed ? 1 : 0);
}
main().catch((e) => {
  process.stderr.write(String(e && e.stack || e) + '\n');
  process.exit(2);
});
