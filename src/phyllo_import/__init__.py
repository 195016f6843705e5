# phyllo_import - phyllo-export inside Blender.  File > Import >
# Phyllotaxis scene (.cfg) runs the installed phyllo-export on a scene
# file and then the script it writes, which builds (or rebuilds) the
# scene's collection from the artist's own organ objects.  The
# Phyllotaxis panel in the 3D viewport's sidebar then lists the scene's
# settings (phyllo-export --settings): changing one runs phyllo-export
# again with it (--set) and rebuilds the structure in place, and "Save
# to scene file" writes the changes into the .cfg (--cfg), its comments
# kept.  A bad scene or value is reported with phyllo-export's own
# message and changes nothing.  phyllo-export is run with its arguments
# as a list, never through a shell.
#
# Blender 3.x reads bl_info below; 4.2 and later read
# blender_manifest.toml beside this file (an extension).
import json
import os
import runpy
import subprocess
import tempfile
import time

import bpy
from bpy.props import (BoolProperty, CollectionProperty, EnumProperty,
                       FloatProperty, IntProperty, PointerProperty,
                       StringProperty)
from bpy_extras.io_utils import ImportHelper

bl_info = {
    "name": "Phyllotaxis scene (phyllo-export)",
    "author": "phyllo-export",
    "version": (0, 2, 0),
    "blender": (3, 4, 0),
    "location": "File > Import > Phyllotaxis scene (.cfg); "
                "View3D > Sidebar > Phyllotaxis",
    "description": "Spiral phyllotaxis from a phyllo-export scene file",
    "category": "Import-Export",
}

# The add-on's package name: "phyllo_import" for 3.x, and
# "bl_ext.REPO.phyllo_import" when installed as an extension.
PACKAGE = __package__ or __name__
TAG = "phyllo_export"       # what the generated script marks
# A change rebuilds at once while a run takes at most this long; after
# a slower one the panel waits for Update.
LIVE_SECONDS = 0.5


class PhylloPreferences(bpy.types.AddonPreferences):
    bl_idname = PACKAGE

    program: StringProperty(
        name="phyllo-export",
        description="The phyllo-export program, where the add-on carries "
        "none of its own: a full path, or a name looked up on PATH",
        default="phyllo-export",
        subtype="FILE_PATH")

    def draw(self, context):
        self.layout.prop(self, "program")


def program(context):
    """The add-on's own program (bin/, in the zips for one system), else
    the configured one (PHYLLO_EXPORT overrides it): a full path, or the
    first on PATH's full folders -- never one in the current or the
    scene's folder (shutil.which and Windows look there first)."""
    ext = ".exe" if os.name == "nt" else ""
    own = os.path.join(os.path.dirname(os.path.abspath(__file__)), "bin",
                       "phyllo-export" + ext)
    if os.path.isfile(own):
        try:
            if not os.access(own, os.X_OK):
                os.chmod(own, 0o755)    # a zip's files lose their modes
        except OSError:
            pass
        return own
    prefs = context.preferences.addons.get(PACKAGE)
    name = os.environ.get("PHYLLO_EXPORT") or (
        prefs.preferences.program if prefs else "phyllo-export")
    if os.path.dirname(name):
        return name if os.path.isabs(name) else None
    found = (os.path.join(d, n) for d in os.environ.get("PATH", "").split(
        os.pathsep) if os.path.isabs(d) for n in (name, name + ext))
    return next((p for p in found if os.path.isfile(p) and
                 os.access(p, os.X_OK)), None)


def run_program(context, args):
    """Run phyllo-export with args (a list: no shell).  Returns its
    output, or raises RuntimeError with its own one-line message."""
    exe = program(context)
    if exe is None:
        raise RuntimeError("phyllo-export: program not found: install it, "
                           "or give its full path in the add-on's "
                           "preferences")
    try:
        run = subprocess.run([exe] + args, stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, encoding="utf-8",
                             errors="replace", timeout=600,
                             creationflags=getattr(
                                 subprocess, "CREATE_NO_WINDOW", 0))
    except (OSError, subprocess.SubprocessError) as e:
        raise RuntimeError("phyllo-export: cannot run %s: %s" % (exe, e))
    if run.returncode != 0:
        # Our message names the file and line, or the --set; as it is.
        lines = [l for l in run.stderr.splitlines()
                 if not l.startswith(("phyllo-export: warning", "\r"))]
        raise RuntimeError(lines[0] if lines else
                           "phyllo-export failed (exit %d)" % run.returncode)
    return run.stdout


