# SPDX-License-Identifier: AGPL-3.0-or-later
"""The ParaView view of a scene run's contact (doc/user/contact-and-scenes.md):
the skin coloured by its ContactForce, the bowl translucent, arrows for the
control nodes' ContactForce. Run under pvpython (or pvbatch):

    pvpython contact_view.py RUN_DIR OUT.png

where RUN_DIR holds run.pvd from `tetskin simulate SCENE.json --every N -o RUN_DIR/run.pvd`
with its last frame numbered 1 (as --steps 600 --every 600 writes it).
"""
import sys
from paraview.simple import *
d = sys.argv[1]
skin = XMLPolyDataReader(FileName=[d + '/run_frames/surface_00001.vtp'])
bowl = XMLPolyDataReader(FileName=[d + '/run_frames/obstacle_0.vtp'])
cage = XMLUnstructuredGridReader(FileName=[d + '/run_frames/control_00001.vtu'])
view = CreateView('RenderView')
view.ViewSize = [1000, 640]
view.OrientationAxesVisibility = 0
try:
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass
view.Background = [0.32, 0.34, 0.40]
s = Show(skin, view)
skin.UpdatePipeline()
skinTop = skin.PointData['ContactForce'].GetRange(-1)[1]
ColorBy(s, ('POINTS', 'ContactForce', 'Magnitude'))
lut = GetColorTransferFunction('ContactForce')
lut.ApplyPreset('Inferno (matplotlib)', True)
lut.RescaleTransferFunction(0, skinTop / 3)
bar = GetScalarBar(lut, view)
bar.Title = 'ContactForce (N)'
bar.ComponentTitle = ''
s.SetScalarBarVisibility(view, True)
b = Show(bowl, view)
b.Opacity = 0.2
b.DiffuseColor = [0.75, 0.8, 0.88]
cage.UpdatePipeline()
top = cage.PointData['ContactForce'].GetRange(-1)[1]
glyphs = Glyph(Input=cage, GlyphType='Arrow')
glyphs.OrientationArray = ['POINTS', 'ContactForce']
glyphs.ScaleArray = ['POINTS', 'ContactForce']
glyphs.ScaleFactor = 4.0 / top
glyphs.GlyphMode = 'All Points'
g = Show(glyphs, view)
g.ColorArrayName = [None, '']
g.DiffuseColor = [1.0, 0.85, 0.1]
view.CameraFocalPoint = [0, -7.5, 0]
view.CameraPosition = [12, -28, 12]
view.CameraViewUp = [0, 1, 0]
view.CameraViewAngle = 30
Render(view)
SaveScreenshot(sys.argv[2], view, ImageResolution=[1000, 640])
print('largest node contact force', top)
