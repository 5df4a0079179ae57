# LipSync Studio animation import for Blender (3.x and later).
#
# Reads what `lipsync export controls` and `lipsync export cues` write (docs/formats.md):
#   File > Import > LipSync Animation Controls (.json, .csv)
#       keys every control (jawOpen, mouthClose, ... mouthOpen) on the selected object:
#       a mesh's shape keys of the same names; an armature's jaw bone (named "jaw" unless told
#       otherwise) turned about its X axis by jawOpen times an angle (20 degrees unless told
#       otherwise); and on any object custom properties "lipsync_<control>" that drivers can feed
#       to a rig's other bones or shape keys;
#   File > Import > LipSync Mouth Cues (.tsv, .json, .xml, .dat)
#       a 2D mouth: one image strip per cue in the Video Sequencer, from a folder of drawings
#       named after the shapes (A.png ... H.png, X.png, or Preston Blair's names: MBP.png,
#       etc.png, ...), and the integer property "lipsync_mouth" (0 = A ... 8 = X) keyed with
#       constant interpolation on the selected object, for rigs that switch drawings.
# Both key at the file's own frame rate (the scene's rate is set to it) and put the sound in the
# Sequencer at the scene's first frame.
#
# Installed by `cmake --install` to share/lipsync/blender/; install it in Blender with
# Edit > Preferences > Add-ons > Install. Without the UI (blender -b --python):
#   import lipsync_animation as la
#   la.import_controls(context, "speech-controls.json")
#   la.import_cues(context, "speech-cues.tsv", "/path/to/mouth-drawings")

bl_info = {
    "name": "LipSync Studio animation",
    "author": "LipSync Studio",
    "version": (1, 0, 0),
    "blender": (3, 0, 0),
    "location": "File > Import",
    "description": "Mouth controls and Rhubarb-compatible mouth cues from LipSync Studio",
    "category": "Import-Export",
}

import csv
import json
import math
import os
import xml.etree.ElementTree as ElementTree

SHAPES = "ABCDEFGHX"
PRESTON_BLAIR = ["MBP", "etc", "E", "AI", "O", "U", "FV", "L", "rest"]


class LipsyncFileError(Exception):
    """A file that is not what LipSync Studio writes: the message names the file and the place."""


# ---------------------------------------------------------------------------------------------
# Readers (no Blender needed)

def read_controls(path):
    """Returns {"soundFile", "frameRate", "names", "times", "values"} of a controls file."""
    if path.lower().endswith(".json"):
        with open(path, encoding="utf-8") as f:
            try:
                root = json.load(f)
            except ValueError as e:
                raise LipsyncFileError(f"{path}: not JSON: {e}")
        if root.get("format") != "lipsync-controls":
            raise LipsyncFileError(f"{path}: format: not a lipsync-controls file")
        names = list(root["controls"])
        frames = root["frames"]
        return {"soundFile": root.get("soundFile", ""), "frameRate": float(root["frameRate"]), "names": names,
                "times": [float(fr["time"]) for fr in frames], "values": [list(map(float, fr["values"])) for fr in frames]}
    sound, rate, names, times, values = "", 0.0, None, [], []
    with open(path, encoding="utf-8", newline="") as f:
        for number, line in enumerate(f, 1):
            line = line.rstrip("\r\n")
            if line.startswith("# soundFile: "):
                sound = line[len("# soundFile: "):]
            elif line.startswith("# frameRate: "):
                rate = float(line[len("# frameRate: "):])
            elif line.startswith("frame,time"):
                header = next(csv.reader([line]))
                names = [n for n in header[2:] if not (n[0] in "xy" and n[1:].isdigit())]
            elif line:
                if names is None:
                    raise LipsyncFileError(f"{path}: line {number}: a row before the header")
                cells = next(csv.reader([line]))
                try:
                    times.append(float(cells[1]))
                    values.append([float(v) for v in cells[2:2 + len(names)]])
                except (ValueError, IndexError):
                    raise LipsyncFileError(f"{path}: line {number}: expected numbers")
    if names is None or rate <= 0:
        raise LipsyncFileError(f"{path}: no header or frame rate")
    return {"soundFile": sound, "frameRate": rate, "names": names, "times": times, "values": values}


def _shape(name, path, where, preston_blair_first=False):
    if preston_blair_first and name in PRESTON_BLAIR:
        return PRESTON_BLAIR.index(name)
    if len(name) == 1 and name in SHAPES:
        return SHAPES.index(name)
    if name in PRESTON_BLAIR:
        return PRESTON_BLAIR.index(name)
    raise LipsyncFileError(f"{path}: {where}: '{name}' is not a mouth shape")


