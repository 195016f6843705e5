# install.py - the import add-on installed and enabled from its zip, as
# an artist's Blender does it: an extension from 4.2 on, a legacy add-on
# before.  Imported by the test scripts that drive the add-on.
import bpy


def install_addon(zip_path):
    if bpy.app.version >= (4, 2, 0):
        bpy.ops.extensions.package_install_files(
            filepath=zip_path, repo="user_default", enable_on_install=True)
    else:
        bpy.ops.preferences.addon_install(filepath=zip_path)
        bpy.ops.preferences.addon_enable(module="phyllo_import")
