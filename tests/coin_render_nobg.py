#!/usr/bin/python3
"""Run ../shared/tools/coin_render.py on a scene with its VRML97 Backgrounds removed.

Used by tests/coin_corpus.sh (issue 19) for files with their own Background:
their silhouettes are compared with the Background gone on both sides (animed
with --bg, Coin through this script), so that a background Coin draws
differently (its Gouraud-shaded gradient sphere, the last Background bound
instead of the first, texture files it cannot load) cannot hide or fake a
geometry match. The Background itself is compared separately.

usage: coin_render_nobg.py TOOL in out.png [coin_render.py's other arguments]

The tool is run unchanged (runpy); only pivy's SoDB.readAll is wrapped so the
graph it returns has every SoVRMLBackground taken out of its parent. Prints
"removed N Background(s)" so the log says what was done.
"""
import runpy
import sys

from pivy import coin

_read_all = coin.SoDB.readAll


def _read_without_backgrounds(inp):
    scene = _read_all(inp)
    if scene is None:
        return scene
    # readAll hands the graph back unreferenced; the search action's paths
    # reference it and would delete it when they go away.
    scene.ref()
    ty = coin.SoType.fromName(coin.SbName("VRMLBackground"))
    if ty.isBad():
        scene.unrefNoDelete()
        return scene
    sa = coin.SoSearchAction()
    sa.setType(ty)
    sa.setInterest(coin.SoSearchAction.ALL)
    sa.setSearchingAll(True)
    sa.apply(scene)
    paths = sa.getPaths()
    # Collect first: removing a child re-indexes the paths still to visit.
    pairs = []
    for i in range(paths.getLength()):
        p = paths[i]
        if p.getLength() >= 2:
            pairs.append((p.getNodeFromTail(1), p.getTail()))
    removed = 0
    for parent, node in pairs:
        idx = parent.findChild(node)
        if idx >= 0:
            parent.removeChild(idx)
            removed += 1
    del pairs, paths, sa
    scene.unrefNoDelete()
    print("removed %d Background(s)" % removed)
    return scene


coin.SoDB.readAll = staticmethod(_read_without_backgrounds)

if __name__ == "__main__":
    tool = sys.argv[1]
    sys.argv = [tool] + sys.argv[2:]
    runpy.run_path(tool, run_name="__main__")
