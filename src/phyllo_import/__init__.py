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
import re
import runpy
import subprocess
import tempfile
import time

import blf
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
# A number as the scene file writes one (libconfig's integers, with L
# for 64 bits, hexadecimal, and floats); any other text in a number's
# field is an expression.
NUMBER = re.compile(r"[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?L{0,2}\Z|"
                    r"[-+]?0[xX][0-9a-fA-F]+L{0,2}\Z")
INT32 = 2 ** 31     # what Blender's integer fields hold


def quoted(text):
    """Whether text is one string literal of the scene file's syntax."""
    return len(text) >= 2 and text[0] == '"' and text[-1] == '"' and \
        '"' not in text[1:-1].replace('\\"', "")


def unquote(text):
    return text[1:-1].replace('\\"', '"').replace("\\\\", "\\")


def quote(text):
    return '"%s"' % text.replace("\\", "\\\\").replace('"', '\\"')


def shown(value):
    """A number's or expression's text in its field: without quotes."""
    return unquote(value) if quoted(value) else value


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
    """One setting of the scene or of one of its parts: its path
    ("PART:path" for a part's), its kind of field, its value as the file
    (or the default) has it, and the field."""
    path: StringProperty()
    type: StringProperty()      # as --settings and phyllo-export(5) say
    # NUMBER: text, a number as typed or an expression (Blender's float
    # fields hold seven digits, and a number may be an expression);
    # INTEGER; CHOICE, a word of a list; TEXT, scene syntax; FIXED, shown
    # and not changed here (name, model).
    kind: StringProperty()
    file: StringProperty()      # the scene file that holds it
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
    integer: IntProperty(update=setting_changed)
    choice: EnumProperty(items=choice_items, update=setting_changed)
    text: StringProperty(update=setting_changed)

    def value(self):
        """The field's value in scene syntax ("" where none)."""
        if self.kind == "NUMBER":
            # A number exactly as typed; anything else an expression.
            text = self.text.strip()
            return text if not text or NUMBER.match(text) else quote(text)
        if self.kind == "INTEGER":
            return str(self.integer)
        if self.kind == "CHOICE":
            return quote(self.choice) if self.choice != NONE else ""
        if self.kind == "FIXED":
            return self.written
        return self.text.strip()

    def changed(self):
        if self.kind == "NUMBER":
            # As shown, so that "15", a string, is not taken for a change
            # to 15.
            return self.text.strip() != shown(self.written)
        return self.value() != self.written


class PhylloStructure(bpy.types.PropertyGroup):
    """What an imported structure's collection remembers."""
    scene: StringProperty(name="Scene file", subtype="FILE_PATH")
    frames: IntProperty(name="Frames", min=0)
    settings: CollectionProperty(type=PhylloSetting)
    error: StringProperty()
    seconds: FloatProperty()    # the last run, program and build
    stale: BoolProperty()       # changed since the last build
    last: StringProperty()      # the setting changed last, shown whole
    show_parts: BoolProperty(name="Parts", default=True,
                             description="Show the settings of the parts, "
                             "the scenes the structure's organs are made "
                             "of (each saved into its own file)")
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
    """The field a setting of --settings gets: shown only for the name
    and the model (the panel's fields are that model's, its collection
    that name's); a menu for a word of a list; an integer field for an
    integer Blender's fields hold; the text of a number or expression
    (without its quotes); else the scene file's own text."""
    value = s["value"] or ""
    path = s["path"].split(":")[-1]
    if path in ("name", "model"):
        return "FIXED"
    if s.get("choices") and (not value or quoted(value) and
                             unquote(value) in s["choices"]):
        return "CHOICE"
    if s["type"] == "integer" and re.match(r"[-+]?\d+L{0,2}\Z", value) \
            and -INT32 <= int(value.rstrip("L")) < INT32:
        return "INTEGER"
    if s["type"] in ("number", "integer", "expression") and (
            not quoted(value) or quote(unquote(value)) == value):
        return "NUMBER"
    return "TEXT"


def interval(s):
    """"[1, 10000000]", "(0, 4]": a setting's range, for the panel."""
    lo, hi = s.get("min"), s.get("max")
    if lo is None and hi is None:
        return ""
    return "%s%s, %s]" % ("(" if s.get("min_open") or lo is None else "[",
                          "-inf" if lo is None else "%.12g" % lo,
                          "inf" if hi is None else "%.12g" % hi)


