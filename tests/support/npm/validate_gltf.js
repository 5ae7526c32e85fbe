// Validates a glTF file with Khronos's glTF validator (the gltf-validator package that
// package-lock.json pins; `npm ci` here installs it) and prints its report as one line of JSON:
// issues.numErrors, numWarnings, numInfos, numHints and the messages. Used by
// tests/cli/export_gltf_test.cpp. Usage: node validate_gltf.js FILE.glb
const fs = require('fs');
const validator = require('gltf-validator');

const bytes = new Uint8Array(fs.readFileSync(process.argv[2]));
validator
  .validateBytes(bytes, {
    maxIssues: 100,
    // A .glb Saltus writes holds everything; a reference to anything else is an error.
    externalResourceFunction: (uri) => Promise.reject(new Error('external resource ' + uri)),
  })
  .then((report) => console.log(JSON.stringify(report)))
  .catch((error) => {
    console.error('validate_gltf.js: ' + error);
    process.exit(1);
  });
