// sunflower.pov - a sunflower head from scenes/sunflower.cfg, with its
// organs modelled in SDL.  Export the include first, then render:
//   phyllo-export --pov -o sunflower.inc scenes/sunflower.cfg
//   povray +A +W640 +H480 +Iscenes/sunflower.pov
// (make renders does both for every scene.)
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4.0, -3.5> look_at <0, -0.4, -0.15> angle 42 }
light_source { <2, 6, -3> color rgb 1.1 }
light_source { <-4, 3, -3> color rgb 0.35 shadowless }
background { rgb <0.62, 0.76, 0.90> }

// Organ models, each at the origin facing outward along +x, up +y, of
// unit size (phyllo-export scales them by their packing radius).
#declare Seed = sphere { 0, 1 scale <0.9, 0.55, 0.75>
  texture { pigment { rgb <0.16, 0.09, 0.03> } finish { phong 0.4 } } }
#declare Floret = union {
  sphere { 0, 1 scale <0.9, 0.6, 0.75> }
  cone { <0, 0.3, 0>, 0.5, <0, 1.2, 0>, 0.1 }
  texture { pigment { rgb <0.55, 0.32, 0.05> } finish { phong 0.2 } } }
#macro Petal(Colour)
  sphere { <1, 0, 0>, 1 scale <0.5, 0.05, 0.14>
    texture { pigment { rgb Colour } finish { phong 0.3 } } }
#end
#declare PetalA = object { Petal(<1.00, 0.78, 0.06>) }
#declare PetalB = object { Petal(<0.98, 0.72, 0.05>) }
#declare PetalC = object { Petal(<1.00, 0.82, 0.10>) }
#declare PetalD = object { Petal(<0.96, 0.68, 0.04>) }

#include "sunflower.inc"
object { Sunflower }
