# The Blender add-on (resources/blender/lipsync_animation.py), headless: Debian's
# `blender -b --factory-startup --python tests/blender/test_addon.py -- ADDON CONTROLS CUES`.
# On a tiny rig built here (a mesh with shape keys named after the controls, an armature), it
# imports a controls file and a cues file written by `lipsync export`, and checks that:
#  - the scene runs at the file's frame rate and the sound is in the Sequencer at the first frame;
#  - every shape key of a control is keyed on every frame with the file's value;
#  - an armature's jaw bone turns by jawOpen, and it gets the controls as keyed custom properties;
#  - the cues become one image strip per drawn cue and a constant "lipsync_mouth" curve whose
#    value at every cue's start is that cue's shape;
#  - File > Import's operators run;
#  - a file that is not LipSync's is refused with its name.
# Exits 1 on the first failed check (blender --python-exit-code 1).
import importlib.util
import math
import os
import sys
import tempfile

import bpy

args = sys.argv[sys.argv.index("--") + 1:]
addon_path, controls_path, cues_path = args[:3]
spec = importlib.util.spec_from_file_location("lipsync_animation", addon_path)
la = importlib.util.module_from_spec(spec)
spec.loader.exec_module(la)
la.register()


def check(condition, message):
    if not condition:
        print("FAIL:", message)
        sys.exit(1)


context = bpy.context
scene = context.scene
data = la.read_controls(controls_path)
names = data["names"]
check("jawOpen" in names and "mouthOpen" in names, f"control names: {names}")

# A mesh with the controls as shape keys, plus one key the file does not name.
bpy.ops.mesh.primitive_plane_add()
face = context.active_object
face.shape_key_add(name="Basis")
for name in names + ["unrelated"]:
    face.shape_key_add(name=name)
keys = la.import_controls(context, controls_path, face)
check(keys == 2 * len(names) * len(data["times"]), f"{keys} keys")
check(abs(scene.render.fps / scene.render.fps_base - data["frameRate"]) < 1e-6, "scene frame rate")
sound = [s for s in scene.sequence_editor.sequences_all if s.type == "SOUND"]
check(len(sound) == 1 and sound[0].frame_start == scene.frame_start, "the sound strip at the first frame")
blocks = face.data.shape_keys.key_blocks
for k, name in enumerate(names):
    for f, t in enumerate(data["times"]):
        frame = la._frame_of(scene, t)
        scene.frame_set(frame)
        check(abs(blocks[name].value - data["values"][f][k]) < 1e-5,
              f"{name} at frame {frame}: {blocks[name].value} vs {data['values'][f][k]}")
check(face.data.shape_keys.animation_data.action is not None, "shape key action")
check(not any(c.data_path == 'key_blocks["unrelated"].value' for c in face.data.shape_keys.animation_data.action.fcurves),
      "a shape key the file does not name is left alone")

# An armature with a jaw bone: jawOpen turns it; the controls as keyed custom properties for drivers.
bpy.ops.object.armature_add()
rig = context.active_object
bpy.ops.object.mode_set(mode="EDIT")
rig.data.edit_bones[0].name = "jaw"
bpy.ops.object.mode_set(mode="OBJECT")
la.import_controls(context, controls_path, rig, jaw_degrees=30.0)
jaw_column = names.index("jawOpen")
for f in (len(data["times"]) // 3, len(data["times"]) // 2):
    scene.frame_set(la._frame_of(scene, data["times"][f]))
    check(abs(rig["lipsync_jawOpen"] - data["values"][f][jaw_column]) < 1e-5, "armature property")
    expected = math.radians(30.0) * data["values"][f][jaw_column]
    check(abs(rig.pose.bones["jaw"].rotation_euler[0] - expected) < 1e-5,
          f"jaw bone at frame {scene.frame_current}: {rig.pose.bones['jaw'].rotation_euler[0]} vs {expected}")

# Cues as drawings: a folder of nine tiny images named after the shapes.
drawings = tempfile.mkdtemp()
for letter in la.SHAPES:
    image = bpy.data.images.new(letter, 4, 4)
    image.filepath_raw = os.path.join(drawings, letter + ".png")
    image.file_format = "PNG"
    image.save()
cue_data = la.read_cues(cues_path)
mouth = bpy.data.objects.new("mouth", None)
scene.collection.objects.link(mouth)
count = la.import_cues(context, cues_path, drawings, mouth)
check(count == len(cue_data["cues"]) and count > 5, f"{count} cues")
strips = [s for s in scene.sequence_editor.sequences_all if s.type == "IMAGE"]
drawn = [c for c in cue_data["cues"] if la._frame_of(scene, c[1]) > la._frame_of(scene, c[0])]
check(len(strips) == len(drawn), f"{len(strips)} image strips for {len(drawn)} cues")
curve = [c for c in mouth.animation_data.action.fcurves if c.data_path == '["lipsync_mouth"]'][0]
check(all(p.interpolation == "CONSTANT" for p in curve.keyframe_points), "constant mouth curve")
for start, end, shape in cue_data["cues"]:
    first = la._frame_of(scene, start)
    check(round(curve.evaluate(first)) == shape, f"shape at frame {first}")

# The operators of File > Import, as a user runs them.
context.view_layer.objects.active = face
check(bpy.ops.lipsync.import_controls(filepath=controls_path) == {"FINISHED"}, "the controls operator")
check(bpy.ops.lipsync.import_cues(filepath=cues_path, drawings=drawings) == {"FINISHED"}, "the cues operator")
check(hasattr(bpy.types, "LIPSYNC_OT_import_controls"), "registered")

# Not LipSync's: refused with its name.
bad = os.path.join(drawings, "bad.json")
with open(bad, "w") as f:
    f.write('{"format": "rhubarb"}')
try:
    la.import_controls(context, bad, face)
    check(False, "a foreign file was read")
except la.LipsyncFileError as e:
    check(bad in str(e), str(e))

la.unregister()
print("PASS: the add-on imported", len(data["times"]), "frames of controls and", count, "cues")