# --- A structure's settings, as --settings gives them. ---

_filling = False    # set while the panel's fields are filled: no rebuild
_choices = {}       # enum items by setting: Blender needs them kept
NONE = "(none)"     # the menu item of a word not given (none is a word)


def quoted(text):
    """Whether text is one string literal of the scene file's syntax."""
    return len(text) >= 2 and text[0] == '"' and text[-1] == '"' and \
        '"' not in text[1:-1].replace('\\"', "")


def unquote(text):
    return text[1:-1].replace('\\"', '"').replace("\\\\", "\\")


def quote(text):
    return '"%s"' % text.replace("\\", "\\\\").replace('"', '\\"')


def number_text(x):
    """A float field's value in scene syntax: seven digits, which is what
    Blender's single-precision fields hold."""
    return "%.7g" % x


def choice_items(self, context):
    # A setting without a value (shape, where a profile is given) offers
    # "none" too, which sets nothing.
    key = (self.choices, not self.written)
    items = _choices.get(key)
    if items is None:
        items = _choices[key] = [(NONE, NONE, "")] * (not self.written) + \
            [(w, w, "") for w in self.choices.split("\n") if w]
    return items


def setting_changed(self, context):
    if _filling:
        return
    top = self.id_data
    st = top.phyllo
    st.stale = True
    st.last = self.path
    if st.live and st.seconds <= LIVE_SECONDS:
        try:
            rebuild(context, top)
        except RuntimeError:
            pass            # rebuild() left the message in st.error
    else:
        try:
            applicability(context, st)  # greyed out at once, all the same
        except RuntimeError:
            pass            # Update will say why


class PhylloSetting(bpy.types.PropertyGroup):
    """One setting of the scene: its path, its kind of field, its value
    as the file (or the default) has it, and the field."""
    path: StringProperty()
    type: StringProperty()      # as --settings and phyllo-export(5) say
    kind: StringProperty()      # NUMBER INTEGER CHOICE STRING TEXT
    written: StringProperty()   # scene syntax, or "" for none
    origin: StringProperty()    # file, default
    default: StringProperty()
    doc: StringProperty()
    unit: StringProperty()
    choices: StringProperty()   # one a line
    range: StringProperty()     # "1 .. 10000000", for the panel
    # Whether it applies, as the scene's other settings and the panel's
    # changes stand, and if not, why: the loader refuses it given then,
    # so it is greyed out and left out of --set.
    applies: BoolProperty(default=True)
    why: StringProperty()
    number: FloatProperty(update=setting_changed, precision=4)
    integer: IntProperty(update=setting_changed)
    choice: EnumProperty(items=choice_items, update=setting_changed)
    text: StringProperty(update=setting_changed)

    def value(self):
        """The field's value in scene syntax ("" where none)."""
        if self.kind == "NUMBER":
            return number_text(self.number)
        if self.kind == "INTEGER":
            return str(self.integer)
        if self.kind == "CHOICE":
            return quote(self.choice) if self.choice != NONE else ""
        if self.kind == "STRING":
            if not self.text.strip():
                return ""
            # An expression field holding a number is the number.
            try:
                float(self.text)
                return self.text.strip()
            except ValueError:
                return quote(self.text)
        return self.text.strip()

    def changed(self):
        if self.kind == "NUMBER" and self.written:
            x = float(self.written)
            return abs(self.number - x) > 1e-6 * max(1.0, abs(x))
        return self.value() != self.written and \
            not (self.value() == "" and self.written == "")


