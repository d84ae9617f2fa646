"""Default materials: wet cloth, water, colliders (Doc/output.md, "Blender").

"Soak wet cloth" reads the mesh attribute `saturation` (Attribute node) and
turns it into a wetness w = (saturation / sMax) ^ "Wetness exponent" (0
dry, 1 at the scene's `<WetCloth sMax>`; node "Wetness"). The exponent, 0.5,
makes a fabric look wet well before it is full: it darkens where water
has replaced the air at its surface, which happens before its pores are
full. As w rises, the fabric does what wet cotton does:
- its colour darkens and deepens: the base colour goes from "Dry colour" to
  "Wet colour" = "Dry colour" raised to the power "Wet darkening", times
  "Wet brightness". Water fills the air between the fibres, so less light
  scatters back out of the fabric, and the power makes each colour channel
  fall the more the darker it was (wet fabric looks more saturated);
- it turns glossier: roughness from "Dry roughness" to "Wet roughness", and a
  clear coat (the water film on the fibres) from 0 to "Wet film".
Every value an artist would change is a labelled node (RGB or Value) at the
left of the tree.

"Soak water" is clear water: a Principled BSDF with full transmission and
IOR 1.333, and a light blue absorption in the volume, so deep water is
bluer than thin water. Shadow rays pass its surface (node "Clear to
shadows"), since the renders leave out caustics.

"Soak collider" is a matte dark grey, against which dry and wet cloth both
show. "Soak container" is the same grey on the faces seen from inside and
transparent on faces seen from outside, so a tank's near walls do not hide
what is in it; light passes its walls, so a closed tank is not dark inside.
"""
import bpy

CLOTH = "Soak wet cloth"
WATER = "Soak water"
COLLIDER = "Soak collider"
CONTAINER = "Soak container"

DRY_COLOUR = (0.80, 0.76, 0.68, 1.0)   # natural cotton
WETNESS_EXPONENT = 0.5
WET_DARKENING = 2.0
WET_BRIGHTNESS = 0.2
DRY_ROUGHNESS = 0.9
WET_ROUGHNESS = 0.35
WET_FILM = 0.3
COLLIDER_COLOUR = (0.22, 0.22, 0.23, 1.0)


def _new(name):
    material = bpy.data.materials.new(name)
    material.use_nodes = True
    nodes = material.node_tree.nodes
    nodes.clear()
    return material, nodes, material.node_tree.links


# Principled BSDF inputs that Blender 4 renamed: (Blender 3 name, Blender 4 name).
SHEEN = ("Sheen", "Sheen Weight")
COAT = ("Clearcoat", "Coat Weight")
COAT_ROUGHNESS = ("Clearcoat Roughness", "Coat Roughness")
TRANSMISSION = ("Transmission", "Transmission Weight")


def _input(node, names):
    """The node's input of the first name it has."""
    for name in names:
        if name in node.inputs:
            return node.inputs[name]
    raise KeyError(f"{node.name} has none of the inputs {names}")


def _value(nodes, label, value, location):
    node = nodes.new("ShaderNodeValue")
    node.label = node.name = label
    node.outputs[0].default_value = value
    node.location = location
    return node


def _map_range(nodes, label, location, from_max=1.0):
    node = nodes.new("ShaderNodeMapRange")
    node.label = node.name = label
    node.clamp = True
    node.inputs["From Min"].default_value = 0.0
    node.inputs["From Max"].default_value = from_max
    node.location = location
    return node


def wet_cloth(s_max):
    """The wet cloth material; wetness = saturation / s_max."""
    material, nodes, links = _new(CLOTH)
    attribute = nodes.new("ShaderNodeAttribute")
    attribute.attribute_type = "GEOMETRY"
    attribute.attribute_name = "saturation"
    attribute.location = (-900, 300)
    s_max_node = _value(nodes, "Saturation when soaked (WetCloth sMax)", s_max, (-900, 100))
    fraction = _map_range(nodes, "Saturation / sMax", (-700, 300))
    links.new(attribute.outputs["Fac"], fraction.inputs["Value"])
    links.new(s_max_node.outputs[0], fraction.inputs["From Max"])
    exponent = _value(nodes, "Wetness exponent", WETNESS_EXPONENT, (-900, 0))
    wetness = nodes.new("ShaderNodeMath")
    wetness.label = wetness.name = "Wetness"
    wetness.operation = "POWER"
    wetness.location = (-500, 300)
    links.new(fraction.outputs["Result"], wetness.inputs[0])
    links.new(exponent.outputs[0], wetness.inputs[1])

    dry = nodes.new("ShaderNodeRGB")
    dry.label = dry.name = "Dry colour"
    dry.outputs[0].default_value = DRY_COLOUR
    dry.location = (-900, -100)
    darkening = _value(nodes, "Wet darkening", WET_DARKENING, (-900, -300))
    deeper = nodes.new("ShaderNodeGamma")
    deeper.label = deeper.name = "Deeper colour"
    deeper.location = (-650, -150)
    links.new(dry.outputs[0], deeper.inputs["Color"])
    links.new(darkening.outputs[0], deeper.inputs["Gamma"])
    wet_brightness = _value(nodes, "Wet brightness", WET_BRIGHTNESS, (-900, -380))
    wet = nodes.new("ShaderNodeMixRGB")
    wet.label = wet.name = "Wet colour"
    wet.blend_type = "MULTIPLY"
    wet.location = (-650, -350)
    wet.inputs["Fac"].default_value = 1.0
    links.new(deeper.outputs[0], wet.inputs["Color1"])
    links.new(wet_brightness.outputs[0], wet.inputs["Color2"])
    colour = nodes.new("ShaderNodeMixRGB")
    colour.label = colour.name = "Colour by wetness"
    colour.location = (-400, 100)
    links.new(wetness.outputs[0], colour.inputs["Fac"])
    links.new(dry.outputs[0], colour.inputs["Color1"])
    links.new(wet.outputs[0], colour.inputs["Color2"])

    dry_rough = _value(nodes, "Dry roughness", DRY_ROUGHNESS, (-900, -500))
    wet_rough = _value(nodes, "Wet roughness", WET_ROUGHNESS, (-900, -600))
    roughness = _map_range(nodes, "Roughness by wetness", (-400, -300))
    links.new(wetness.outputs[0], roughness.inputs["Value"])
    links.new(dry_rough.outputs[0], roughness.inputs["To Min"])
    links.new(wet_rough.outputs[0], roughness.inputs["To Max"])
    film_node = _value(nodes, "Wet film", WET_FILM, (-900, -700))
    film = nodes.new("ShaderNodeMath")
    film.label = film.name = "Film by wetness"
    film.operation = "MULTIPLY"
    film.location = (-400, -550)
    links.new(wetness.outputs[0], film.inputs[0])
    links.new(film_node.outputs[0], film.inputs[1])

    bsdf = nodes.new("ShaderNodeBsdfPrincipled")
    bsdf.location = (-100, 100)
    _input(bsdf, SHEEN).default_value = 0.3
    _input(bsdf, COAT_ROUGHNESS).default_value = 0.08
    links.new(colour.outputs[0], bsdf.inputs["Base Color"])
    links.new(roughness.outputs["Result"], bsdf.inputs["Roughness"])
    links.new(film.outputs[0], _input(bsdf, COAT))
    out = nodes.new("ShaderNodeOutputMaterial")
    out.location = (250, 100)
    links.new(bsdf.outputs[0], out.inputs["Surface"])
    return material


