# screenshot.py - the README's picture of the Phyllotaxis panel: a
# Blender with a window (under Xvfb is fine) imports a scene through the
# add-on, changes a setting in the panel, opens the sidebar on the
# Phyllotaxis tab, prints "screenshot: ready" and waits to be killed,
# while the display is captured from outside (Blender's own screenshot
# reads a black buffer under software OpenGL).  Needs a Blender whose
# sidebar tab a script may choose (Region.active_panel_category, from
# 4.2) and OpenGL (Mesa is enough).  Run first headless (-b), which
# installs the add-on and saves the preferences, then with a window:
#   blender -b --python screenshot.py -- ZIP SCENE
#   Xvfb :7 -screen 0 1600x1000x24 &
#   DISPLAY=:7 blender EMPTY.blend --python screenshot.py -- ZIP SCENE \
#       < /dev/null > log &
#   (wait for "screenshot: ready" in log) xwd -root -display :7 |
#       convert xwd:- OUT.png
# with PHYLLO_EXPORT naming the program if it is not on PATH.  A Debian
# root's Blender (tests/tools/blender-root.sh) has no OpenGL of its own:
# chroot ROOT apt-get install libgl1-mesa-dri libglx-mesa0 libegl-mesa0,
# and Xvfb -listen tcp, DISPLAY=127.0.0.1:7 (the chroot shares the
# network, not /tmp's X socket).  README's picture: the sid root's
# Blender 5.2 on the coneflower, cut to 1290 x 910, scaled to 1000 wide.
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from install import install_addon  # noqa: E402 (after the path)

zip_path, scene = sys.argv[sys.argv.index("--") + 1:][:2]

# Installed by the first run, whose preferences the second loads.
if not hasattr(bpy.types, "IMPORT_SCENE_OT_phyllotaxis"):
    install_addon(zip_path)
if bpy.app.background:
    # A first run, headless: the add-on installed and the preferences
    # saved, so that the window's run shows no first-start splash.
    bpy.context.preferences.view.show_splash = False
    bpy.ops.wm.save_userpref()
    raise SystemExit(0)
for ob in list(bpy.data.objects):
    bpy.data.objects.remove(ob)
bpy.ops.import_scene.phyllotaxis(filepath=scene)
st = bpy.context.scene.phyllo_structure.phyllo
# The ray florets' placeholders sized as the disc's, by the panel.
next(s for s in st.settings if s.path == "organs.0.scale").text = "1.6 * r"

window = bpy.context.window_manager.windows[0]
area = max((a for a in window.screen.areas if a.type == "VIEW_3D"),
           key=lambda a: a.width * a.height)
space = area.spaces.active
space.show_region_ui = True
space.shading.type = "SOLID"
space.overlay.show_floor = False
space.overlay.show_axis_x = space.overlay.show_axis_y = False
region = next(r for r in area.regions if r.type == "WINDOW")
# From above and a little aside, the whole head in view.
view = space.region_3d
view.view_perspective = "PERSP"
view.view_rotation = (0.93, 0.33, 0.05, 0.13)
with bpy.context.temp_override(window=window, area=area, region=region):
    bpy.ops.view3d.view_all()
tries = [0]


def shoot():
    # A few redraws first: the sidebar drawn (its tab can be chosen only
    # then), the instances made.
    tries[0] += 1
    if tries[0] == 2:
        sidebar = next(r for r in area.regions if r.type == "UI")
        sidebar.active_panel_category = "Phyllotaxis"
        area.tag_redraw()
    if tries[0] < 5:
        return 0.5
    if tries[0] == 5:
        print("screenshot: ready", flush=True)
    return 1.0


bpy.app.timers.register(shoot, first_interval=1.0)
