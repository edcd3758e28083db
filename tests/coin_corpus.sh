#!/usr/bin/env bash
# How much of the corpus animed draws like Coin 4.0 does (issue 19, item 5).
#
# For every ../shared/corpus file that Coin reads and draws something for
# (MANIFEST.tsv: coin_reads = yes, coin_tris_lines_points not 0/0/0), render
# it with Coin (through pivy, ../shared/tools/coin_render.py) and with
# `animed render` at the same size, time 0, the same background colour and
# headlight rule, and compare silhouettes: the non-background pixels of each
# picture, intersection over union. A file matches at IoU >= 0.95 (files
# with their own Background: see one() below). Prints
# the share that match and writes every file's figures to
# $OUT/report.tsv (default target/coin-corpus/), worst first, with the
# pairs side by side as $OUT/pairs/NAME.png for a person to look at.
#
#   bash tests/coin_corpus.sh            # every file (about 240; minutes)
#   EVERY=5 bash tests/coin_corpus.sh    # every 5th file (what CI runs)
#   ANIMED=target/release/animed bash tests/coin_corpus.sh
#   FILES="axis.iv vrml_1/points.wrl" bash tests/coin_corpus.sh
#                                        # only the files whose corpus path
#                                        # contains one of these words
#
# Coin draws every text through tests/coin_render_font.py, which hands it
# the face animed draws that text in (Liberation Serif/Sans/Mono, from
# Debian's fonts-liberation2): left alone, Coin 4.0 draws VRML97 Text and
# unnamed Inventor fonts in its built-in font and misreads Inventor's
# PostScript names (that script's header gives Coin's source lines), so the
# silhouettes would compare font choices rather than text layout.
#
# Lighting differs on purpose (Coin lights per vertex, animed per pixel), so
# colours are not compared here; silhouettes show geometry, camera, framing
# and what each reader skips. Exit 0 after a run (the share is a figure to
# quote, not a gate), 3 when a tool is missing (said loudly: not a pass).
set -uo pipefail
cd "$(dirname "$0")/.."
ROOT=$(pwd)
OUT=${OUT:-$ROOT/target/coin-corpus}
SHARED=${ANIMED_SHARED:-$ROOT/../shared}
EVERY=${EVERY:-1}
FILES=${FILES:-}
W=160
H=120
BG=0.31,0.07,0.27

missing=()
[ -f "$SHARED/corpus/MANIFEST.tsv" ] || missing+=("$SHARED/corpus (set ANIMED_SHARED)")
[ -f "$SHARED/tools/coin_render.py" ] || missing+=("$SHARED/tools/coin_render.py")
[ -x /usr/bin/convert ] || missing+=(imagemagick)
command -v Xvfb >/dev/null 2>&1 || missing+=(xvfb)
/usr/bin/python3 -c 'import pivy, PySide2, OpenGL' >/dev/null 2>&1 \
  || missing+=("python3-pivy/python3-pyside2.qtgui/python3-opengl")
