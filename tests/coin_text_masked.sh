#!/usr/bin/env bash
# How much of a text file's Coin difference is the text itself (issue 19).
#
# For each corpus FILE given (path under ../shared/corpus), prints three
# silhouette IoUs of Coin 4.0 against animed, at W×H (default 160×120, as
# tests/coin_corpus.sh, with the same masks):
#   own     each renderer frames the file itself (coin_corpus.sh's figure);
#   coin    both draw a copy with Coin's view-all camera put in it
#           (tests/coin_camera.py), so framing is the same;
#   masked  that copy, with every pixel either renderer draws for text
#           painted background in both (text pixels: where the copy differs
#           from a second copy whose `string` fields are emptied).
# `masked` near 1 with `coin` low says the difference is the glyphs alone.
#
#   ANIMED=target/release/animed bash tests/coin_text_masked.sh \
#     castle-engine-demo-models/prototypes/proto_nodes.wrl
#
# Exit 3 when a tool is missing (said loudly: not a pass).
set -uo pipefail
cd "$(dirname "$0")/.."
ROOT=$(pwd)
SHARED=${ANIMED_SHARED:-$ROOT/../shared}
ANIMED=${ANIMED:-$ROOT/target/release/animed}
W=${W:-160}
H=${H:-120}
BG=0.31,0.07,0.27
HEX='#4f1245' # BG as 8-bit, what the masks take for background
PY=(env LD_PRELOAD=/usr/lib/x86_64-linux-gnu/libGL.so.1 /usr/bin/python3)

missing=()
[ -f "$SHARED/tools/coin_render.py" ] || missing+=("$SHARED/tools/coin_render.py")
[ -x "$ANIMED" ] || missing+=("$ANIMED (cargo build --release)")
[ -x /usr/bin/convert ] || missing+=(imagemagick)
command -v Xvfb >/dev/null 2>&1 || missing+=(xvfb)
/usr/bin/python3 -c 'import pivy, PySide2' >/dev/null 2>&1 || missing+=(python3-pivy/python3-pyside2.qtgui)
if [ ${#missing[@]} -gt 0 ]; then
  echo "coin_text_masked: NOT RUN — missing: ${missing[*]} (not a pass)"
  exit 3
fi
[ $# -gt 0 ] || { echo "usage: $0 FILE... (paths under $SHARED/corpus)"; exit 2; }

TMP=$(mktemp -d)
DISP=:$((500 + RANDOM % 400))
Xvfb "$DISP" -screen 0 1024x768x24 +extension GLX +render -noreset >/dev/null 2>&1 &
XPID=$!
trap 'kill $XPID 2>/dev/null; rm -rf "$TMP"' EXIT
export DISPLAY=$DISP
sleep 2

# IoU of the non-background pixels of two pictures (coin_corpus.sh's masks).
iou() {
  local p
  for p in "$1" "$2"; do
    /usr/bin/convert "$p" -alpha off -fuzz 3% -fill white +opaque "$HEX" -fill black -opaque "$HEX" \
      -colorspace Gray -threshold 50% "$p.mask.png"
  done
  local i u
  i=$(/usr/bin/convert "$1.mask.png" "$2.mask.png" -compose multiply -composite -format '%[fx:mean*w*h]' info:)
  u=$(/usr/bin/convert "$1.mask.png" "$2.mask.png" -compose lighten -composite -format '%[fx:mean*w*h]' info:)
  awk -v i="$i" -v u="$u" 'BEGIN { if (u == 0) print "nan"; else printf "%.4f", i / u }'
}

# Both renderers' pictures of $1 into $TMP/coin_$2.png and $TMP/animed_$2.png;
# Coin's (and its camera) through tests/coin_render_font.py, as in
# tests/coin_corpus.sh, so it draws each text in animed's face.
both() {
  (cd "$DIR" && timeout 60 "${PY[@]}" "$ROOT/tests/coin_render_font.py" "$SHARED/tools/coin_render.py" \
    "$1" "$TMP/coin_$2.png" $W $H \
    --time 0 --headlight auto --bg $BG >/dev/null 2>&1)
  timeout 60 "$ANIMED" render "$1" --time 0 --size ${W}x${H} --bg $BG --headlight auto \
    -o "$TMP/animed_$2.png" >/dev/null 2>&1
}

for rel in "$@"; do
  f=$SHARED/corpus/$rel
  DIR=$(dirname "$f")
  kind=wrl
  zcat -f "$f" | head -c 20 | grep -q Inventor && kind=iv
  cam=$(cd "$DIR" && "${PY[@]}" "$ROOT/tests/coin_render_font.py" "$ROOT/tests/coin_camera.py" "$f" $W $H $kind 2>/dev/null)
  if [ -z "$cam" ]; then
    echo "$rel: Coin gave no camera"
    continue
  fi
  # The camera goes first in an Inventor file (after its header), last in
  # a VRML97 one (the first Viewpoint binds; the file has none, or Coin
  # would not have framed it). The copies live in $TMP (the corpus is
  # read-only), so a file with relative inlines or textures loses them
  # in animed's copy: use it on self-contained files.
  if [ $kind = iv ]; then
    { zcat -f "$f" | head -1; echo "$cam"; zcat -f "$f" | tail -n +2; } >"$TMP/cam.$kind"
  else
    { zcat -f "$f"; echo "$cam"; } >"$TMP/cam.$kind"
  fi
  perl -0pe 's/(string\s*)(\[[^]]*\]|"[^"]*")/$1""/g' "$TMP/cam.$kind" >"$TMP/notext.$kind"
  both "$f" own
  both "$TMP/cam.$kind" cam
  both "$TMP/notext.$kind" notext
  for r in coin animed; do
    /usr/bin/convert "$TMP/${r}_cam.png" "$TMP/${r}_notext.png" -compose difference -composite \
      -colorspace Gray -threshold 1% "$TMP/text_$r.png"
  done
  /usr/bin/convert "$TMP/text_coin.png" "$TMP/text_animed.png" -compose lighten -composite "$TMP/text.png"
  for r in coin animed; do
    /usr/bin/convert "$TMP/${r}_cam.png" \( "$TMP/text.png" -fill "$HEX" -opaque white -transparent black \) \
      -composite "$TMP/${r}_masked.png"
  done
  n=$(/usr/bin/convert "$TMP/text.png" -format '%[fx:mean*w*h]' info:)
  printf '%s\town=%s coin=%s masked=%s text_px=%s\n' "$rel" "$(iou "$TMP/coin_own.png" "$TMP/animed_own.png")" \
    "$(iou "$TMP/coin_cam.png" "$TMP/animed_cam.png")" "$(iou "$TMP/coin_masked.png" "$TMP/animed_masked.png")" "$n"
done
