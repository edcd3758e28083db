#!/usr/bin/env bash
# Rewrites goldens/release_*.png with the RELEASE binary. tests/render_determinism.rs
# then requires the test-profile library and binary to produce exactly these bytes
# (debug/test vs release determinism). Run after an intended change of the
# renderer's output, look at the pictures, commit them.
set -euo pipefail
cd "$(dirname "$0")/.."
common=(tests/data/oak_leafless.obj --size 200x150 --headlight on --threads 2)
cargo run --release -q -- render "${common[@]}" --style filled -o goldens/release_oak.png
cargo run --release -q -- render "${common[@]}" --style lines -o goldens/release_oak_lines.png
echo "release-goldens: wrote goldens/release_oak.png goldens/release_oak_lines.png"
