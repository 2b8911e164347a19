#!/usr/bin/env bash
# Installs the Khronos glTF validator (npm package "gltf-validator") into a cache directory, with
# a small command-line wrapper, so that tests/io/surface_io_test.cpp can check the glTF files we
# write (tests/io, tests/anim). The tests fail when it is not installed.
#
#   scripts/install-gltf-validator.sh            # into ${XDG_CACHE_HOME:-~/.cache}/sculpt/gltf-validator
#   SCULPT_GLTF_VALIDATOR_DIR=DIR scripts/install-gltf-validator.sh
#
# Needs node and npm (Debian: apt-get install nodejs npm). Idempotent.
set -euo pipefail

DIR="${SCULPT_GLTF_VALIDATOR_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/sculpt/gltf-validator}"
VERSION="2.0.0-dev.3.10"

for tool in node npm; do
  command -v "$tool" >/dev/null || { echo "error: $tool is not installed" >&2; exit 1; }
done

mkdir -p "$DIR"
if [[ ! -f "$DIR/node_modules/gltf-validator/package.json" ]] ||
   ! grep -q "\"version\": \"$VERSION\"" "$DIR/node_modules/gltf-validator/package.json"; then
  npm install --prefix "$DIR" --no-save --no-audit --no-fund "gltf-validator@$VERSION"
fi

# validate.js FILE: prints the report's messages; exit status 1 when it has errors, 2 when the
# file cannot be read. External resources are resolved next to the file.
cat > "$DIR/validate.js" <<'JS'
const fs = require('fs');
const path = require('path');
const validator = require(path.join(__dirname, 'node_modules', 'gltf-validator'));
const file = process.argv[2];
let bytes;
try {
  bytes = new Uint8Array(fs.readFileSync(file));
} catch (error) {
  console.error(String(error));
  process.exit(2);
}
validator.validateBytes(bytes, {
  uri: path.basename(file),
  externalResourceFunction: (uri) => new Promise((resolve, reject) => {
    fs.readFile(path.join(path.dirname(file), decodeURIComponent(uri)),
                (error, data) => error ? reject(error.toString()) : resolve(new Uint8Array(data)));
  }),
}).then((report) => {
  for (const message of report.issues.messages) {
    const severity = ['error', 'warning', 'info', 'hint'][message.severity];
    console.log(`${severity} ${message.code} ${message.pointer || ''}: ${message.message}`);
  }
  console.log(`errors=${report.issues.numErrors} warnings=${report.issues.numWarnings}`);
  process.exit(report.issues.numErrors > 0 ? 1 : 0);
}, (error) => {
  console.error(String(error));
  process.exit(2);
});
JS
echo "gltf-validator $VERSION installed in $DIR (run: node $DIR/validate.js FILE)"