def water():
    material, nodes, links = _new(WATER)
    bsdf = nodes.new("ShaderNodeBsdfPrincipled")
    bsdf.location = (-300, 200)
    bsdf.inputs["Base Color"].default_value = (0.92, 0.97, 1.0, 1.0)
    _input(bsdf, TRANSMISSION).default_value = 1.0
    bsdf.inputs["Roughness"].default_value = 0.02
    bsdf.inputs["IOR"].default_value = 1.333
    absorption = nodes.new("ShaderNodeVolumeAbsorption")
    absorption.label = absorption.name = "Water tint"
    absorption.location = (-300, -200)
    absorption.inputs["Color"].default_value = (0.55, 0.80, 0.95, 1.0)
    absorption.inputs["Density"].default_value = 2.0
    # Shadow rays pass the surface (tinted by the volume): without caustics, light that crosses
    # water would otherwise leave a black shadow, which on cloth reads as wet.
    light_path = nodes.new("ShaderNodeLightPath")
    light_path.location = (-300, 500)
    clear = nodes.new("ShaderNodeBsdfTransparent")
    clear.location = (-300, -450)
    mix = nodes.new("ShaderNodeMixShader")
    mix.label = mix.name = "Clear to shadows"
    mix.location = (0, 200)
    links.new(light_path.outputs["Is Shadow Ray"], mix.inputs["Fac"])
    links.new(bsdf.outputs[0], mix.inputs[1])
    links.new(clear.outputs[0], mix.inputs[2])
    out = nodes.new("ShaderNodeOutputMaterial")
    out.location = (250, 100)
    links.new(mix.outputs[0], out.inputs["Surface"])
    links.new(absorption.outputs[0], out.inputs["Volume"])
    return material


def collider():
    material, nodes, links = _new(COLLIDER)
    bsdf = nodes.new("ShaderNodeBsdfPrincipled")
    bsdf.inputs["Base Color"].default_value = COLLIDER_COLOUR
    bsdf.inputs["Roughness"].default_value = 0.6
    out = nodes.new("ShaderNodeOutputMaterial")
    out.location = (300, 0)
    links.new(bsdf.outputs[0], out.inputs["Surface"])
    return material


def container():
    """Grey where the face's front (the inside) faces the ray, transparent where its back does and to shadow rays."""
    material, nodes, links = _new(CONTAINER)
    geometry = nodes.new("ShaderNodeNewGeometry")
    geometry.location = (-400, 300)
    bsdf = nodes.new("ShaderNodeBsdfPrincipled")
    bsdf.location = (-400, 100)
    bsdf.inputs["Base Color"].default_value = COLLIDER_COLOUR
    bsdf.inputs["Roughness"].default_value = 0.6
    clear = nodes.new("ShaderNodeBsdfTransparent")
    clear.location = (-400, -200)
    light_path = nodes.new("ShaderNodeLightPath")
    light_path.location = (-650, 450)
    clear_where = nodes.new("ShaderNodeMath")
    clear_where.label = clear_where.name = "Seen from outside, or a shadow ray"
    clear_where.operation = "MAXIMUM"
    clear_where.location = (-200, 350)
    links.new(geometry.outputs["Backfacing"], clear_where.inputs[0])
    links.new(light_path.outputs["Is Shadow Ray"], clear_where.inputs[1])
    mix = nodes.new("ShaderNodeMixShader")
    mix.location = (0, 100)
    links.new(clear_where.outputs[0], mix.inputs["Fac"])
    links.new(bsdf.outputs[0], mix.inputs[1])
    links.new(clear.outputs[0], mix.inputs[2])
    out = nodes.new("ShaderNodeOutputMaterial")
    out.location = (250, 100)
    links.new(mix.outputs[0], out.inputs["Surface"])
    material.blend_method = "BLEND"
    return material
