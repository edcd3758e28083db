#!/usr/bin/python3
"""Print Coin 4.0's view-all camera for a scene file, as a node to add to it (issue 19).

usage: coin_camera.py in W H wrl|iv

Reads the file with Coin (pivy), puts a default SoPerspectiveCamera before it
and calls viewAll for a W x H viewport, as ../shared/tools/coin_render.py does
for a file without a camera. Prints that camera as a VRML97 Viewpoint (wrl) or
an Inventor PerspectiveCamera (iv), so that a copy of the file with the line
added is drawn by both renderers through Coin's framing: what is left between
the two pictures is then not view-all's doing (tests/coin_text_masked.sh).
Run it from the file's folder (inlines); no display is needed.
"""
import sys

from pivy import coin


def main():
    if len(sys.argv) != 5 or sys.argv[4] not in ("wrl", "iv"):
        sys.exit(__doc__)
    path, w, h, kind = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
    inp = coin.SoInput()
    if not inp.openFile(path):
        sys.exit("cannot open " + path)
    scene = coin.SoDB.readAll(inp)
    if scene is None:
        sys.exit("Coin cannot read " + path)
    scene.ref()
    root = coin.SoSeparator()
    root.ref()
    cam = coin.SoPerspectiveCamera()
    root.addChild(cam)
    root.addChild(scene)
    cam.viewAll(root, coin.SbViewportRegion(w, h))
    pos = cam.position.getValue().getValue()
    axis, angle = cam.orientation.getValue().getAxisAngle()
    rot = tuple(axis.getValue()) + (angle,)
    if kind == "wrl":
        print("Viewpoint { position %.7g %.7g %.7g orientation %.7g %.7g %.7g %.7g "
              "fieldOfView %.7g }" % (pos + rot + (cam.heightAngle.getValue(),)))
    else:
        print("PerspectiveCamera { position %.7g %.7g %.7g orientation %.7g %.7g %.7g %.7g "
              "heightAngle %.7g nearDistance %.7g farDistance %.7g }"
              % (pos + rot + (cam.heightAngle.getValue(), cam.nearDistance.getValue(),
                              cam.farDistance.getValue())))


main()
