// pineapple.pov - the pineapple of scenes/pineapple.cfg: the (8, 13, 21)
// triple-contact pattern, every eye touching six neighbours.
//   phyllo-export --pov -o pineapple.inc scenes/pineapple.cfg
//   povray +A +W640 +H480 +Iscenes/pineapple.pov
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 2.6, -9.5> look_at <0, 2.1, 0> angle 38 }
light_source { <-6, 10, -8> color rgb 1.1 }
light_source { <6, 4, -6> color rgb 0.3 shadowless }
background { rgb <0.80, 0.86, 0.80> }

// An eye: a flattened dome with a point, outward along +x (down the
// fruit), up along +y (out of the surface), of unit radius.
#declare Eye = union {
  sphere { 0, 1 scale <1, 0.45, 1> }
  cone { <0, 0.3, 0>, 0.35, <-0.2, 0.75, 0>, 0 }
  texture {
    pigment { gradient y color_map { [0 rgb <0.45, 0.30, 0.05>] [0.5 rgb <0.78, 0.55, 0.12>] } scale 0.9 }
    finish { phong 0.35 }
  }
}

#include "pineapple.inc"
// The fruit stands on +Z in the scene file, which is +y here.
object { Pineapple }
