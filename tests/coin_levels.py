#!/usr/bin/python3
"""How close animed's lighting levels are to Coin 4.0's (issue 19: "Inventor
lighting levels match within a few units").

usage: tests/coin_levels.py [FILE ...]     (run from anywhere; default files below)
env:   ANIMED (default target/release/animed), ANIMED_SHARED (default ../shared),
       W, H (default 320x240), OUT (default target/coin-levels)

Each file is drawn by Coin (through pivy, ../shared/tools/coin_render.py) and
by `animed render` at the same size, time 0, on the same background colour,
with the headlight rule of the coin corpus script. Compared are only the
pixels that are foreground in both pictures and whose four neighbours are
too (so edges, where the silhouettes and Coin's lines differ, do not count).
Prints per file: how many pixels, the mean R G B of each renderer over them,
animed's mean minus Coin's per channel (the level difference, in units of
255) and the mean absolute difference per pixel and channel.

Coin lights per vertex (Gouraud), animed per pixel: on curved surfaces the
per-pixel figure differs by the shape of the highlight, so the default files
are ones made mostly of large flat faces, where both are exact.

Exit 3 with a loud message when a tool is missing (not a pass).
"""
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SHARED = os.environ.get("ANIMED_SHARED", os.path.join(ROOT, "..", "shared"))
ANIMED = os.environ.get("ANIMED", os.path.join(ROOT, "target", "release", "animed"))
W = int(os.environ.get("W", "320"))
H = int(os.environ.get("H", "240"))
OUT = os.environ.get("OUT", os.path.join(ROOT, "target", "coin-levels"))
BG = (0.31, 0.07, 0.27)

# Lit Inventor and VRML 1.0 files made mostly of flat faces.
DEFAULT = [
    "inventor-debian/data/models/sgi/indigo.iv",
    "inventor-debian/data/models/machines/simpleMonitor.iv",
    "inventor-debian/data/models/household/manillaFolder.iv",
    "inventor-debian/data/models/household/outlet.iv",
    "inventor-debian/data/models/robots/cubeMan.iv",
    "inventor-debian/data/models/sgi/logo.iv",
    "castle-engine-demo-models/vrml_engine_doc_simple_examples/material_state.wrl",
    "castle-engine-demo-models/lights_materials/vrml_1/materials_parts_primitives.wrl",
]


def need(ok, what):
    if not ok:
        print("!" * 72)
        print("coin_levels: NOT RUN — missing: %s (not a pass)" % what)
        print("!" * 72)
        sys.exit(3)


def pixels(path):
    data = subprocess.run(
        ["/usr/bin/convert", path, "-alpha", "off", "-depth", "8", "rgb:-"],
        check=True,
        stdout=subprocess.PIPE,
    ).stdout
    if len(data) != W * H * 3:
        sys.exit("%s: expected %dx%d pixels" % (path, W, H))
    return data


def foreground(p):
    """Pixels that are not the background colour (within 3 %, as the
    corpus script's masks)."""
    bg = [round(c * 255) for c in BG]
    tol = 0.03 * 255
    return [
        max(abs(p[3 * i + k] - bg[k]) for k in range(3)) > tol for i in range(W * H)
    ]


def inner(mask):
    """Foreground pixels whose four neighbours are foreground too."""
    out = [False] * (W * H)
    for y in range(1, H - 1):
        for x in range(1, W - 1):
            i = y * W + x
            out[i] = mask[i] and mask[i - 1] and mask[i + 1] and mask[i - W] and mask[i + W]
    return out


def compare(coin, animed):
    a, b = pixels(coin), pixels(animed)
    fa, fb = inner(foreground(a)), inner(foreground(b))
    shared = [i for i in range(W * H) if fa[i] and fb[i]]
    n = len(shared)
    if n == 0:
        return None
    mean = lambda p, k: sum(p[3 * i + k] for i in shared) / n
    ma = [mean(a, k) for k in range(3)]
    mb = [mean(b, k) for k in range(3)]
    mad = [sum(abs(a[3 * i + k] - b[3 * i + k]) for i in shared) / n for k in range(3)]
    return n, ma, mb, mad


def main():
    need(os.path.isfile(os.path.join(SHARED, "tools", "coin_render.py")), "../shared/tools/coin_render.py")
    need(os.path.isfile("/usr/bin/convert"), "imagemagick")
    need(os.access(ANIMED, os.X_OK), "animed binary %s (set ANIMED)" % ANIMED)
    need(subprocess.run(["sh", "-c", "command -v Xvfb"], stdout=subprocess.DEVNULL).returncode == 0, "xvfb")
    files = sys.argv[1:] or DEFAULT
    os.makedirs(OUT, exist_ok=True)
    disp = ":%d" % (500 + os.getpid() % 400)
    xvfb = subprocess.Popen(
        ["Xvfb", disp, "-screen", "0", "1024x768x24", "+extension", "GLX", "+render", "-noreset"],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    try:
        import time

        time.sleep(2)
        env = dict(os.environ, DISPLAY=disp, LD_PRELOAD="/usr/lib/x86_64-linux-gnu/libGL.so.1")
        bg = ",".join("%g" % c for c in BG)
        print("file\tpixels\tcoin R G B\tanimed R G B\tanimed-coin R G B\tmean |diff| R G B")
        for rel in files:
            f = rel if os.path.isabs(rel) else os.path.join(SHARED, "corpus", rel)
            name = rel.replace("/", "_")
            coin = os.path.join(OUT, name + ".coin.png")
            anim = os.path.join(OUT, name + ".animed.png")
            for old in (coin, anim):
                if os.path.exists(old):
                    os.remove(old)
            subprocess.run(
                ["/usr/bin/python3", os.path.join(SHARED, "tools", "coin_render.py"), f, coin,
                 str(W), str(H), "--time", "0", "--headlight", "auto", "--bg", bg],
                cwd=os.path.dirname(f), env=env, stdout=subprocess.DEVNULL,
                stderr=subprocess.DEVNULL, timeout=120,
            )
            subprocess.run(
                [ANIMED, "render", f, "--time", "0", "--size", "%dx%d" % (W, H), "--bg", bg,
                 "--headlight", "auto", "-o", anim],
                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=120,
            )
            if not (os.path.isfile(coin) and os.path.isfile(anim)):
                print("%s\tno picture from %s" % (rel, "Coin" if not os.path.isfile(coin) else "animed"))
                continue
            r = compare(coin, anim)
            if r is None:
                print("%s\t0\tno shared foreground" % rel)
                continue
            n, ma, mb, mad = r
            fmt = lambda v: " ".join("%.1f" % x for x in v)
            print("%s\t%d\t%s\t%s\t%s\t%s" % (
                rel, n, fmt(ma), fmt(mb), fmt([y - x for x, y in zip(ma, mb)]), fmt(mad)))
            sys.stdout.flush()
    finally:
        xvfb.terminate()


if __name__ == "__main__":
    main()