def read_cues(path, dat_frame_rate=24.0):
    """Returns {"soundFile", "duration", "cues": [(start, end, shape index)]} of a cues file."""
    lower = path.lower()
    with open(path, encoding="utf-8") as f:
        text = f.read()
    if lower.endswith(".json"):
        root = json.loads(text)
        cues = [(float(c["start"]), float(c["end"]), _shape(c["value"], path, f"mouthCues[{i}]"))
                for i, c in enumerate(root["mouthCues"])]
        return {"soundFile": root["metadata"].get("soundFile", ""), "duration": float(root["metadata"]["duration"]),
                "cues": cues}
    if lower.endswith(".xml"):
        root = ElementTree.fromstring(text)
        cues = [(float(c.get("start")), float(c.get("end")), _shape(c.text.strip(), path, "mouthCue"))
                for c in root.iter("mouthCue")]
        return {"soundFile": root.findtext("metadata/soundFile", ""),
                "duration": float(root.findtext("metadata/duration", "0")), "cues": cues}
    dat = lower.endswith(".dat")
    starts = []
    for number, line in enumerate(text.splitlines(), 1):
        if dat and number == 1:
            if line.strip() != "MohoSwitch1":
                raise LipsyncFileError(f"{path}: line 1: a Moho switch file starts with MohoSwitch1")
            continue
        if not line.strip():
            continue
        first, _, name = line.partition(" " if dat else "\t")
        try:
            t = (int(first) - 1) / dat_frame_rate if dat else float(first)
        except ValueError:
            raise LipsyncFileError(f"{path}: line {number}: expected a {'frame' if dat else 'time'}")
        starts.append((t, _shape(name.strip(), path, f"line {number}", preston_blair_first=dat)))
    if not starts:
        raise LipsyncFileError(f"{path}: no mouth cues")
    end = starts[-1][0]
    cues = [(s, starts[i + 1][0], shape) for i, (s, shape) in enumerate(starts[:-1])]
    return {"soundFile": "", "duration": end, "cues": cues}


# ---------------------------------------------------------------------------------------------
# Blender

def _set_scene_rate(scene, rate):
    """The scene's frame rate as the file's: 25, 30000/1001 for 29.97, ..."""
    fps = round(rate)
    scene.render.fps = max(1, fps)
    scene.render.fps_base = fps / rate if rate > 0 else 1.0


def _frame_of(scene, seconds):
    return scene.frame_start + round(seconds * scene.render.fps / scene.render.fps_base)


def _add_sound(scene, sound_file):
    if not sound_file or not os.path.isfile(sound_file):
        return None
    editor = scene.sequence_editor or scene.sequence_editor_create()
    strip = editor.sequences.new_sound(os.path.basename(sound_file), sound_file, channel=1,
                                       frame_start=scene.frame_start)
    return strip


def import_controls(context, path, obj=None, jaw_bone="jaw", jaw_degrees=20.0):
    """Keys the controls of `path` on `obj` (default: the active object); returns the keys set."""
    data = read_controls(path)
    scene = context.scene
    obj = obj or context.active_object
    if obj is None:
        raise LipsyncFileError("select the object to animate first")
    _set_scene_rate(scene, data["frameRate"])
    keys = 0
    shape_keys = obj.data.shape_keys.key_blocks if getattr(obj.data, "shape_keys", None) else {}
    for k, name in enumerate(data["names"]):
        prop = "lipsync_" + name
        obj[prop] = 0.0
        block = shape_keys.get(name) if shape_keys else None
        for t, row in zip(data["times"], data["values"]):
            frame = _frame_of(scene, t)
            obj[prop] = row[k]
            obj.keyframe_insert(data_path=f'["{prop}"]', frame=frame)
            keys += 1
            if block is not None:
                block.value = row[k]
                block.keyframe_insert("value", frame=frame)
                keys += 1
    pose = obj.pose if obj.type == "ARMATURE" else None
    jaw = pose.bones.get(jaw_bone) if pose is not None and jaw_bone else None
    if jaw is not None and "jawOpen" in data["names"]:
        k = data["names"].index("jawOpen")
        jaw.rotation_mode = "XYZ"
        for t, row in zip(data["times"], data["values"]):
            jaw.rotation_euler[0] = math.radians(jaw_degrees) * row[k]
            jaw.keyframe_insert("rotation_euler", index=0, frame=_frame_of(scene, t))
            keys += 1
    if data["times"]:
        scene.frame_end = max(scene.frame_end, _frame_of(scene, data["times"][-1]))
    _add_sound(scene, data["soundFile"])
    return keys


def _drawing(folder, shape):
    for name in (SHAPES[shape], PRESTON_BLAIR[shape]):
        for ext in (".png", ".jpg", ".jpeg", ".webp"):
            candidate = os.path.join(folder, name + ext)
            if os.path.isfile(candidate):
                return candidate
    return None


