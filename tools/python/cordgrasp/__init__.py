"""cordgrasp: the cord-driven grasp planner (Li et al., T-RO 2015), Bullet physics, OSMesa.

    import cordgrasp
    mug = cordgrasp.load_mesh("mug")
    plan = cordgrasp.plan(mug, cordgrasp.load_hand(), grasps=2, seed=3)

Reference: docs/python.md.
"""
from ._cordgrasp import *  # noqa: F401,F403
from ._cordgrasp import __doc__ as _doc  # noqa: F401

__version__ = version()  # noqa: F405
