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

# Up to 30 s: on a loaded 2-core machine Xvfb has taken more than 5 s.
for _ in $(seq 1 300); do
  xdotool getdisplaygeometry >/dev/null 2>&1 && break
  sleep 0.1
done
xdotool getdisplaygeometry >/dev/null 2>&1 || fail "Xvfb did not start on $DISPLAY within 30 s"

# Recovery copies of the untitled demo go here, not to the real home.
export XDG_STATE_HOME="$OUT/state"
rm -rf "$XDG_STATE_HOME"
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
# A click is held 300 ms: minifb only reports button levels per poll, and
# on a loaded machine a frame can take longer than a human 100 ms click.
xdotool mousemove $(at "$ROW_X" "$ROW_Y") mousedown 1 sleep 0.3 mouseup 1
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
xdotool mousemove $(at "$FIELD_X" "$FIELD_Y") mousedown 1 sleep 0.3 mouseup 1
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

# Idle CPU with unsaved changes (the autosave clock ticks once a second).
t0=$(ticks); sleep 3; t1=$(ticks)
echo "window_smoke: idle CPU with unsaved changes $(awk "BEGIN{printf \"%.1f\", ($t1-$t0)*100/($hz*3)}")%"

# The window's close button (WM_DELETE_WINDOW, as a window manager sends
# it): with unsaved changes the editor asks in a reopened window.
wm_close() {
  python3 - "$1" <<'PY'
import ctypes, sys
x = ctypes.cdll.LoadLibrary("libX11.so.6")
x.XOpenDisplay.restype = ctypes.c_void_p
x.XOpenDisplay.argtypes = [ctypes.c_char_p]
x.XInternAtom.restype = ctypes.c_ulong
x.XInternAtom.argtypes = [ctypes.c_void_p, ctypes.c_char_p, ctypes.c_int]
class ClientMessage(ctypes.Structure):
    _fields_ = [("type", ctypes.c_int), ("serial", ctypes.c_ulong),
                ("send_event", ctypes.c_int), ("display", ctypes.c_void_p),
                ("window", ctypes.c_ulong), ("message_type", ctypes.c_ulong),
                ("format", ctypes.c_int), ("l", ctypes.c_long * 5)]
class XEvent(ctypes.Union):
    _fields_ = [("xclient", ClientMessage), ("pad", ctypes.c_long * 24)]
x.XFlush.argtypes = [ctypes.c_void_p]
x.XCloseDisplay.argtypes = [ctypes.c_void_p]
x.XSendEvent.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.c_int,
                         ctypes.c_long, ctypes.POINTER(XEvent)]
d = x.XOpenDisplay(None)
if not d:
    sys.exit("cannot open the display")
w = int(sys.argv[1])
ev = XEvent()
ev.xclient.type = 33  # ClientMessage
ev.xclient.window = w
ev.xclient.message_type = x.XInternAtom(d, b"WM_PROTOCOLS", 0)
ev.xclient.format = 32
ev.xclient.l[0] = x.XInternAtom(d, b"WM_DELETE_WINDOW", 0)
x.XSendEvent(d, w, 0, 0, ctypes.byref(ev))
x.XFlush(d)
x.XCloseDisplay(d)
PY
}
# Waits (up to 10 s) for an animed window other than $1 (the closed one).
find_window() {
  local old=${1:-}
  wid=""
  for _ in $(seq 1 100); do
    wid=$(xdotool search --name '^animed' 2>/dev/null | grep -vx "$old" | head -1)
    [ -n "$wid" ] && break
    kill -0 "$app_pid" 2>/dev/null || break
    sleep 0.1
  done
  [ -n "$wid" ] || fail "no animed window"
  eval "$(xdotool getwindowgeometry --shell "$wid")"
  ox=$X
  oy=$Y
}
if command -v python3 >/dev/null 2>&1; then
  wm_close "$wid" || fail "could not send WM_DELETE_WINDOW"
  find_window "$wid"
  kill -0 "$app_pid" 2>/dev/null || { cat "$OUT/animed.log"; fail "closing with unsaved changes did not ask"; }
  sleep 1
  shot 5-close-question
  # Esc: back to editing; the change is still there.
  xdotool key Escape
  sleep 0.3
  title=$(xdotool getwindowname "$wid")
  case "$title" in *"*") ;; *) fail "the reopened window lost the unsaved mark: '$title'" ;; esac
  echo "window_smoke: close with unsaved changes asked first (reopened window $wid)"
else
  echo "window_smoke: *** close-button check SKIPPED: python3 missing ***"
fi

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
ls "$XDG_STATE_HOME"/animed/*.animed-recovery.wrl >/dev/null 2>&1 \
  && fail "a discarded session left a recovery copy in $XDG_STATE_HOME/animed"

# Closing twice (the second time while asked) ends the program and keeps
# the unsaved work in the recovery copy.
if command -v python3 >/dev/null 2>&1; then
  "$BIN" edit --size "${W}x${H}" >"$OUT/animed2.log" 2>&1 &
  app_pid=$!
  find_window
  sleep 1
  # A fresh editor under a loaded machine may not take the first click yet
  # (seen at load 13): try the edit up to three times.
  for _attempt in 1 2 3; do
    xdotool mousemove $(at "$ROW_X" "$ROW_Y") mousedown 1 sleep 0.3 mouseup 1
    sleep 0.3
    xdotool mousemove $(at "$FIELD_X" "$FIELD_Y") mousedown 1 sleep 0.3 mouseup 1
    sleep 0.3
    xdotool type --delay 50 "5"
    xdotool key Return
    for _ in $(seq 1 50); do
      case "$(xdotool getwindowname "$wid")" in *"*") break 2 ;; esac
      sleep 0.1
    done
  done
  case "$(xdotool getwindowname "$wid")" in *"*") ;; *) fail "second session: typing made no unsaved change" ;; esac
  wm_close "$wid"
  find_window "$wid"
  kill -0 "$app_pid" 2>/dev/null || fail "the first close did not ask"
  sleep 1
  wm_close "$wid"
  for _ in $(seq 1 100); do
    kill -0 "$app_pid" 2>/dev/null || break
    sleep 0.1
  done
  kill -0 "$app_pid" 2>/dev/null && fail "the second close did not end the program"
  copy="$XDG_STATE_HOME/animed/untitled-$app_pid.animed-recovery.wrl"
  wait "$app_pid"
  app_pid=""
  [ -f "$copy" ] || { cat "$OUT/animed2.log"; fail "no recovery copy $copy after closing"; }
  grep -q "$copy" "$OUT/animed2.log" || fail "the program did not say where the copy is"
  grep -q "animed-keys 1" "$copy" || fail "the recovery copy has no key note"
  echo "window_smoke: closed twice: $(cat "$OUT/animed2.log")"
fi
echo "window_smoke: ok (screenshots in $OUT)"