def import_cues(context, path, drawings=None, obj=None, dat_frame_rate=24.0):
    """Places the cues of `path`: image strips from `drawings` (a folder; none: no strips) and the
    keyed "lipsync_mouth" property on `obj` (default: the active object, if any). Returns the
    number of cues."""
    data = read_cues(path, dat_frame_rate)
    scene = context.scene
    if path.lower().endswith(".dat"):
        _set_scene_rate(scene, dat_frame_rate)
    obj = obj or context.active_object
    editor = scene.sequence_editor or scene.sequence_editor_create()
    for start, end, shape in data["cues"]:
        first, last = _frame_of(scene, start), _frame_of(scene, end)
        if obj is not None:
            obj["lipsync_mouth"] = shape
            obj.keyframe_insert(data_path='["lipsync_mouth"]', frame=first)
        drawing = _drawing(drawings, shape) if drawings else None
        if drawing and last > first:
            strip = editor.sequences.new_image(f"mouth {SHAPES[shape]} {first}", drawing, channel=2, frame_start=first)
            strip.frame_final_end = last
    if obj is not None and obj.animation_data and obj.animation_data.action:
        for curve in obj.animation_data.action.fcurves:
            if curve.data_path == '["lipsync_mouth"]':
                for point in curve.keyframe_points:
                    point.interpolation = "CONSTANT"
    scene.frame_end = max(scene.frame_end, _frame_of(scene, data["duration"]))
    _add_sound(scene, data["soundFile"])
    return len(data["cues"])


try:
    import bpy
    from bpy.props import FloatProperty, StringProperty
    from bpy_extras.io_utils import ImportHelper
except ImportError:  # the readers alone, outside Blender
    bpy = None

if bpy is not None:
    class LIPSYNC_OT_import_controls(bpy.types.Operator, ImportHelper):
        """Key LipSync Studio's mouth controls on the selected object's shape keys and properties"""
        bl_idname = "lipsync.import_controls"
        bl_label = "Import LipSync Animation Controls"
        bl_options = {"REGISTER", "UNDO"}
        filter_glob: StringProperty(default="*.json;*.csv", options={"HIDDEN"})
        jaw_bone: StringProperty(name="Jaw bone", default="jaw",
                                 description="The armature's bone that jawOpen turns about its X axis")
        jaw_degrees: FloatProperty(name="Jaw angle", default=20.0, min=0.0, max=90.0,
                                   description="Degrees the jaw bone turns at jawOpen = 1")

        def execute(self, context):
            try:
                keys = import_controls(context, self.filepath, jaw_bone=self.jaw_bone, jaw_degrees=self.jaw_degrees)
            except (LipsyncFileError, OSError, KeyError, ValueError) as e:
                self.report({"ERROR"}, str(e))
                return {"CANCELLED"}
            self.report({"INFO"}, f"{keys} keys from {os.path.basename(self.filepath)}")
            return {"FINISHED"}

    class LIPSYNC_OT_import_cues(bpy.types.Operator, ImportHelper):
        """Place LipSync Studio's (or Rhubarb's) mouth cues as drawings in the Sequencer"""
        bl_idname = "lipsync.import_cues"
        bl_label = "Import LipSync Mouth Cues"
        bl_options = {"REGISTER", "UNDO"}
        filter_glob: StringProperty(default="*.tsv;*.json;*.xml;*.dat", options={"HIDDEN"})
        drawings: StringProperty(name="Drawings", subtype="DIR_PATH",
                                 description="Folder of A.png ... H.png and X.png (or Preston Blair's names)")
        dat_frame_rate: FloatProperty(name=".dat frame rate", default=24.0, min=24.0, max=100.0)

        def execute(self, context):
            try:
                cues = import_cues(context, self.filepath, bpy.path.abspath(self.drawings) or None,
                                   dat_frame_rate=self.dat_frame_rate)
            except (LipsyncFileError, OSError, KeyError, ValueError) as e:
                self.report({"ERROR"}, str(e))
                return {"CANCELLED"}
            self.report({"INFO"}, f"{cues} mouth cues from {os.path.basename(self.filepath)}")
            return {"FINISHED"}

    def _menu(self, context):
        self.layout.operator(LIPSYNC_OT_import_controls.bl_idname, text="LipSync Animation Controls (.json, .csv)")
        self.layout.operator(LIPSYNC_OT_import_cues.bl_idname, text="LipSync Mouth Cues (.tsv, .json, .xml, .dat)")

    _classes = (LIPSYNC_OT_import_controls, LIPSYNC_OT_import_cues)

    def register():
        for c in _classes:
            bpy.utils.register_class(c)
        bpy.types.TOPBAR_MT_file_import.append(_menu)

    def unregister():
        bpy.types.TOPBAR_MT_file_import.remove(_menu)
        for c in reversed(_classes):
            bpy.utils.unregister_class(c)
