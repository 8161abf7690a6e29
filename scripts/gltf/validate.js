// Runs the Khronos glTF validator over the .glb files given; prints one line per file and
// every error, warning and information, and exits 1 when any file has an error or warning.
const validator = require('gltf-validator');
const fs = require('fs');
(async () => {
    let failed = 0;
    for (const file of process.argv.slice(2)) {
        const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
            maxIssues: 100,
        });
        const { numErrors, numWarnings, numInfos } = report.issues;
        console.log(`${file}: ${numErrors} errors, ${numWarnings} warnings, ${numInfos} infos`);
        for (const m of report.issues.messages)
            if (m.severity <= 1) console.log(`  [${m.severity}] ${m.code} ${m.pointer || ''}: ${m.message}`);
        if (numErrors > 0 || numWarnings > 0) failed += 1;
    }
    if (failed > 0) {
        console.log(`${failed} file(s) with errors or warnings`);
        process.exit(1);
    }
})();
