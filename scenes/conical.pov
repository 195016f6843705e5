// conical.pov - scenes/conical.cfg rendered with simple organ models.
//   phyllo-export --pov -o conical.inc scenes/conical.cfg
//   povray +A +W640 +H480 +Iscenes/conical.pov
// (make renders does both.)  Organs are built at the origin, outward
// along +x, up along +y (out of the surface), of unit size.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 2.6, -10.5> look_at <0, 2.2, 0> angle 40 }
light_source { <-5, 9, -7> color rgb 1.1 }
light_source { <6, 3, -5> color rgb 0.35 shadowless }
background { rgb <0.82, 0.88, 0.80> }

// A leaf: a flat oval lying along the surface, pointing down it.
#declare Leaf = sphere { <1, 0, 0>, 1 scale <0.9, 0.12, 0.55>
  texture { pigment { rgb <0.30, 0.58, 0.18> } finish { phong 0.3 } } }
#include "conical.inc"
object { Conical }

