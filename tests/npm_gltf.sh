#!/usr/bin/env bash
# Installs the npm packages the glTF cross-checks use (tests/gltf_node: the
# Khronos validator and three.js) into target/npm-gltf, once. Called by
# tests/run-all.sh (CI) and .ci/land, so a landing runs those checks too
# instead of printing NOT RUN. Without node/npm it says so loudly; the tests
# then print NOT RUN themselves.
set -uo pipefail
cd "$(dirname "$0")/.."
if command -v npm >/dev/null 2>&1 && command -v node >/dev/null 2>&1; then
  if [ ! -d target/npm-gltf/node_modules/three ] || [ ! -d target/npm-gltf/node_modules/gltf-validator ]; then
    mkdir -p target/npm-gltf
    [ -f target/npm-gltf/package.json ] || echo '{"private":true}' > target/npm-gltf/package.json
    npm install --prefix target/npm-gltf --no-audit --no-fund gltf-validator three >/dev/null 2>&1 \
      || echo "npm_gltf: could not install gltf-validator/three: glTF cross-checks NOT RUN"
  fi
else
  echo "npm_gltf: node/npm missing: glTF validator and three.js checks NOT RUN"
fi
