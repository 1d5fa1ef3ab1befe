"""The layout helpers the 2D scene generators share (make_blend_scenes.py,
make_multisample_scenes.py): the clip_space camera with positions laid out in pixels
(x_win = x * W/2 + W/2), quads with a colour per corner, a background whose colour and alpha
differ in every corner, and scene files written with arrays of numbers on one line each."""
import json
import re

# A background with a different colour and alpha in each corner: every destination factor varies.
BACKGROUND = [[0.81, 0.23, 0.11, 0.17], [0.13, 0.71, 0.29, 0.93], [0.21, 0.33, 0.87, 0.61],
              [0.93, 0.86, 0.41, 0.37]]  # top-left, top-right, bottom-left, bottom-right


def clip(px, py, w, h, z=0.5):
    """Clip-space position of pixel coordinate (px, py) in a w x h framebuffer."""
    return [round(px / (w / 2) - 1, 6), round(py / (h / 2) - 1, 6), z]


def quad(name, x, y, qw, qh, colours, w, h, z=0.5, **state):
    """An indexed quad (two triangles) from (x, y) to (x + qw, y + qh) in pixels; colours for its
    top-left, top-right, bottom-left and bottom-right corners."""
    d = {"name": name,
         "positions": [clip(x, y, w, h, z), clip(x + qw, y, w, h, z), clip(x, y + qh, w, h, z),
                       clip(x + qw, y + qh, w, h, z)],
         "colours": colours, "indices": [0, 2, 1, 1, 2, 3], "cull": "none"}
    d.update(state)
    return d


def background(w, h, z=0.5):
    return quad("background", 0, 0, w, h, BACKGROUND, w, h, z=z, depth_test=False)


def dump(filename, scene):
    text = json.dumps(scene, indent=1)
    # Arrays of numbers on one line each.
    text = re.sub(r"\[\s+([-0-9.e, \n]+?)\s+\]", lambda m: "[" + " ".join(m.group(1).split()) + "]", text)
    with open(filename, "w") as f:
        f.write(text + "\n")


def scene(description, w, h, draws, samples=1, depth_format=None):
    fb = {"width": w, "height": h, "clear_colour": [0, 0, 0, 0]}
    if samples != 1:
        fb["samples"] = samples
    if depth_format:
        fb["depth_format"] = depth_format
    return {"description": description, "framebuffer": fb, "camera": {"type": "clip_space"}, "draws": draws}