def rows_of(listing):
    """The panel's fields for --settings' listing, every setting of the
    scene and of its parts, worked out whole before anything is set:
    what cannot be read here fails before the import changes anything."""
    files = {p["object"]: os.path.abspath(p["scene"])
             for p in listing.get("parts", [])}
    rows = []
    for s in listing["settings"]:
        value = s["value"] or ""
        kind = kind_of(s)
        part = s["path"].split(":")[0] if ":" in s["path"] else ""
        row = dict(
            path=s["path"], type=s["type"], kind=kind, written=value,
            file=files.get(part, "") if part else
            os.path.abspath(listing["scene"]),
            origin=s["from"], default=s["default"], doc=s["doc"],
            unit=s.get("unit", ""), range=interval(s),
            choices="\n".join(s.get("choices", [])),
            applies=s.get("applies", True), why=s.get("why", ""))
        if kind == "INTEGER":
            row["integer"] = int(value.rstrip("L"))
        elif kind == "CHOICE":
            row["choice"] = unquote(value) if value else NONE
        elif kind == "NUMBER":
            row["text"] = shown(value)
        elif kind == "TEXT":
            row["text"] = value
        rows.append(row)
    return rows


def fill(st, rows):
    """The panel's fields, from rows_of()."""
    global _filling
    _filling = True
    try:
        st.settings.clear()
        for row in rows:
            item = st.settings.add()
            # The menu's items depend on choices and written: set first.
            for key in ("choices", "written"):
                setattr(item, key, row[key])
            for key, value in row.items():
                setattr(item, key, value)
    finally:
        _filling = False


def field_of(item):
    """The property that holds a setting's value in the panel."""
    return {"INTEGER": "integer", "CHOICE": "choice",
            "FIXED": "written"}.get(item.kind, "text")


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
        # Everything that may fail comes before the build, the one step
        # that changes the .blend: a failed import leaves it as it was.
        # (The script sets the timeline to the frames.)
        try:
            listing = settings_of(context, self.filepath)
            rows = rows_of(listing)
            seconds = build(context, self.filepath, self.frames, [])
        except (RuntimeError, ValueError, KeyError) as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        top = structure_of(listing["name"])
        if top is not None:
            st = top.phyllo
            st.scene = self.filepath
            st.frames = self.frames
            st.error = ""
            st.last = ""
            st.seconds = seconds
            st.stale = False
            fill(st, rows)
            context.scene.phyllo_structure = top
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
        path = bpy.path.abspath(st.scene)
        # Built first, the fields after: a failure (the file changed
        # since, and now bad) leaves both as they were.
        try:
            rows = rows_of(settings_of(context, path))
            seconds = build(context, path, st.frames, [])
        except (RuntimeError, ValueError, KeyError) as e:
            st.error = str(e)
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        fill(st, rows)
        st.error = ""
        st.seconds = seconds
        st.stale = False
        return {"FINISHED"}


class PHYLLO_OT_save(OnStructure, bpy.types.Operator):
    """Write the changed settings into the scene file, and a part's into
    the part's own file, keeping comments and layout (phyllo-export
    --cfg); a setting the file gives that a change leaves unused is
    taken out"""
    bl_idname = "phyllo.save"
    bl_label = "Save to Scene File"
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        top = active_structure(context)
        st = top.phyllo
        main = bpy.path.abspath(st.scene)
        kept = kept_changes(st)
        changes = {}        # file: its --set, a part's without "PART:"
        for s in st.settings:
            if s.changed() and s.value() != "" and s.applies:
                if not s.file:
                    self.report({"ERROR"}, "%s: the file of its part is "
                                "not known: nothing written" % s.path)
                    return {"CANCELLED"}
                changes.setdefault(s.file, []).append(
                    "%s=%s" % (s.path.split(":")[-1], s.value()))
        given = {s.path for s in st.settings if s.origin == "file"}
        tmps = []
        try:
            # Every file's text first, then each written beside its file
            # and put over it: a refusal or a failed write leaves them.
            texts = [(f, run_program(context, ["--cfg"] + sum(
                (["--set", o] for o in sets), []) + [f]))
                for f, sets in sorted(changes.items())]
            for f, text in texts:
                tmps.append("%s.%d.tmp" % (f, os.getpid()))
                with open(tmps[-1], "w") as out:
                    out.write(text)
            for (f, _), tmp in zip(texts, tmps):
                os.replace(tmp, f)
            rows = rows_of(settings_of(context, main))
        except (RuntimeError, OSError, ValueError, KeyError) as e:
            for tmp in tmps:
                if os.path.exists(tmp):
                    os.remove(tmp)
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        fill(st, rows)
        put_back(st, kept)
        taken = sorted(given - {r["path"] for r in rows
                                if r["origin"] == "file"})
        self.report({"INFO"}, "Wrote %d setting(s) into %s%s" % (
            sum(len(v) for v in changes.values()),
            ", ".join(os.path.basename(f) for f in sorted(changes)) or
            "no file (nothing changed)",
            "; took out %s, which the changes leave unused"
            % ", ".join(taken) if taken else ""))
        return {"FINISHED"}


