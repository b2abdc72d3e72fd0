#!/usr/bin/env python3
"""Renders scenes with softraster and with Mesa llvmpipe (glref) and compares the pictures.

  compare.py SOFTRASTER GLREF OUTDIR SCENE.json          one scene; exit 1 if over the bar
  compare.py SOFTRASTER GLREF OUTDIR --report FILE.md SCENE.json...
                                                         all of them, and a markdown table

The bar (the same as for the shared reference pictures): at most 0.1% of pixels with a
channel off by more than 2/255, and a PSNR of at least 38 dB."""
import json, os, subprocess, sys, time

HERE = os.path.dirname(os.path.abspath(__file__))
IMGDIFF = os.path.join(HERE, '..', 'tools', 'imgdiff.py')
MAX_FRAC_OVER_2 = 0.001
MIN_PSNR = 38.0


def compare(softraster, glref, outdir, scene):
    name = os.path.splitext(os.path.basename(scene))[0]
    os.makedirs(outdir, exist_ok=True)
    ours, theirs = os.path.join(outdir, name + '.softraster.png'), os.path.join(outdir, name + '.llvmpipe.png')
    for exe, cmd, out in ((softraster, 'render', ours), (glref, None, theirs)):
        args = [exe, cmd, scene, '-o', out] if cmd else [exe, scene, '-o', out]
        r = subprocess.run(args, capture_output=True, text=True)
        if r.returncode != 0:
            return name, {'error': '%s failed: %s' % (os.path.basename(exe), r.stderr.strip())}, False
    r = subprocess.run([sys.executable, IMGDIFF, theirs, ours, '--heatmap', os.path.join(outdir, name + '.heatmap.png')],
                       capture_output=True, text=True)
    stats = json.loads(r.stdout)
    ok = stats['frac_over_2'] <= MAX_FRAC_OVER_2 and stats['psnr_db'] >= MIN_PSNR
    return name, stats, ok


def main(argv):
    softraster, glref, outdir = argv[1:4]
    rest = argv[4:]
    report = None
    if rest and rest[0] == '--report':
        report, rest = rest[1], rest[2:]
    rows, all_ok = [], True
    for scene in rest:
        name, stats, ok = compare(softraster, glref, outdir, scene)
        all_ok &= ok
        rows.append((scene, name, stats, ok))
        print(('PASS ' if ok else 'FAIL ') + name + ' ' + json.dumps(stats))
    if report:
        with open(report, 'w') as f:
            f.write(REPORT_HEAD.format(date=time.strftime('%Y-%m-%d'), frac=MAX_FRAC_OVER_2 * 100, psnr=MIN_PSNR))
            f.write('| scene | pixels off by > 2/255 | PSNR (dB) | max channel diff | result |\n|---|---|---|---|---|\n')
            for scene, name, s, ok in rows:
                rel = os.path.relpath(scene, os.path.join(HERE, '..', '..'))
                if 'error' in s:
                    f.write('| `%s` | | | | error: %s |\n' % (rel, s['error']))
                    continue
                psnr = 'identical' if s['identical'] else '%.1f' % s['psnr_db']
                f.write('| `%s` | %.4f%% | %s | %d | %s |\n' % (rel, s['frac_over_2'] * 100, psnr, s['max_diff'], 'pass' if ok else 'FAIL'))
        print('wrote', report)
    return 0 if all_ok else 1


