// flowershop.pov - scenes/flowershop.cfg: plants spaced in a pot by the
// collision model, each a stem with a daisy or zinnia head; three levels
// of parts, each declared once in the include.
//   phyllo-export --pov -o flowershop.inc scenes/flowershop.cfg
//   povray +A +W640 +H480 +Iscenes/flowershop.pov
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4.2, -5.2> look_at <0, 1.1, 0> angle 40 }
light_source { <3, 8, -4> color rgb 1.1 }
light_source { <-4, 3, -3> color rgb 0.4 shadowless }
background { rgb <0.93, 0.9, 0.84> }

// A stem: three units up its own +y (the soil's normal).
#declare Stem = cylinder { 0, <0, 3, 0>, 0.03
  texture { pigment { rgb <0.25, 0.5, 0.18> } } }
// The daisy's organs (scenes/daisy.cfg).
#declare DiscFloret = sphere { 0, 1 scale <0.9, 0.6, 0.9>
  texture { pigment { rgb <0.95, 0.75, 0.1> } } }
#macro Ray(Colour)
  sphere { <1, 0, 0>, 1 scale <0.45, 0.04, 0.09>
    texture { pigment { rgb Colour } finish { phong 0.3 } } }
#end
#declare RayA = object { Ray(<1, 1, 1>) }
#declare RayB = object { Ray(<0.97, 0.97, 0.95>) }
#declare RayC = object { Ray(<0.95, 0.93, 0.97>) }
// The zinnia's (scenes/zinnia.cfg).
#declare Floret = sphere { 0, 1 scale <0.9, 0.7, 0.9>
  texture { pigment { rgb <0.85, 0.6, 0.1> } } }
#declare Petal = sphere { <1, 0, 0>, 1 scale <0.5, 0.06, 0.2>
  texture { pigment { rgb <0.85, 0.12, 0.25> } finish { phong 0.3 } } }

#include "flowershop.inc"
object { FlowerShop }
// The pot and its soil.
cone { <0, -1.2, 0>, 0.8, <0, 0, 0>, 1.1 open
  texture { pigment { rgb <0.7, 0.38, 0.22> } } }
disc { <0, -0.02, 0>, y, 1.1 texture { pigment { rgb <0.3, 0.22, 0.15> } } }
