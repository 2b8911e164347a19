# Imports a .glb morph animation into Blender and shows that it plays: one line per mesh object,
# the actions, and the shape-key values at several frames. Fails (exit 1 with
# --python-exit-code 1) when the shape keys, Basis excluded, are not EXPECTED_KEYS in all or
# there is no action.
#
#   blender --background --factory-startup --python-exit-code 1 \
#       --python tests/anim/blender_import_check.py -- FILE.glb EXPECTED_KEYS

import sys

import bpy

try:
    import numpy  # Blender's glTF importer needs it; Debian's blender does not pull it in
except ImportError:
    raise SystemExit("Blender's Python has no numpy (Debian: apt-get install python3-numpy; "
                     "scripts/install-deps.sh installs it)")
# Blender 3.4's importer still uses numpy.bool, which NumPy 1.24 (Debian 12) removed.
if "bool" not in vars(numpy):
    numpy.bool = numpy.bool_

args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
if len(args) != 2:
    raise SystemExit("usage: blender ... --python blender_import_check.py -- FILE.glb EXPECTED_KEYS")
path, expected = args[0], int(args[1])

# The factory scene's cube, camera and light would only clutter the listing.
for obj in list(bpy.data.objects):
    bpy.data.objects.remove(obj)

bpy.ops.import_scene.gltf(filepath=path)

meshes = sorted((o for o in bpy.data.objects if o.type == "MESH"), key=lambda o: o.name)
total = 0
for obj in meshes:
    blocks = obj.data.shape_keys.key_blocks if obj.data.shape_keys else []
    names = [b.name for b in blocks if b.name != "Basis"]
    total += len(names)
    print(f"mesh {obj.name}: {len(obj.data.vertices)} vertices, {len(names)} shape keys"
          f" ({names[0] if names else '-'} .. {names[-1] if names else '-'})")
print(f"shape keys: {total}")

actions = list(bpy.data.actions)
for action in actions:
    start, end = action.frame_range
    print(f"action {action.name}: frames {start:g}..{end:g}, {len(action.fcurves)} fcurves")
print(f"actions: {len(actions)}")

scene = bpy.context.scene
starts = [a.frame_range[0] for a in actions] or [scene.frame_start]
ends = [a.frame_range[1] for a in actions] or [scene.frame_end]
first, last = min(starts), max(ends)
for step in range(5):
    frame = first + (last - first) * step / 4
    scene.frame_set(int(frame), subframe=frame - int(frame))
    for obj in meshes:
        if not obj.data.shape_keys:
            continue
        active = [(b.name, b.value) for b in obj.data.shape_keys.key_blocks
                  if b.name != "Basis" and b.value != 0.0]
        shown = ", ".join(f"{name}={value:.3f}" for name, value in active) or "none"
        print(f"frame {frame:g} {obj.name} scale {obj.scale[0]:g}: {shown}")

if total != expected:
    raise RuntimeError(f"{total} shape keys, expected {expected}")
if not actions:
    raise RuntimeError("no action was imported")
print("blender import check: ok")
