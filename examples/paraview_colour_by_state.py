"""Colouring the grains by their state in ParaView, with ParaView's Python.

    pvpython examples/paraview_colour_by_state.py RUNDIR [ARRAY] [OUT.png]

RUNDIR is an oedometer run written with --vtk PERIOD: its grains are vtk/grains-<iter>.vtu, one file a
frame (the same series as oedometer.pvd). Each grain is drawn as a sphere of its radius (a Glyph scaled
by the point array r) and coloured by ARRAY: generation (0 original, 1 its fragments, 2, ...; the
default), nAbraded (abrasions so far), stressRatio (sigma_e / f_t) or damage (fatigue). The last frame
goes to OUT.png (default RUNDIR/grains-ARRAY.png). In the ParaView window the same is: open
oedometer.pvd, Filters > Glyph (Glyph Type Sphere, Scale Array r, Scale Factor 2), Coloring: ARRAY.
"""
import glob
import os
import sys

from paraview import simple as pv

STATES = ('generation', 'nAbraded', 'stressRatio', 'damage')


def main(run, array='generation', out=None):
    frames = sorted(glob.glob(os.path.join(run, 'vtk', 'grains-*.vtu')))
    if not frames:
        sys.exit('%s: no vtk/grains-*.vtu; run the oedometer with --vtk PERIOD' % run)
    if array not in STATES:
        sys.exit('ARRAY: expected one of %s, got %r' % (', '.join(STATES), array))
    grains = pv.XMLUnstructuredGridReader(FileName=frames)
    if array not in grains.PointData.keys():
        sys.exit('%s: no point array %r (it has %s)' % (frames[0], array, ', '.join(grains.PointData.keys())))
    spheres = pv.Glyph(Input=grains, GlyphType='Sphere')
    spheres.ScaleArray = ['POINTS', 'r']
    spheres.ScaleFactor = 2.0            # the sphere glyph has diameter 1
    spheres.GlyphMode = 'All Points'
    view = pv.GetActiveViewOrCreate('RenderView')
    shown = pv.Show(spheres, view)
    pv.ColorBy(shown, ('POINTS', array))
    shown.RescaleTransferFunctionToDataRange(True, False)
    shown.SetScalarBarVisibility(view, True)
    scene = pv.GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.AnimationTime = grains.TimestepValues[-1] if grains.TimestepValues else 0.0
    view.ResetCamera()
    out = out or os.path.join(run, 'grains-%s.png' % array)
    pv.SaveScreenshot(out, view, ImageResolution=[800, 800])
    print('paraview_colour_by_state: %d frames, coloured by %s: %s' % (len(frames), array, out))
    return out


if __name__ == '__main__':
    if not 2 <= len(sys.argv) <= 4:
        sys.exit('usage: pvpython examples/paraview_colour_by_state.py RUNDIR [ARRAY] [OUT.png]')
    main(*sys.argv[1:])