class PhylloStructure(bpy.types.PropertyGroup):
    """What an imported structure's collection remembers."""
    scene: StringProperty(name="Scene file", subtype="FILE_PATH")
    frames: IntProperty(name="Frames", min=0)
    settings: CollectionProperty(type=PhylloSetting)
    error: StringProperty()
    seconds: FloatProperty()    # the last run, program and build
    stale: BoolProperty()       # changed since the last build
    last: StringProperty()      # the setting changed last, shown whole
    live: BoolProperty(name="Live", default=True,
                       description="Rebuild as soon as a setting changes, "
                       "while a run takes at most %.1f s" % LIVE_SECONDS)

    def overrides(self, every=False):
        """--set arguments for the settings changed in the panel that
        apply (every: those that do not, too)."""
        return ["%s=%s" % (s.path, s.value()) for s in self.settings
                if s.changed() and s.value() != "" and
                (s.applies or every)]


def kind_of(s):
    """The field a setting of --settings gets: a number field where it
    has a number, a menu for a word of a list, the text of a string or
    expression without its quotes, else the scene file's own text."""
    value = s["value"] or ""
    if s.get("choices"):
        return "CHOICE"
    if s["type"] in ("number", "integer") and value:
        return "NUMBER" if s["type"] == "number" else "INTEGER"
    if s["type"] == "expression":
        return "STRING"
    return "TEXT"


def interval(s):
    """"[1, 10000000]", "(0, 4]": a setting's range, for the panel."""
    lo, hi = s.get("min"), s.get("max")
    if lo is None and hi is None:
        return ""
    return "%s%s, %s]" % ("(" if s.get("min_open") or lo is None else "[",
                          "-inf" if lo is None else "%g" % lo,
                          "inf" if hi is None else "%g" % hi)


def fill(st, settings):
    """The panel's fields from --settings' list."""
    global _filling
    _filling = True
    try:
        st.settings.clear()
        for s in settings:
            if ":" in s["path"] or s["path"] in ("name", "model"):
                continue    # a part's, or one the panel cannot change
            item = st.settings.add()
            value = s["value"] or ""
            item.path = s["path"]
            item.type = s["type"]
            item.kind = kind_of(s)
            item.written = value
            item.origin = s["from"]
            item.default = s["default"]
            item.doc = s["doc"]
            item.unit = s.get("unit", "")
            item.range = interval(s)
            item.choices = "\n".join(s.get("choices", []))
            item.applies = s.get("applies", True)
            item.why = s.get("why", "")
            if item.kind == "NUMBER":
                item.number = float(value)
            elif item.kind == "INTEGER":
                item.integer = int(value.rstrip("L"))
            elif item.kind == "CHOICE":
                item.choice = unquote(value) if value else NONE
            elif item.kind == "STRING":
                item.text = unquote(value) if quoted(value) else value
            else:
                item.text = value
    finally:
        _filling = False


def field_of(item):
    """The property that holds a setting's value in the panel."""
    return {"NUMBER": "number", "INTEGER": "integer",
            "CHOICE": "choice"}.get(item.kind, "text")


def kept_changes(st):
    """The changes of settings that do not apply now, kept for when they
    do: what a refill from the file would lose."""
    return {s.path: getattr(s, field_of(s)) for s in st.settings
            if not s.applies and s.changed()}


def put_back(st, kept):
    global _filling
    _filling = True
    try:
        for s in st.settings:
            if s.path in kept:
                setattr(s, field_of(s), kept[s.path])
    finally:
        _filling = False


def structure_of(name):
    """The collection the script built for scene name."""
    return next((c for c in bpy.data.collections
                 if c.get(TAG) == name and c.get("phyllo_structure")),
                None)


def build(context, path, frames, overrides):
    """Run phyllo-export --blender and the script it writes, which builds
    into the structure's collection; the seconds it took."""
    start = time.perf_counter()
    args = ["--blender"] + (["--frames", str(frames)] if frames else [])
    for o in overrides:
        args += ["--set", o]
    with tempfile.TemporaryDirectory(prefix="phyllo-") as tmp:
        script = os.path.join(tmp, "import.py")
        run_program(context, args + ["-o", script, path])
        try:
            runpy.run_path(script, run_name="__main__")
        except SystemExit:
            # The script's own refusal of this Blender, printed on the
            # console; it stops before it changes anything.
            raise RuntimeError("phyllo-export: the script does not run "
                               "in Blender %s (see the console)"
                               % bpy.app.version_string)
    return time.perf_counter() - start


