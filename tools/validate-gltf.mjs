// Validate one glTF/GLB file with the Khronos glTF validator and print its JSON report.
// Usage: node tools/validate-gltf.mjs FILE.glb
// Exit code: 0 when the report has no errors, 1 when it has, 2 when the file cannot be read.
import { readFile } from "node:fs/promises";
import path from "node:path";
import validator from "gltf-validator";

const file = process.argv[2];
if (!file) {
  console.error("usage: node validate-gltf.mjs FILE.glb");
  process.exit(2);
}

let bytes;
try {
  bytes = await readFile(file);
} catch (err) {
  console.error(`cannot read ${file}: ${err.message}`);
  process.exit(2);
}

const report = await validator.validateBytes(new Uint8Array(bytes), {
  uri: path.basename(file),
  maxIssues: 200,
  externalResourceFunction: (uri) =>
    readFile(path.resolve(path.dirname(file), decodeURIComponent(uri))).then((b) => new Uint8Array(b)),
});
console.log(JSON.stringify(report, null, 2));
process.exit(report.issues.numErrors > 0 ? 1 : 0);
