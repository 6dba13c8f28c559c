// Validates glTF and GLB files with the Khronos glTF validator (npm package gltf-validator):
// prints each file's error, warning and info counts and its messages, and exits 1 when any file
// has an error. Usage: node gltf_validate.js VALIDATOR_PACKAGE_DIR FILE...
'use strict';
const fs = require('fs');
const path = require('path');
const validator = require(process.argv[2]);

async function validate(file) {
    const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
        uri: path.basename(file),
        maxIssues: 0,
        externalResourceFunction: (uri) =>
            new Promise((resolve, reject) => {
                fs.readFile(path.join(path.dirname(file), decodeURIComponent(uri)), (error, data) =>
                    error ? reject(error.toString()) : resolve(new Uint8Array(data)));
            }),
    });
    const issues = report.issues;
    console.log(`${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ${issues.numInfos} infos`);
    for (const m of issues.messages.slice(0, 20))
        console.log(`  ${['error', 'warning', 'info', 'hint'][m.severity]} ${m.code} ${m.pointer || ''}: ${m.message}`);
    return issues.numErrors;
}

(async () => {
    let errors = 0;
    for (const file of process.argv.slice(3)) errors += await validate(file);
    process.exit(errors > 0 ? 1 : 0);
})().catch((error) => {
    console.error(error.toString());
    process.exit(2);
});
