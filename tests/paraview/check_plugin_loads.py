# pvpython started with PV_PLUGIN_PATH naming the plugin's folder loads it by
# itself: both filters are in paraview.simple without a LoadPlugin call.
import sys

import paraview.simple

missing = [name for name in ("TetSkinBindSurface", "TetSkinDeformSurface")
           if not hasattr(paraview.simple, name)]
if missing:
    print("FAIL: not loaded from PV_PLUGIN_PATH: " + ", ".join(missing))
    sys.exit(1)
print("the plugin's filters are loaded")
