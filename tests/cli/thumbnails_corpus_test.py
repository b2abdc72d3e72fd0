#!/usr/bin/env python3
"""thumbnails_corpus_test.py SOFTRASTER CORPUS WORKDIR

`softraster thumbnails` over every glTF, GLB, OBJ, FBX, STL, DAE, 3DS and PLY file of
Debian's assimp-testmodels (CORPUS, /usr/share/assimp/models), broken ones included. Every
file either draws a picture that shows the model (not just the background) or fails with a
one-line reason; the files expected to fail are listed below with the reason. Nothing
crashes or hangs: a crash or a timeout would show as a failure the list does not expect."""
import json, os, shutil, subprocess, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'tools'))
from imgdiff import read_png  # noqa: E402

exe, corpus, work = sys.argv[1:4]
EXTENSIONS = ('.gltf', '.glb', '.obj', '.fbx', '.stl', '.dae', '.3ds', '.ply')

# File (relative to the corpus) -> a piece of the reason it must fail with.
EXPECTED_FAILURES = {
    # glTF 1.0 binary (KHR_binary_glTF): assimp 5.2 reads glTF 1.0 as text only.
    'glTF/BoxTextured-glTF-Binary/BoxTextured.glb': 'No suitable reader',
    # The deliberately broken glTF 2.0 files.
    'glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb': 'non-finite position',
    'glTF2/IndexOutOfRange/AllIndicesOutOfRange.gltf': 'has no faces',
    'glTF2/MissingBin/BoxTextured.gltf': 'could not open referenced file',
    'glTF2/RecursiveNodes/RecursiveNodes.gltf': 'recursive reference',
    'glTF2/SchemaFailures/sceneWrongType.gltf': 'was not of type',
    'glTF2/TestNoRootNode/NoScene.gltf': 'No scene',
    'glTF2/TestNoRootNode/SceneWithoutNodes.gltf': 'nothing to draw',
    'glTF2/issue_3269/texcoord_crash.gltf': 'Invalid attribute',
    'glTF2/wrongTypes/badArray.gltf': 'was not of type "array"',
    'glTF2/wrongTypes/badExtension.gltf': 'was not of type "object"',
    'glTF2/wrongTypes/badNumber.gltf': 'was not of type "number"',
    'glTF2/wrongTypes/badObject.gltf': 'was not of type "object"',
    'glTF2/wrongTypes/badString.gltf': 'was not of type "string"',
    'glTF2/wrongTypes/badUint.gltf': 'was not of type "uint"',
    # Files with nothing to draw: cameras or lights only, UTF-16 text assimp does not decode.
    'Collada/cameras.dae': 'nothing to draw',
    'Collada/lights.dae': 'nothing to draw',
    'OBJ/box_UTF16BE.obj': 'nothing to draw',
    # Malformed: XML assimp cannot read, numbers it cannot parse, a block out of range.
    'Collada/cube_UTF16LE.dae': 'malformed XML',
    'Collada/library_animation_clips.dae': 'as a real number',
    'FBX/transparentTest.fbx': 'out of range',
    # A point cloud whose positions include NaN.
    'PLY/pond.0.ply': 'non-finite position',
    # Empty or malformed files of the corpus's "invalid" folder.
    'invalid/empty.3ds': 'File is empty',
    'invalid/empty.obj': 'too small',
    'invalid/empty.ply': 'is empty',
    'invalid/malformed.obj': 'Invalid face index',
    # One good solid and one empty one, which assimp's triangulation rejects.
    'STL/triangle_with_empty_solid.stl': 'invalid primitive type',
}
# Least share of a picture's pixels that must differ from the background...
MIN_COVERAGE = 0.002
# ... except for these files, drawn correctly as what they are: (least pixels, why).
SPARSE_PICTURES = {
    'OBJ/point_cloud.obj': (4, 'a few points, one pixel each'),
    'OBJ/number_formats.obj': (0, 'its one triangle is degenerate (collinear corners)'),
}


def main():
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    files = sorted(os.path.join(d, f) for d, _, fs in os.walk(corpus) for f in fs
                   if f.lower().endswith(EXTENSIONS))
    if len(files) < 140:
        sys.exit('FAIL: expected about 150 model files in %s, found %d (is assimp-testmodels installed?)'
                 % (corpus, len(files)))
    out = os.path.join(work, 'thumbs')
    report_path = os.path.join(work, 'report.json')
    r = subprocess.run([exe, 'thumbnails', *files, '--out', out, '--report', report_path, '--size', '64',
                        '--timeout', '300'], capture_output=True, text=True, timeout=3600)
    failures = []
    if r.returncode != 1:
        failures.append('exit code %d, expected 1 (some files fail)\n%s' % (r.returncode, r.stderr[-2000:]))
    report = json.load(open(report_path))
    entries = {os.path.relpath(e['input'], corpus): e for e in report['inputs']}
    if len(report['inputs']) != len(files) or len(entries) != len(files):
        failures.append('the report lists %d inputs for %d files' % (len(report['inputs']), len(files)))
    drawn = 0
    for rel, e in sorted(entries.items()):
        expected = EXPECTED_FAILURES.get(rel)
        if e['status'] == 'failed':
            reason = e.get('reason', '')
            if '\n' in reason or not reason:
                failures.append('%s: the reason is not one line: %r' % (rel, reason))
            if expected is None:
                failures.append('%s: failed unexpectedly: %s' % (rel, reason))
            elif expected not in reason:
                failures.append('%s: failed with %r, expected a reason with %r' % (rel, reason, expected))
            if os.path.exists(os.path.join(out, rel + '.png')):
                failures.append('%s: failed but left a picture' % rel)
            continue
        if expected is not None:
            failures.append('%s: expected to fail (%s) but was %s' % (rel, expected, e['status']))
            continue
        w, h, ch, pix = read_png(e['output'])
        background = pix[0:ch]  # the default background; a framed model never covers a corner
        differing = sum(1 for i in range(0, len(pix), ch) if pix[i:i + ch] != background)
        least = SPARSE_PICTURES[rel][0] if rel in SPARSE_PICTURES else MIN_COVERAGE * w * h
        if differing < least:
            failures.append('%s: the picture shows nothing (%d pixels differ from the background)' % (rel, differing))
        drawn += 1
    missing = set(EXPECTED_FAILURES) - set(entries)
    if missing:
        failures.append('listed as expected failures but not in the corpus: %s' % sorted(missing))
    summary = report['summary']
    if summary['ok'] != drawn or summary['failed'] != len(files) - drawn:
        failures.append('summary %s disagrees with the entries (%d drawn)' % (summary, drawn))
    print('%d files: %d drawn, %d failed as expected' % (len(files), drawn, len(files) - drawn))
    if failures:
        print('FAILED:\n  ' + '\n  '.join(failures))
        sys.exit(1)


main()
