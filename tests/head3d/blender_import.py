"""Run inside Blender (blender -b --python-exit-code 1 --python blender_import.py -- FILE TIME...):
imports a .glb with Blender's own glTF importer and prints one JSON line with what Blender made of
it: the objects, the head's vertex count and shape keys, and at each TIME (seconds) the head's and
eyes' rotations (quaternions x, y, z, w in glTF's axes) and the shape keys' values."""
import json
import sys

import bpy
import numpy

# Debian 12's Blender 3.4 importer still calls numpy.bool, which Debian's numpy 1.24 removed
# (AttributeError inside the importer): give it back the alias it meant.
if "bool" not in numpy.__dict__:
    numpy.bool = numpy.bool_


def main():
    args = sys.argv[sys.argv.index("--") + 1:]
    path, times = args[0], [float(t) for t in args[1:]]
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=path)
    scene = bpy.context.scene
    objects = {o.name: o for o in scene.objects}
    head = objects["head"]
    keys = head.data.shape_keys.key_blocks if head.data.shape_keys else []
    fps = scene.render.fps / scene.render.fps_base
    result = {
        "objects": sorted(objects),
        "vertices": len(head.data.vertices),
        "shape_keys": [k.name for k in keys][1:],  # the first is Blender's Basis
        "fps": fps,
        "poses": [],
    }
    for t in times:
        frame = t * fps
        scene.frame_set(int(frame), subframe=frame - int(frame))
        pose = {"time": t, "weights": {k.name: k.value for k in list(keys)[1:]}, "rotations": {}}
        for name in ("head", "eye_l", "eye_r"):
            q = objects[name].rotation_quaternion
            # Blender is z up: the importer turns glTF's y-up scene about x. A rotation about the
            # head's own axes maps (x, y, z) -> (x, -z, y), the same as the axes themselves.
            pose["rotations"][name] = [q.x, q.z, -q.y, q.w]
        result["poses"].append(pose)
    print("BLENDER-IMPORT " + json.dumps(result))


main()