REPORT_HEAD = """# Conformance

softraster's claim is that it draws what a conformant OpenGL implementation draws for the
scene format (`docs/scene-format.md`, versions 1 and 2). The test suite checks it in two
ways, both run by ctest:

1. `conformance.*`: the scenes in `tests/conformance/` (copied from `../shared`) against the
   pictures Mesa llvmpipe drew for them (`*.ref.png`). `fill_rule` must be identical.
2. `llvmpipe.*`: every scene in `tests/conformance/` and `tests/scenes/` rendered by
   softraster and, in the same run, by Mesa llvmpipe through OSMesa (`tests/reference/`,
   the `glref` tool, built when `libosmesa6-dev` is installed), then compared.

The bar: at most {frac:.1f}% of pixels with any channel off by more than 2/255, and a PSNR of at
least {psnr:.0f} dB (`tests/tools/imgdiff.py`).

## The reference renderer (`tests/reference/`)

An OpenGL 3.3 core context from OSMesa; it refuses to run unless `GL_RENDERER` names
llvmpipe. It renders into a framebuffer object with an `GL_RGBA8` color and a
`GL_DEPTH32F_STENCIL8` depth-stencil renderbuffer (4 samples when the scene asks, resolved
with `glBlitFramebuffer`), with GLSL shaders that spell out the spec's formulas. Version 2
keys become the same GL state: `glDepthFunc`, `glDepthMask`, `glPolygonOffset`,
`glStencilFuncSeparate`/`glStencilOpSeparate`/`glStencilMaskSeparate` per face,
`glBlendEquationSeparate`, `glBlendFuncSeparate`, `glBlendColor`, `glColorMask`, `glScissor`,
`GL_SAMPLE_ALPHA_TO_COVERAGE`, `discard` below the alpha cutoff and `noperspective`
varyings in GLSL; supersampled scenes are drawn k times larger and box-filtered on the CPU.
llvmpipe draws only 1 and 4 samples: 2, 8 and 16 are proved by properties in
`tests/pipeline/sample_patterns_test.cpp` instead. It shares only
the scene loader (meshes, textures, the spec's matrices) with softraster; draw order, flat
normals, culling, blending and all rasterization are its own or Mesa's.

What we found by experiment about getting the spec's conventions out of llvmpipe:

- **Fill rule and row order.** The vertex shader negates clip-space y, so GL window row 0,
  the first row llvmpipe stores in memory, is the top row of the picture, and rows are read
  back without flipping. llvmpipe then applies its top-left rule in that memory order,
  which is the spec's rule "in the image as stored": the shared `fill_rule` scene comes out
  byte-identical to its reference. (Rendering y-up and flipping the rows afterwards turns
  it into a bottom-left rule.) The y flip mirrors windings, so `glFrontFace` is inverted.
- **Sample positions.** With the same flip, llvmpipe's 4x pattern in memory order is the
  spec's `(0.375, 0.125), (0.875, 0.375), (0.125, 0.625), (0.625, 0.875)`; `msaa4` matches.
- **Textures.** Rows are uploaded bottom row first, so GL's t = 0 is the bottom of the
  picture as displayed; no mipmaps, `GL_NEAREST`/`GL_LINEAR`, `GL_REPEAT`/`GL_CLAMP_TO_EDGE`.
- **Blending.** `glBlendFuncSeparate(SRC_ALPHA, ONE_MINUS_SRC_ALPHA, ONE, ONE_MINUS_SRC_ALPHA)`
  for alpha and `(SRC_ALPHA, ONE, ZERO, ONE)` for additive; llvmpipe blends RGBA8 in 8-bit
  fixed point with rounded products, which softraster now does too (float blending drifted
  by up to 5 levels over a dozen layers).
- **Precision.** llvmpipe's attribute interpolation behaves like exact arithmetic where a
  float plane equation does not: a ground plane clipped at the near plane has 1/w spanning
  three orders of magnitude, and float planes alias a minified texture differently near the
  horizon. softraster evaluates its planes in double precision.
- `pow(0, 0)` is undefined in GLSL; the shader spells out the spec's `pow(0, 0) = 1`.

Timing: `glref SCENE --time --frames N --warmup W` times clear + draws + resolve + `glFinish`
and prints one JSON line; `LP_NUM_THREADS` sets llvmpipe's thread count.

## Results

Produced by `scripts/conformance-report.sh` (llvmpipe from Debian 12's Mesa 22.3.6) on {date} (not typed by hand):

"""

if __name__ == '__main__':
    sys.exit(main(sys.argv))