if [ ${#missing[@]} -gt 0 ]; then
  echo "!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!"
  echo "coin_corpus: NOT RUN — missing: ${missing[*]}"
  echo "This is not a pass. See ../shared/REFERENCE-RENDERERS.md."
  echo "!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!"
  exit 3
fi

# Coin draws text in the faces animed embeds only when fontconfig maps the
# names tests/coin_render_font.py gives it to them (Debian's
# fonts-liberation2, which tests/run-all.sh installs); without them every
# text file is compared against another font. Said loudly, and in the
# summary, but the run goes on: the other files do not need them.
FONT_WARN=""
for pair in "Times New Roman=Liberation Serif" "Arial=Liberation Sans" "Courier New=Liberation Mono"; do
  got=$(fc-match -f '%{family[0]}' "${pair%%=*}" 2>/dev/null)
  [ "$got" = "${pair#*=}" ] || FONT_WARN="$FONT_WARN '${pair%%=*}' is '${got:-?}', not '${pair#*=}';"
done
if [ -n "$FONT_WARN" ]; then
  FONT_WARN="fonts-liberation2 missing:$FONT_WARN text files are compared against another font than animed's"
  echo "!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!"
  echo "coin_corpus: $FONT_WARN"
  echo "!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!!"
fi

if [ -z "${ANIMED:-}" ]; then
  cargo build --quiet || exit 1
  ANIMED=${CARGO_TARGET_DIR:-$ROOT/target}/debug/animed
fi
export ANIMED SHARED OUT W H BG ROOT
rm -rf "$OUT"
mkdir -p "$OUT/pairs" "$OUT/tmp"

DISP=:$((90 + RANDOM % 400))
Xvfb "$DISP" -screen 0 1024x768x24 +extension GLX +render -noreset >/dev/null 2>&1 &
XPID=$!
trap 'kill $XPID 2>/dev/null' EXIT
export DISPLAY=$DISP
sleep 2

# The files Coin draws something for, every $EVERY-th of them; with
# FILES, only those whose path contains one of its words.
awk -F'\t' -v every="$EVERY" -v files="$FILES" '
  BEGIN { nw = split(files, words, /[ \n]+/) }
  function wanted(path,   i) {
    if (files == "") return 1
    for (i = 1; i <= nw; i++) if (words[i] != "" && index(path, words[i])) return 1
    return 0
  }
  NR > 1 && $7 == "yes" && $6 != "" && $6 != "0/0/0" && wanted($1) { if (n++ % every == 0) print $1 }' \
  "$SHARED/corpus/MANIFEST.tsv" >"$OUT/files.txt"
if [ ! -s "$OUT/files.txt" ]; then
  echo "coin_corpus: no corpus file Coin draws matches FILES='$FILES'"
  exit 2
fi

# Why a file's own Background cannot be compared with Coin's, or "": each
# reason is a documented Coin limit, found in the file's text, printed in the
# report next to the figures it excuses.
coin_bg_limit() {
  local f=$1 why=()
  zcat -f "$f" 2>/dev/null | grep -qE '(front|back|left|right|top|bottom)Url[[:space:]]*\[?[[:space:]]*"[^"]' \
    && why+=("draws a Background panorama face white when its texture does not load (this Coin loads no texture files, REFERENCE-RENDERERS.md; animed shows the sky and ground colours where no panorama image loaded)")
  [ "$(zcat -f "$f" 2>/dev/null | grep -cE '(^|[^A-Za-z0-9_])Background[[:space:]]*\{')" -gt 1 ] \
    && why+=("binds the last Background (VRML97 4.6.10 binds the first)")
  zcat -f "$f" 2>/dev/null | grep -qE '(sky|ground)Angle[[:space:]]*\[?[[:space:]]*[-+.0-9]' \
    && why+=("Gouraud-shades its gradient sphere on a coarse tessellation (VRML97 6.5 interpolates by angle, as animed and view3dscene draw it)")
  local IFS=';'
  [ ${#why[@]} -gt 0 ] && echo "Coin limit: ${why[*]}"
}
export -f coin_bg_limit

# Both pictures to black (background) and white (everything else): first
# everything that is not the --bg colour turns white (so black objects
# count), then the --bg colour turns black.
masks() {
  local hex p
  hex=$(awk -F, '{printf "#%02x%02x%02x", $1*255+0.5, $2*255+0.5, $3*255+0.5}' <<<"$BG")
  for p in "$@"; do
    /usr/bin/convert "$p" -alpha off -fuzz 3% -fill white +opaque "$hex" -fill black -opaque "$hex" \
      -colorspace Gray -threshold 50% "$p.mask.png"
  done
}
export -f masks

# Prints the silhouette IoU of two pictures rendered with --bg.
iou_of() {
  local inter union
  masks "$1" "$2"
  inter=$(/usr/bin/convert "$1.mask.png" "$2.mask.png" -compose multiply -composite -format '%[fx:mean*w*h]' info:)
  union=$(/usr/bin/convert "$1.mask.png" "$2.mask.png" -compose lighten -composite -format '%[fx:mean*w*h]' info:)
  awk -v i="$inter" -v u="$union" 'BEGIN { if (u == 0) print "nan"; else printf "%.4f", i / u }'
}
export -f iou_of

# Coin's render of $1 into $2 with coin_render.py's arguments after them,
# always through tests/coin_render_font.py (each text in the face animed
# draws it in; that script's header says which Coin deviations this
# undoes), with NOBG=1 also through tests/coin_render_nobg.py (Backgrounds
# removed).
coin() {
  local f=$1 out=$2 tool=("$ROOT/tests/coin_render_font.py")
  shift 2
  [ "${NOBG:-0}" = 1 ] && tool+=("$ROOT/tests/coin_render_nobg.py")
  tool+=("$SHARED/tools/coin_render.py")
  (cd "$(dirname "$f")" && timeout 60 env LD_PRELOAD=/usr/lib/x86_64-linux-gnu/libGL.so.1 \
    /usr/bin/python3 "${tool[@]}" "$f" "$out" $W $H --time 0 --headlight auto "$@")
}
export -f coin

# One file: prints "score<TAB>path<TAB>note".
#
# A file without a Background of its own is drawn on the --bg colour by both
# and scored by silhouette IoU.
#
# A file with its own Background (Coin draws it whatever --bg says) is drawn
# twice by each: without the Background (Coin through coin_render_nobg.py,
# animed with --bg, which overrides it) for the silhouette IoU, and with it
# for the Background itself, compared pixel by pixel where both pictures
# show background (tests/coin_bg_compare.py: within 12 %, allowing Coin's
# Gouraud gradient bands to sit up to H/16 pixels away). Its score is the
# smaller of the two, or the IoU alone when the Background differs for a
# documented Coin limit (coin_bg_limit, printed in the note). The note keeps
# the old score (whole pictures within 12 %, until session 8) beside the new
# figures: "bg iou=… bg_px=strict/shifted(n) old=…".
one() {
  local rel=$1 f name tmp a b iou note="" own_bg=0 bgargs=(--bg "$BG")
  f=$SHARED/corpus/$rel
  # zgrep: gzipped files (.wrl.gz) hold Backgrounds too.
  zgrep -q 'Background' "$f" 2>/dev/null && own_bg=1
  name=$(tr '/ ' '__' <<<"$rel")
  tmp=$OUT/tmp/$name
  a=$tmp.coin.png
  b=$tmp.animed.png
  NOBG=$own_bg coin "$f" "$a" "${bgargs[@]}" >"$tmp.coin.log" 2>&1
  timeout 60 "$ANIMED" render "$f" --time 0 --size ${W}x${H} "${bgargs[@]}" \
    --headlight auto -o "$b" >"$tmp.animed.log" 2>&1 || note="animed failed: $(tail -1 "$tmp.animed.log")"
  if [ ! -s "$a" ]; then
    printf 'nan\t%s\tCoin wrote no picture\n' "$rel"
    return
  fi
  if [ ! -s "$b" ]; then
    printf '0\t%s\t%s\n' "$rel" "${note:-animed wrote no picture}"
    return
  fi
  iou=$(iou_of "$a" "$b")
  if [ "$iou" = nan ]; then
    printf 'nan\t%s\tCoin drew nothing at time 0\n' "$rel"
    return
  fi
  if [ $own_bg = 0 ]; then
    /usr/bin/convert "$a" "$b" +append "$OUT/pairs/$name.png"
    printf '%s\t%s\t%s\n' "$iou" "$rel" "$note"
    return
  fi
  # The file's own Background, on both sides.
  local ab=$tmp.coin-bg.png bb=$tmp.animed-bg.png old cmp strict shifted n limit score
  coin "$f" "$ab" >"$tmp.coin-bg.log" 2>&1
  timeout 60 "$ANIMED" render "$f" --time 0 --size ${W}x${H} --headlight auto -o "$bb" \
    >"$tmp.animed-bg.log" 2>&1
  if [ ! -s "$ab" ] || [ ! -s "$bb" ]; then
    printf '0\t%s\tbg: no picture with the Background (see %s.*-bg.log)\n' "$rel" "$tmp"
    return
  fi
  /usr/bin/convert \( "$ab" "$bb" +append \) \( "$a" "$b" +append \) -append "$OUT/pairs/$name.png"
  old=$(/usr/bin/compare -metric AE -fuzz 12% "$ab" "$bb" null: 2>&1 | sed -E 's/^([0-9.e+]+).*/\1/')
  old=$(awk -v d="$old" -v n=$((W * H)) 'BEGIN { printf "%.4f", 1 - d / n }')
  cmp=$(/usr/bin/python3 "$ROOT/tests/coin_bg_compare.py" "$ab" "$bb" "$a.mask.png" "$b.mask.png" $W $H) \
    || cmp="nan nan 0"
  read -r strict shifted n <<<"$cmp"
  limit=$(coin_bg_limit "$f")
  note="bg iou=$iou bg_px=$strict/$shifted($n) old=$old"
  if [ "$n" = 0 ]; then
    score=$iou
    note="$note; no background pixel to compare"
  elif awk -v s="$shifted" 'BEGIN { exit !(s >= 0.95) }'; then
    score=$iou
  elif [ -n "$limit" ]; then
    score=$iou
    note="$note; Background not counted: $limit"
  else
    score=$(awk -v i="$iou" -v s="$shifted" 'BEGIN { printf "%.4f", (s < i ? s : i) }')
    note="$note; Background differs"
  fi
  printf '%s\t%s\t%s\n' "$score" "$rel" "$note"
}
export -f one

xargs -a "$OUT/files.txt" -d '\n' -P 2 -I{} bash -c 'one "$@"' _ {} >"$OUT/raw.tsv"
sort -g "$OUT/raw.tsv" >"$OUT/report.tsv"

# The share over every file Coin drew something for; then, as a second
# figure, without the files tests/coin_known.tsv lists as drawn wrong by
# Coin itself (each with its reason, printed).
awk -F'\t' '
  FNR == NR { if ($0 !~ /^#/ && NF >= 2) known[$1] = $2; next }
  $1 == "nan" { skipped++; next }
  { n++; if ($1 >= 0.95) ok++; else if ($2 in known) { kn++; kl = kl sprintf("  %s (%s): %s\n", $2, $1, known[$2]) } }
  ($2 in known) && $1 != "nan" && $1 >= 0.95 { km = km sprintf("  %s now matches (%s): take it out of tests/coin_known.tsv\n", $2, $1) }
  END {
    printf "coin_corpus: %d of %d files match Coin (silhouette IoU >= 0.95): %.1f%%", ok, n, n ? 100 * ok / n : 0
    if (skipped) printf " (%d skipped: Coin drew nothing)", skipped
    printf "\n"
    if (kn) {
      printf "coin_corpus: without the %d failing files Coin draws wrong (tests/coin_known.tsv): %d of %d: %.1f%%\n", kn, ok, n - kn, 100 * ok / (n - kn)
      printf "%s", kl
    }
    printf "%s", km
  }' "$ROOT/tests/coin_known.tsv" "$OUT/report.tsv" | tee "$OUT/summary.txt"
[ -z "$FONT_WARN" ] || echo "coin_corpus: NOT comparable for text: $FONT_WARN" | tee -a "$OUT/summary.txt"
echo "coin_corpus: worst files (IoU, path, note) — all in $OUT/report.tsv, pictures in $OUT/pairs/:"
if [ -n "$FILES" ]; then
  cat "$OUT/report.tsv"
else
  awk -F'\t' '$1 != "nan" && $1 < 0.95' "$OUT/report.tsv" | head -15
fi
