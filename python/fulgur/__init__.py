"""fulgur: the sound of electric discharges, from Python (docs/python.md).

    import fulgur
    samples, rate = fulgur.render("examples/lightning_3km.json")   # as fulgur render
    nodes, report = fulgur.lightning(seed=3)                      # a bolt's tree
    with fulgur.Engine() as e:                                    # the real-time engine
        e.post(nodes, "lightning"); block = e.render(256)
"""
from ._convert import NODE_DTYPE, NODE_MAIN
from .aero import AeroTexture
from .engine import Engine, preset_names, preset_sound
from .fire import FireFeed
from .errors import FulgurError, SceneError
from .generators import charges, field_scene, grow, lightning
from .scene import Rendering, Scene, render, write_wav

__all__ = ["NODE_DTYPE", "NODE_MAIN", "AeroTexture", "Engine", "FireFeed", "FulgurError",
           "Rendering", "Scene", "SceneError", "charges", "field_scene", "grow", "lightning",
           "preset_names", "preset_sound", "render", "write_wav"]
__version__ = "0.1.0"