def settings_of(context, path, overrides=()):
    """phyllo-export --settings, read."""
    args = ["--settings"]
    for o in overrides:
        args += ["--set", o]
    return json.loads(run_program(context, args + [path]))


def applicability(context, st):
    """Which settings apply with every change in the panel: a change
    may leave others unused (a kernel without an exponent) or make them
    count again.  --settings lists those too, given or not."""
    listed = {s["path"]: s for s in settings_of(
        context, bpy.path.abspath(st.scene), st.overrides(every=True))[
        "settings"]}
    for item in st.settings:
        s = listed.get(item.path)
        if s is not None:
            item.applies = s.get("applies", True)
            item.why = s.get("why", "")


def rebuild(context, top):
    """Build top's structure again with the panel's settings; on an
    error leave it as it was, the message in the panel."""
    st = top.phyllo
    try:
        applicability(context, st)
        seconds = build(context, bpy.path.abspath(st.scene), st.frames,
                        st.overrides())
    except RuntimeError as e:
        st.error = str(e)
        raise
    st.error = ""
    st.seconds = seconds
    st.stale = False


class IMPORT_SCENE_OT_phyllotaxis(bpy.types.Operator, ImportHelper):
    """Build the organs of a phyllo-export scene file, instancing the
    .blend's own organ objects"""
    bl_idname = "import_scene.phyllotaxis"
    bl_label = "Import Phyllotaxis Scene"
    bl_options = {"REGISTER", "UNDO"}

    filename_ext = ".cfg"
    filter_glob: StringProperty(default="*.cfg", options={"HIDDEN"})
    frames: IntProperty(
        name="Frames", default=0, min=0, max=100000,
        description="Make the scene this many times, f = 0 .. 1 in its "
        "expressions, and set the timeline to them (0: one, no frames)")

    def execute(self, context):
        try:
            seconds = build(context, self.filepath, self.frames, [])
            settings = settings_of(context, self.filepath)
        except RuntimeError as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        top = structure_of(settings["name"])
        if top is not None:
            st = top.phyllo
            st.scene = self.filepath
            st.frames = self.frames
            st.error = ""
            st.seconds = seconds
            st.stale = False
            fill(st, settings["settings"])
            context.scene.phyllo_structure = top
        if self.frames:
            scene = context.scene
            scene.frame_end = scene.frame_start + self.frames - 1
        self.report({"INFO"}, "Imported %s"
                    % os.path.basename(self.filepath))
        return {"FINISHED"}


def active_structure(context):
    top = getattr(context.scene, "phyllo_structure", None)
    return top if top is not None and top.phyllo.scene else None


class OnStructure:
    """What the panel's operators share: they act on the active
    structure, and are greyed out without one."""

    @classmethod
    def poll(cls, context):
        return active_structure(context) is not None


class PHYLLO_OT_update(OnStructure, bpy.types.Operator):
    """Run phyllo-export with the panel's settings and build the
    structure again"""
    bl_idname = "phyllo.update"
    bl_label = "Update"
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        try:
            rebuild(context, active_structure(context))
        except RuntimeError as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        return {"FINISHED"}


class PHYLLO_OT_revert(OnStructure, bpy.types.Operator):
    """Set every setting back to the scene file's and build again"""
    bl_idname = "phyllo.revert"
    bl_label = "Revert"
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        top = active_structure(context)
        st = top.phyllo
        try:
            fill(st, settings_of(context, bpy.path.abspath(st.scene))[
                "settings"])
            rebuild(context, top)
        except RuntimeError as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        return {"FINISHED"}


class PHYLLO_OT_save(OnStructure, bpy.types.Operator):
    """Write the changed settings into the scene file, keeping its
    comments and layout (phyllo-export --cfg)"""
    bl_idname = "phyllo.save"
    bl_label = "Save to Scene File"
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        top = active_structure(context)
        st = top.phyllo
        path = bpy.path.abspath(st.scene)
        overrides = st.overrides()
        kept = kept_changes(st)
        try:
            text = run_program(context, ["--cfg"] + sum(
                (["--set", o] for o in overrides), []) + [path])
            # Beside the file, then over it: a failed write leaves it.
            tmp = "%s.%d.tmp" % (path, os.getpid())
            with open(tmp, "w") as f:
                f.write(text)
            os.replace(tmp, path)
            settings = settings_of(context, path)
        except (RuntimeError, OSError) as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        fill(st, settings["settings"])
        put_back(st, kept)
        self.report({"INFO"}, "Wrote %d setting(s) into %s"
                    % (len(overrides), os.path.basename(path)))
        return {"FINISHED"}


