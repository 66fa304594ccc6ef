// Validates a .gltf or .glb file with the Khronos glTF validator (npm gltf-validator)
// and prints its counts as JSON; exit 1 when it reports an error. External buffers and
// images are read from beside the file.
//
//   NODE_PATH=DIR/node_modules node gltf_validate.cjs FILE
const fs = require('fs');
const path = require('path');
const validator = require('gltf-validator');

const file = process.argv[2];
const bytes = new Uint8Array(fs.readFileSync(file));
validator.validateBytes(bytes, {
  uri: path.basename(file),
  maxIssues: 100,
  externalResourceFunction: (uri) => new Promise((resolve, reject) => {
    fs.readFile(path.resolve(path.dirname(file), decodeURIComponent(uri)),
                (err, data) => (err ? reject(err.toString()) : resolve(new Uint8Array(data))));
  }),
}).then((report) => {
  const i = report.issues;
  console.log(JSON.stringify({errors: i.numErrors, warnings: i.numWarnings, infos: i.numInfos,
                              messages: i.messages.filter((m) => m.severity === 0).slice(0, 5),
                              triangles: report.info ? report.info.totalTriangleCount : null}));
  process.exit(i.numErrors > 0 ? 1 : 0);
}, (error) => {
  console.error(`gltf_validate: ${error}`);
  process.exit(2);
});
