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
from pivy import coin

from coin_graph_edit import edit_graph_on_read, run_tool


def remove_backgrounds(scene):
    ty = coin.SoType.fromName(coin.SbName("VRMLBackground"))
    if ty.isBad():
        return
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
    print("removed %d Background(s)" % removed)


edit_graph_on_read(remove_backgrounds)

if __name__ == "__main__":
    run_tool()
