"""What the coin_render_*.py wrappers share: edit the scene graph pivy's
SoDB.readAll returns before the wrapped Coin tool sees it, then run that
tool (runpy) with the remaining arguments. Wrappers compose: each one's
edit runs on the graph the one before it returned.
"""
import runpy
import sys

from pivy import coin


def edit_graph_on_read(edit):
    """From now on, SoDB.readAll calls `edit(scene)` on each graph it reads."""
    read_all = coin.SoDB.readAll

    def read_and_edit(inp):
        scene = read_all(inp)
        if scene is None:
            return scene
        # readAll hands the graph back unreferenced; a search action's paths
        # reference it and would delete it when they go away.
        scene.ref()
        edit(scene)
        scene.unrefNoDelete()
        return scene

    coin.SoDB.readAll = staticmethod(read_and_edit)


def run_tool():
    """Runs argv[1] as a script with argv[2:] as its arguments."""
    tool = sys.argv[1]
    sys.argv = [tool] + sys.argv[2:]
    runpy.run_path(tool, run_name="__main__")
