# A Catalyst script (ParaView 5.9+ "v2" form) for `soak run --catalyst`:
# every frame it draws the cloth coloured by saturation over the water
# particles (a PNG) and writes the cloth's and the water's point data as CSV
# extracts, into $SOAK_OUTPUT/catalyst (the run's folder). The test
# Tests/Catalyst/check_insitu.py compares them with the run's .vtp/.vtu.
import os

from paraview.simple import *
from paraview import catalyst

options = catalyst.Options()
options.ExtractsOutputDirectory = os.path.join(os.environ.get("SOAK_OUTPUT", "."), "catalyst")
options.GlobalTrigger = "TimeStep"
options.GlobalTrigger.Frequency = 1

cloth = TrivialProducer(registrationName="cloth_sheet")
water = TrivialProducer(registrationName="water")

view = CreateView("RenderView")
view.ViewSize = [320, 240]
view.UseColorPaletteForBackground = 0
view.Background = [1.0, 1.0, 1.0]
view.OrientationAxesVisibility = 0
view.CameraPosition = [1.2, 1.2, 1.7]
view.CameraFocalPoint = [0.0, 0.35, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
view.CameraViewAngle = 30.0

clothDisplay = Show(cloth, view)
ColorBy(clothDisplay, ("POINTS", "saturation"))
saturation = GetColorTransferFunction("saturation")
saturation.AutomaticRescaleRangeMode = "Never"
saturation.RGBPoints = [0.0, 0.8, 0.1, 0.1, 0.4, 0.0, 0.0, 0.0]  # dry red to wet black, as Doc/render.py

waterDisplay = Show(water, view)
waterDisplay.Representation = "Points"
waterDisplay.PointSize = 3
waterDisplay.AmbientColor = waterDisplay.DiffuseColor = [0.2, 0.4, 1.0]

picture = CreateExtractor("PNG", view, registrationName="Picture")
picture.Trigger = "TimeStep"
picture.Writer.FileName = "sheet_{timestep:06d}.png"
picture.Writer.ImageResolution = [320, 240]

clothCsv = CreateExtractor("CSV", cloth, registrationName="ClothCsv")
clothCsv.Trigger = "TimeStep"
clothCsv.Writer.FileName = "cloth_{timestep:06d}.csv"
waterCsv = CreateExtractor("CSV", water, registrationName="WaterCsv")
waterCsv.Trigger = "TimeStep"
waterCsv.Writer.FileName = "water_{timestep:06d}.csv"
