#!/usr/bin/env bash
# Fetches the npm package "bunny" (the Stanford bunny, public domain) and writes assets/bunny.obj.
# Run once; the OBJ is committed, so builds never download anything. Needs node and npm.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
(cd "$WORK" && npm pack bunny@1.0.1 --silent > /dev/null && tar xzf bunny-1.0.1.tgz)
node "$ROOT/scripts/convert_bunny.js" "$WORK/package" "$ROOT/assets/bunny.obj"
echo "wrote $ROOT/assets/bunny.obj"
