#!/usr/bin/env bash
# Window smoke test: runs `animed edit` in a real X window under Xvfb, drives
# it with xdotool (click, key, drag), grabs screenshots with ImageMagick and
# checks that each input visibly changed the picture. Also reports the idle
# CPU use of the editor.
#
# Usage: tests/window_smoke.sh ANIMED_BINARY OUT_DIR
# Coordinates (window pixels) come from the environment, computed by
# tests/editor_window.rs from the editor's own layout:
#   ROW_X ROW_Y    a row of the objects list
#   FIELD_X FIELD_Y  the selected object's translation x field
#   VIEW_X VIEW_Y  a point inside the viewport
#   SIDE_GEOM VIEW_GEOM   ImageMagick crop geometries (WxH+X+Y)
# Exit status: 0 ok, 1 a check failed, 77 a tool is missing.
set -uo pipefail

BIN=${1:?usage: window_smoke.sh ANIMED_BINARY OUT_DIR}
OUT=${2:?usage: window_smoke.sh ANIMED_BINARY OUT_DIR}
W=800
H=600
mkdir -p "$OUT"

for tool in Xvfb xdotool import compare convert; do
  if ! command -v "$tool" >/dev/null 2>&1; then
    echo "window_smoke: missing $tool (Debian: xvfb xdotool imagemagick)"
    exit 77
  fi
done

fail() { echo "window_smoke: FAIL: $*"; exit 1; }

# A free display number.
disp=""
for n in $(seq 91 140); do
  if [ ! -e "/tmp/.X$n-lock" ] && [ ! -e "/tmp/.X11-unix/X$n" ]; then disp=$n; break; fi
done
[ -n "$disp" ] || fail "no free X display number"
export DISPLAY=":$disp"

Xvfb "$DISPLAY" -screen 0 1024x768x24 -nolisten tcp >"$OUT/xvfb.log" 2>&1 &
xvfb_pid=$!
app_pid=""
cleanup() {
  [ -n "$app_pid" ] && kill "$app_pid" 2>/dev/null
  kill "$xvfb_pid" 2>/dev/null
  wait 2>/dev/null
}
trap cleanup EXIT

for _ in $(seq 1 50); do
  xdotool getdisplaygeometry >/dev/null 2>&1 && break
  sleep 0.1
done
xdotool getdisplaygeometry >/dev/null 2>&1 || fail "Xvfb did not start on $DISPLAY"

"$BIN" edit --size "${W}x${H}" >"$OUT/animed.log" 2>&1 &
app_pid=$!

wid=""
for _ in $(seq 1 100); do
  wid=$(xdotool search --name '^animed' 2>/dev/null | head -1)
  [ -n "$wid" ] && break
  kill -0 "$app_pid" 2>/dev/null || { cat "$OUT/animed.log"; fail "animed exited early"; }
  sleep 0.1
done
[ -n "$wid" ] || fail "no animed window appeared"
sleep 1

# Window origin on the root window (no window manager: usually 0,0).
eval "$(xdotool getwindowgeometry --shell "$wid")"
ox=$X
oy=$Y

shot() { import -window root -crop "${W}x${H}+${ox}+${oy}" +repage "$OUT/$1.png"; }
# Number of pixels that differ between two shots inside a crop geometry.
diff_px() {
  convert "$OUT/$1.png" -crop "$3" +repage "$OUT/.a.png"
  convert "$OUT/$2.png" -crop "$3" +repage "$OUT/.b.png"
  compare -metric AE -fuzz 2% "$OUT/.a.png" "$OUT/.b.png" null: 2>&1 | cut -d' ' -f1
}
std_dev() { convert "$OUT/$1.png" -crop "$2" +repage -format '%[fx:standard_deviation]' info:; }
at() { echo $((ox + $1)) $((oy + $2)); }

shot 0-start
sd=$(std_dev 0-start "$VIEW_GEOM")
echo "window_smoke: viewport std-dev $sd"
awk "BEGIN{exit !($sd > 0.02)}" || fail "the viewport is blank (std-dev $sd)"

# Idle CPU over 3 s (utime+stime ticks from /proc).
ticks() { awk '{print $14+$15}' "/proc/$app_pid/stat"; }
t0=$(ticks); sleep 3; t1=$(ticks)
hz=$(getconf CLK_TCK)
echo "window_smoke: idle CPU $(awk "BEGIN{printf \"%.1f\", ($t1-$t0)*100/($hz*3)}")%"

# Click: select an object in the list; the side panel changes.
# A human click lasts ~100 ms (minifb only reports button levels per poll).
xdotool mousemove $(at "$ROW_X" "$ROW_Y") mousedown 1 sleep 0.1 mouseup 1
sleep 0.5
shot 1-selected
n=$(diff_px 0-start 1-selected "$SIDE_GEOM")
echo "window_smoke: click changed $n side panel pixels"
[ "${n%.*}" -gt 50 ] || fail "clicking the objects list changed nothing"

# Key: G hides the grid; the viewport changes.
xdotool mousemove $(at "$VIEW_X" "$VIEW_Y")
sleep 0.2
xdotool key g
sleep 0.5
shot 2-grid-off
n=$(diff_px 1-selected 2-grid-off "$VIEW_GEOM")
echo "window_smoke: G changed $n viewport pixels"
[ "${n%.*}" -gt 200 ] || fail "G did not toggle the grid"

# Drag: middle-drag orbits the camera; the viewport changes.
xdotool mousemove $(at "$VIEW_X" "$VIEW_Y") mousedown 2
for i in 1 2 3 4 5 6 7 8; do
  xdotool mousemove $(at $((VIEW_X + i * 10)) $((VIEW_Y + i * 3)))
  sleep 0.05
done
xdotool mouseup 2
sleep 0.5
shot 3-orbited
n=$(diff_px 2-grid-off 3-orbited "$VIEW_GEOM")
echo "window_smoke: middle-drag changed $n viewport pixels"
[ "${n%.*}" -gt 200 ] || fail "middle-drag did not orbit"

# Typing into a field: click, type, Enter moves the object.
xdotool mousemove $(at "$FIELD_X" "$FIELD_Y") mousedown 1 sleep 0.1 mouseup 1
sleep 0.3
xdotool type --delay 50 "3"
xdotool key Return
sleep 0.5
shot 4-typed
n=$(diff_px 3-orbited 4-typed "$VIEW_GEOM")
echo "window_smoke: typing 3 + Enter changed $n viewport pixels"
[ "${n%.*}" -gt 200 ] || fail "typing into the translation field changed nothing"
title=$(xdotool getwindowname "$wid")
echo "window_smoke: title '$title'"
case "$title" in *"*") ;; *) fail "the title does not mark unsaved changes: '$title'" ;; esac

# Ctrl+Q now asks (unsaved change); D discards and quits.
xdotool key ctrl+q
sleep 0.5
shot 5-quit-question
kill -0 "$app_pid" 2>/dev/null || fail "Ctrl+Q quit without asking about the unsaved change"
xdotool key d
for _ in $(seq 1 50); do
  kill -0 "$app_pid" 2>/dev/null || break
  sleep 0.1
done
if kill -0 "$app_pid" 2>/dev/null; then fail "Ctrl+Q did not quit"; fi
wait "$app_pid"; rc=$?
app_pid=""
[ "$rc" = 0 ] || { cat "$OUT/animed.log"; fail "animed exited with $rc"; }
echo "window_smoke: ok (screenshots in $OUT)"
