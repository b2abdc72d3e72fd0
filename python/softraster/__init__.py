"""softraster: a 3D rasterizer that runs the whole graphics pipeline on the CPU.

Pictures of scene files and model files (glTF, GLB, OBJ, FBX, STL, PLY, COLLADA, 3DS and
the other formats assimp reads) as NumPy arrays, with no GPU, no display and no OpenGL
context:

    import softraster
    rgba = softraster.render_model("duck.glb", size=(640, 480), view="front")
    model = softraster.Model("duck.glb")          # read once, drawn from many cameras
    shots = softraster.views(model, count=24, size=256, depth=True)   # as `softraster views` draws them

Conventions:
  * color: H x W x 4 uint8 RGBA, row 0 at the top; sRGB-encoded unless color_space="linear".
  * depth (depth=True): H x W float32, the distance along the camera's view axis in world
    units (the camera-space z of the surface, positive); inf where nothing was drawn.
    "window_z" is the stored window depth in [0, 1] (1 where nothing was drawn).
  * camera: "K", the 3 x 3 intrinsics in pixels (fx = fy, principal point at the picture's
    center; pixel (u, v) covers [u, u + 1) x [v, v + 1), v down); "world_to_camera", 4 x 4 in
    OpenCV's convention (the camera looks down +z, y down), and "world_to_camera_gl" in
    OpenGL's (down -z, y up); the two differ by diag(1, -1, -1, 1). A pixel (u, v) with depth
    d is the camera-space point d * inv(K) @ (u + 0.5, v + 0.5, 1) in OpenCV's convention.

  * normals (normals="world" or "camera"): H x W x 3 float32, the unit normal of the surface at
    each pixel's center (the interpolated vertex normal, or the face normal for flat shading),
    in world space or in the camera's OpenCV axes (x right, y down, z forward); (0, 0, 0)
    where nothing was drawn. Computed in float from the geometry, not read from a picture.
  * ids (ids=True): "object_id", H x W int32, the index of the object at each pixel's center
    (a scene's objects in file order; a model's meshes as placed by its nodes, Model.objects
    of them), and "triangle_id", the triangle's index in that object's mesh; -1 where nothing
    was drawn. They come from one more drawing, one sample per pixel: blended surfaces count
    as opaque, alpha cutoffs are not applied, lines and points are left out.
  * linear (linear=True): H x W x 4 float32, the picture's r, g, b as linear light (decoded
    from sRGB, or c / 255 for a linear picture) and its alpha, 0 to 1. Its precision is the
    8-bit picture's.

Errors: ValueError for a bad scene, model or option (the command line's one-line message),
FileNotFoundError for a missing file. An importer that crashes on a malformed file cannot be
caught in the same process: for batches of files from the wild, run the command line in
a child process per file (`softraster thumbnails` does so, reporting each bad file and going
on).

The GIL is released while a picture is drawn: N Python threads drawing N pictures use N
cores. Each call draws with `threads` worker threads (0: one per core).
"""
from ._softraster import Model, __version__, render as _render, render_model as _render_model, view_directions, write_png

__all__ = ["render", "render_model", "Model", "views", "view_directions", "write_png", "__version__"]


def render(scene, *, threads=0, depth=False, normals=None, ids=False, linear=False):
    """Draws a scene in softraster's scene format (docs/scene-format.md).

    scene: a dict, a JSON string, or a path to a .json file. Meshes and textures named in a
    dict or a string are found relative to the current folder; in a file, relative to it.
    threads: worker threads for this picture (0: one per core).
    depth: also return the depth and the camera (see the module's conventions).
    normals: None, "world" or "camera": also return the surface normals.
    ids: also return "object_id" and "triangle_id". linear: also return "linear", the
    picture as linear float32.

    Returns the picture, H x W x 4 uint8; with any of the others a dict with "color", those
    asked for ("depth" and "window_z", "normals", "object_id" and "triangle_id", "linear")
    and "camera".
    """
    return _render(scene, threads=threads, depth=depth, normals=normals, ids=ids, linear=linear)


def render_model(path, *, size=512, view="three-quarter", samples=4, shading=None, background=None,
                 color_space="srgb", tone_mapping="none", exposure=1.0, shadows=False, ssao=False, threads=0):
    """Draws a model file, framed and lit as `softraster render MODEL` does.

    size: N (square) or (width, height). view: three-quarter, front, back, left, right, top,
    bottom or iso. samples: MSAA samples, 1, 2, 4, 8 or 16. shading: None (each material's
    own), unlit, flat, gouraud, lambert, blinn_phong, phong, pbr, normals or depth.
    background: "R,G,B[,A]" (0 to 1) or "#RRGGBB[AA]". color_space: srgb (glTF's) or linear.
    tone_mapping: none, reinhard or aces; exposure multiplies the light before it.
    shadows, ssao: shadow maps, screen-space ambient occlusion.

    Returns H x W x 4 uint8. To draw one model from many cameras, use Model.
    """
    return _render_model(path, size=size, view=view, samples=samples, shading=shading, background=background,
                         color_space=color_space, tone_mapping=tone_mapping, exposure=exposure, shadows=shadows,
                         ssao=ssao, threads=threads)


def views(model, *, count=24, layout="sphere", seed=0, **options):
    """Draws a model from `count` cameras, as the command `softraster views` does.

    model: a Model, or a path (read once here). layout: "sphere" (evenly spread), "ring"
    (20 degrees above the horizon) or "random" (uniform, the same for the same seed).
    options: those of Model.render (size, samples, depth=True, ...); the background is
    transparent unless given.

    Returns a list of Model.render's dicts, each with its "direction" added.
    """
    if not isinstance(model, Model):
        model = Model(model)
    options.setdefault("background", "0,0,0,0")
    shots = []
    for d in view_directions(count, layout=layout, seed=seed):
        shot = model.render(direction=d, **options)
        shot["direction"] = d
        shots.append(shot)
    return shots
