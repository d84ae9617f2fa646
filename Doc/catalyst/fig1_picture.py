# A Catalyst script for Scenes/fig1_jet.xml (Doc/paraview.md, "In situ and
# live"): one picture a frame, the sheet coloured by saturation from red
# (dry) to black (wet) as Doc/render.py colours it, the water as points,
# seen from the scene's <Camera>. Pictures go to $SOAK_OUTPUT/catalyst,
# the run's own folder.
#   xvfb-run -a soak run Scenes/fig1_jet.xml --catalyst Doc/catalyst/fig1_picture.py
import os

from paraview.simple import *
from paraview import catalyst

options = catalyst.Options()
options.ExtractsOutputDirectory = os.path.join(os.environ.get("SOAK_OUTPUT", "."), "catalyst")
options.GlobalTrigger = "TimeStep"

sheet = TrivialProducer(registrationName="cloth_sheet")  # the channels are named as the .pvd files
water = TrivialProducer(registrationName="water")

view = CreateView("RenderView")
view.ViewSize = [640, 400]
view.UseColorPaletteForBackground = 0
view.Background = [1.0, 1.0, 1.0]
view.OrientationAxesVisibility = 0
view.CameraPosition = [1.3, 1.35, 2.2]
view.CameraFocalPoint = [0.0, 0.9, 0.15]
view.CameraViewUp = [0.0, 1.0, 0.0]
view.CameraViewAngle = 30.0

sheetDisplay = Show(sheet, view)
ColorBy(sheetDisplay, ("POINTS", "saturation"))
saturation = GetColorTransferFunction("saturation")
saturation.AutomaticRescaleRangeMode = "Never"
saturation.RGBPoints = [0.0, 0.8, 0.1, 0.1, 0.4, 0.0, 0.0, 0.0]

waterDisplay = Show(water, view)
waterDisplay.Representation = "Points"
waterDisplay.PointSize = 2
waterDisplay.AmbientColor = waterDisplay.DiffuseColor = [0.25, 0.5, 1.0]

picture = CreateExtractor("PNG", view, registrationName="Picture")
picture.Trigger = "TimeStep"
picture.Writer.FileName = "fig1_{timestep:06d}.png"
picture.Writer.ImageResolution = [640, 400]
