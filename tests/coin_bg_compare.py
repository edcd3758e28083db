#!/usr/bin/python3
"""Compare the Background pixels of a Coin render and an animed render (issue 19).

usage: coin_bg_compare.py coin.png animed.png coin_mask.png animed_mask.png W H

coin.png / animed.png are the renders WITH the file's own Background; the
masks (white = object) come from the renders WITHOUT it (tests/coin_corpus.sh).
Only pixels that are background in both masks are compared. Prints

    strict shifted count

strict:  share of those pixels whose colours differ by at most 12 % (root mean
         square over R, G, B of the difference, as a share of 255: the fuzz the
         script has always used for Backgrounds).
shifted: the same, except that a pixel also matches when a background pixel
         of the other picture at most SHIFT rows above or below, or SHIFT
         columns left or right, is within 12 % — checked both ways (Coin
         against animed and animed against Coin), the smaller share kept.
         Why: Coin draws the sky/ground gradient sphere Gouraud-shaded on a
         coarse tessellation, animed per pixel from the view ray (as VRML97
         6.5 and view3dscene do): the same colours, Coin's bands displaced
         (~15 px at 320x240 on openvrml pixtex1.wrl). SHIFT = H/16 (7 rows
         at 160x120) passes such small displacements; a wrong colour, a
         missing gradient or a Background not drawn at all still fails.
         Where Coin's gradient differs more (freewrl 23.wrl: at the view's
         top edge Coin shows the colour of the 1.07 rad ring, animed and the
         spec's angle interpolation a quarter of the way on to the next),
         tests/coin_corpus.sh names the Coin limit instead of passing it.
count:   how many pixels were compared (0: geometry covers the picture).

Reads the PNGs through ImageMagick's convert (already required by the
script); pure Python, no numpy.
"""
import subprocess
import sys

FUZZ = 0.12


def load(path, w, h, fmt):
    data = subprocess.run(
        ["/usr/bin/convert", path, "-alpha", "off", "-depth", "8", fmt + ":-"],
        check=True,
        stdout=subprocess.PIPE,
    ).stdout
    per = 3 if fmt == "rgb" else 1
    if len(data) != w * h * per:
        sys.exit("%s: expected %dx%d pixels" % (path, w, h))
    return data


def close(a, i, b, j):
    dr = a[3 * i] - b[3 * j]
    dg = a[3 * i + 1] - b[3 * j + 1]
    db = a[3 * i + 2] - b[3 * j + 2]
    return (dr * dr + dg * dg + db * db) / 3.0 <= (FUZZ * 255.0) ** 2


def found_near(a, i, b, bg_b, x, y, w, h, shift):
    """Is a background pixel of b within `shift` rows or columns of (x, y)
    close in colour to pixel i of a?"""
    for d in range(-shift, shift + 1):
        yy = y + d
        if 0 <= yy < h:
            j = yy * w + x
            if bg_b[j] and close(a, i, b, j):
                return True
        xx = x + d
        if 0 <= xx < w:
            j = y * w + xx
            if bg_b[j] and close(a, i, b, j):
                return True
    return False


def main():
    coin, animed, cmask, amask = sys.argv[1:5]
    w, h = int(sys.argv[5]), int(sys.argv[6])
    shift = max(1, h // 16)
    a = load(coin, w, h, "rgb")
    b = load(animed, w, h, "rgb")
    ma = load(cmask, w, h, "gray")
    mb = load(amask, w, h, "gray")
    bg_a = [v < 128 for v in ma]
    bg_b = [v < 128 for v in mb]
    both = [i for i in range(w * h) if bg_a[i] and bg_b[i]]
    if not both:
        print("nan nan 0")
        return
    strict = sum(1 for i in both if close(a, i, b, i))
    ab = ba = 0
    for i in both:
        x, y = i % w, i // w
        if close(a, i, b, i):
            ab += 1
            ba += 1
            continue
        ab += found_near(a, i, b, bg_b, x, y, w, h, shift)
        ba += found_near(b, i, a, bg_a, x, y, w, h, shift)
    n = len(both)
    print("%.4f %.4f %d" % (strict / n, min(ab, ba) / n, n))


main()
