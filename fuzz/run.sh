#!/usr/bin/env bash
# Runs one fuzz target for a while under a memory cap (one at a time: the
# machine is shared).
#
#   bash fuzz/run.sh vrml97 1200      # target, seconds (default 1200)
#
# Needs cargo-fuzz (`cargo install cargo-fuzz`); on a stable toolchain the
# sanitizer flags need RUSTC_BOOTSTRAP=1, set here. A crash, a leak of more
# than the cap or a timeout writes fuzz/artifacts/TARGET/… and fails.
set -euo pipefail
cd "$(dirname "$0")"
target=${1:?target: lexer, vrml97 or inventor}
secs=${2:-1200}
mkdir -p "corpus/$target"
RUSTC_BOOTSTRAP=1 cargo fuzz run --release "$target" "corpus/$target" -- \
  -max_total_time="$secs" -rss_limit_mb=1536 -malloc_limit_mb=1536 -timeout=20 \
  -max_len=65536 -print_final_stats=1
