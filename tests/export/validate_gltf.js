// Runs the Khronos glTF-Validator (npm package gltf-validator) on one .gltf or .glb file and
// exits 0 when it reports no errors, 1 otherwise (printing its messages). External resources
// (.bin, images) are read from the file's folder.
// Usage: node validate_gltf.js FILE
'use strict';
const fs = require('fs');
const path = require('path');
const validator = require('gltf-validator');

const file = process.argv[2];
const bytes = new Uint8Array(fs.readFileSync(file));
validator
  .validateBytes(bytes, {
    uri: path.basename(file),
    externalResourceFunction: (uri) =>
      new Promise((resolve, reject) => {
        fs.readFile(path.join(path.dirname(file), decodeURIComponent(uri)), (err, data) =>
          err ? reject(err.toString()) : resolve(new Uint8Array(data)));
      }),
  })
  .then((report) => {
    const issues = report.issues;
    for (const m of issues.messages) {
      console.log(`${['error', 'warning', 'info', 'hint'][m.severity]}: ${m.code} ${m.pointer || ''} ${m.message}`);
    }
    console.log(`${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ` +
                `${issues.numInfos} infos, ${issues.numHints} hints`);
    process.exit(issues.numErrors === 0 ? 0 : 1);
  })
  .catch((error) => {
    console.log(`${file}: the validator failed: ${error}`);
    process.exit(1);
  });