def group_of(path):
    """The panel's box a setting goes in: "Scene", "planar",
    "collision.receptacle", "organs 1"..."""
    parts = path.split(".")
    if len(parts) == 1:
        return "Scene"
    if parts[0] == "organs":
        return "Organs entry %s" % parts[1]
    return ".".join(parts[:-1])


class VIEW3D_PT_phyllotaxis(bpy.types.Panel):
    """The settings of the structure imported last (or chosen)."""
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Phyllotaxis"
    bl_label = "Phyllotaxis"

    def draw(self, context):
        layout = self.layout
        layout.prop(context.scene, "phyllo_structure", text="")
        top = active_structure(context)
        if top is None:
            layout.label(text="File > Import > Phyllotaxis scene (.cfg)")
            return
        st = top.phyllo
        layout.label(text=os.path.basename(st.scene), icon="FILE")
        if st.error:
            box = layout.box()
            box.alert = True
            for i, line in enumerate(wrap(st.error, 48)):
                box.label(text=line, icon="ERROR" if i == 0 else "BLANK1")
        row = layout.row()
        row.prop(st, "live")
        sub = row.row()
        sub.enabled = st.stale or bool(st.error)
        sub.operator("phyllo.update", text="Update (last %.2f s)"
                     % st.seconds)
        last = next((s for s in st.settings if s.path == st.last), None)
        if last is not None:
            # The setting changed last, whole: what the rows leave out.
            box = layout.box()
            box.label(text="%s: %s" % (last.path, last.type), icon="INFO")
            for line in wrap("; ".join(w for w in (
                    last.doc, last.range and "range " + last.range,
                    last.unit, "default " + last.default,
                    "file " + (last.written or "none")) if w), 44):
                box.label(text=line)
        box, group = None, None
        for item in st.settings:
            if group_of(item.path) != group:
                group = group_of(item.path)
                box = layout.box()
                box.label(text=group)
            # The name, marked when changed, then the field.
            split = box.split(factor=0.4, align=True)
            split.enabled = item.applies
            split.label(text=item.path.split(".")[-1] +
                        (" *" if item.changed() else ""))
            split.prop(item, field_of(item), text="")
            if not item.applies:
                for line in wrap(item.why, 44):
                    box.label(text=line)
        row = layout.row()
        row.operator("phyllo.save")
        row.operator("phyllo.revert")


def wrap(text, width):
    words, lines, line = text.split(), [], ""
    for w in words:
        if line and len(line) + 1 + len(w) > width:
            lines.append(line)
            line = w
        else:
            line = (line + " " + w).strip()
    return lines + [line] if line else lines


def menu_import(self, context):
    self.layout.operator(IMPORT_SCENE_OT_phyllotaxis.bl_idname,
                         text="Phyllotaxis scene (.cfg)")


def is_structure(self, collection):
    return bool(collection.phyllo.scene)


CLASSES = (PhylloPreferences, PhylloSetting, PhylloStructure,
           IMPORT_SCENE_OT_phyllotaxis, PHYLLO_OT_update, PHYLLO_OT_revert,
           PHYLLO_OT_save, VIEW3D_PT_phyllotaxis)


def register():
    for c in CLASSES:
        bpy.utils.register_class(c)
    bpy.types.Collection.phyllo = PointerProperty(type=PhylloStructure)
    bpy.types.Scene.phyllo_structure = PointerProperty(
        type=bpy.types.Collection, poll=is_structure, name="Structure",
        description="The imported structure whose settings the panel "
        "shows")
    bpy.types.TOPBAR_MT_file_import.append(menu_import)


def unregister():
    bpy.types.TOPBAR_MT_file_import.remove(menu_import)
    del bpy.types.Scene.phyllo_structure
    del bpy.types.Collection.phyllo
    for c in reversed(CLASSES):
        bpy.utils.unregister_class(c)