def group_of(path):
    """The panel's box a setting goes in: "Scene", "planar",
    "collision.receptacle", "Organs entry 1", and for a part's,
    "Achene: planar"..."""
    part, _, path = path.rpartition(":")
    parts = path.split(".")
    if len(parts) == 1:
        group = "Scene"
    elif parts[0] == "organs":
        group = "Organs entry %s" % parts[1]
    else:
        group = ".".join(parts[:-1])
    return "%s: %s" % (part, group) if part else group


# --- Labels wrapped to the sidebar's width. ---

# What a label in a box of the sidebar does not have of the region's
# width, in pixels at scale 1: the column of tabs, the panel's and the
# box's margins and the label's own.  Measured on a screenshot of
# Blender 3.4 (a 229-pixel region at scale 1.04 leaves 162 pixels of
# text, 136 beside an icon), with a few to spare.
LABEL_MARGIN = 72
ICON = 28           # a label's icon and its gap, at scale 1


def ui_scale(context):
    # The display's and the user's scale together; 0 without a window.
    return context.preferences.system.ui_scale or \
        context.preferences.view.ui_scale


def text_width(context, text):
    """Pixels the UI's font draws text in, at the UI's size and scale."""
    blf.size(0, context.preferences.ui_styles[0].widget.points *
             ui_scale(context))
    return blf.dimensions(0, text)[0]


def wrap(text, fits):
    """text in lines that each fit (fits(line) is true): by words, and a
    word that does not fit a line alone by characters, so that Blender
    never cuts a line short in its middle."""
    lines, line = [], ""
    for word in text.split():
        if not line or fits(line + " " + word):
            line = (line + " " + word).strip()
            if fits(line):
                continue
        else:
            lines.append(line)
            line = word
        while not fits(line) and len(line) > 1:
            n = len(line) - 1
            while n > 1 and not fits(line[:n]):
                n -= 1
            lines.append(line[:n])
            line = line[n:]
    return lines + [line] if line else lines


def wrapped(context, text, icon=False):
    """text as label lines for a box of the sidebar's region."""
    region = getattr(context, "region", None)
    scale = ui_scale(context)
    room = (region.width if region is not None else 300) - \
        (LABEL_MARGIN + ICON * icon) * scale
    return wrap(text, lambda line: text_width(context, line) <= room)


def labels(layout, context, text, icon=None):
    """text as labels in layout, a line each, wrapped to the sidebar's
    width; with icon, the first line shows it and the others stand as
    far in (BLANK1), so that the text reads as one block."""
    for i, line in enumerate(wrapped(context, text, icon is not None)):
        if icon is None:
            layout.label(text=line)
        else:
            layout.label(text=line, icon=icon if i == 0 else "BLANK1")


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
            labels(box, context, st.error, "ERROR")
        # Update, with the last run's time, the wider: in half the
        # sidebar's width it was cut short.
        row = layout.split(factor=0.35)
        row.prop(st, "live")
        sub = row.row()
        sub.enabled = st.stale or bool(st.error)
        sub.operator("phyllo.update", text="Update (%.2f s)" % st.seconds)
        last = next((s for s in st.settings if s.path == st.last), None)
        if last is not None:
            # The setting changed last, whole: what the rows leave out.
            box = layout.box()
            labels(box, context, "%s: %s" % (last.path, last.type), "INFO")
            labels(box, context, "; ".join(w for w in (
                last.doc, last.range and "range " + last.range,
                last.unit, "default " + last.default,
                "file " + (last.written or "none")) if w))
        box, group, part = None, None, ""
        for item in st.settings:
            if ":" in item.path and not part:
                # The parts' settings, after the scene's, folded away
                # at will.
                part = item.path.split(":")[0]
                layout.prop(st, "show_parts", emboss=False,
                            icon="TRIA_DOWN" if st.show_parts
                            else "TRIA_RIGHT")
            if part and not st.show_parts:
                break
            if group_of(item.path) != group:
                group = group_of(item.path)
                box = layout.box()
                box.label(text=group)
            # The name, marked when changed, then the field.
            split = box.split(factor=0.4, align=True)
            split.enabled = item.applies and item.kind != "FIXED"
            split.label(text=item.path.split(".")[-1].split(":")[-1] +
                        (" *" if item.changed() else ""))
            if item.kind == "FIXED":
                split.label(text=unquote(item.written)
                            if quoted(item.written) else item.written)
            else:
                split.prop(item, field_of(item), text="")
            if not item.applies:
                labels(box, context, item.why)
        row = layout.row()
        row.operator("phyllo.save")
        row.operator("phyllo.revert")


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
